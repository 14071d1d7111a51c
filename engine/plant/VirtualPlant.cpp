#include "plant/VirtualPlant.h"

#include "plant/PlantLine.h"

#include "common/Units.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

namespace drytwin::plant {

using properties::Param;
using properties::ParameterSet;

ParameterSet PlantOptions::defaultTruth() {
    ParameterSet p;
    p[Param::h_HDT] = 72.0;
    p[Param::k_HDT] = 0.0236;
    return p;
}

std::string_view plantKindName(PlantKind k) {
    return k == PlantKind::Distributed ? "distributed" : "lumped";
}

std::string_view sensorModeName(SensorMode m) {
    switch (m) {
    case SensorMode::Realistic:
        return "realistic";
    case SensorMode::Ideal:
        return "ideal";
    case SensorMode::Default:
        break;
    }
    return "default";
}

PlantOptions PlantOptions::demo(unsigned seed, PlantKind kind) {
    PlantOptions o;
    o.seed = seed;
    o.plant = kind;
    o.effects[Mechanism::HeatTransferFouling] = 0.1;
    o.effects[Mechanism::GasPhaseCoupling] = 0.1;
    o.effects[Mechanism::TubeWallHeatLoss] = 0.03; // NTU: about 1.5 % of the excess lost on average
    o.effects[Mechanism::MoistureMeterLag] = 20;
    o.unmeasuredDrift = true;
    return o;
}

Status PlantOptions::validate() const {
    if (batches < 1 || batches > 1000) {
        return Error{ErrorKind::Usage, "batches", "must lie in [1, 1000]"};
    }
    if (samples < 200 || samples > 1000000) {
        return Error{ErrorKind::Usage, "samples", "must lie in [200, 1000000]"};
    }
    for (const auto& [m, s] : effects) {
        if (!(s >= 0 && s <= info(m).maxStrength)) {
            return Error{ErrorKind::Usage, std::string(info(m).name),
                         "strength must lie in [0, " + std::to_string(info(m).maxStrength) + "] " +
                             std::string(info(m).unit)};
        }
    }
    for (const auto& [m, onset] : effectOnsetS) {
        if (!(onset >= 0 && onset < 1e7)) {
            return Error{ErrorKind::Usage, std::string(info(m).name), "onset must lie in [0, 1e7) s"};
        }
    }
    if (auto st = truth.validate(); !st) {
        return st;
    }
    const double tauH = truth[Param::tau_HDT];
    if (std::abs(tauH - std::round(tauH)) > 1e-9) {
        return Error{ErrorKind::Usage, "tau_HDT", "the plant needs a whole number of seconds"};
    }
    if (!(hiddenPeriodS >= 10 && hiddenPeriodS <= 1e5) ||
        !(hiddenAmplitudeK >= 0 && hiddenAmplitudeK <= 30)) {
        return Error{ErrorKind::Usage, "hidden periodic disturbance",
                     "period must lie in [10, 1e5] s and amplitude in [0, 30] K"};
    }
    if (!(noiseScale >= 0 && noiseScale <= 10)) {
        return Error{ErrorKind::Usage, "noiseScale", "must lie in [0, 10]"};
    }
    for (double rate :
         {sensorFaults.spikesPerHour, sensorFaults.stuckPerHour, sensorFaults.dropoutsPerHour}) {
        if (!(rate >= 0 && rate <= 60)) {
            return Error{ErrorKind::Usage, "sensor fault rates", "must lie in [0, 60] per channel and hour"};
        }
    }
    if (!(targetXOutPct > 5 && targetXOutPct < 30)) {
        return Error{ErrorKind::Usage, "targetXOutPct", "must lie in (5, 30) % wb"};
    }
    return {};
}

std::string batchId(int oneBased) {
    char id[16];
    std::snprintf(id, sizeof id, "B%02d", oneBased);
    return id;
}

Expected<PlantResult> runPlant(const PlantOptions& o, const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (auto st = o.validate(); !st) {
        return st.error();
    }
    PlantResult result;
    result.truth = o.truth;
    result.effects = o.effects;
    result.plant = o.plant;
    result.sensors = o.sensors;
    PlantRandom random(o.seed);
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int b = 0; b < o.batches; ++b) {
        if (reportProgress(progress, "generate", static_cast<double>(b) / o.batches,
                           "batch " + std::to_string(b + 1) + "/" + std::to_string(o.batches))) {
            return cancelledError("generate");
        }
        PlantDisturbances disturbances = randomDisturbances(o, random.engine);
        const double initialSetpoint = units::kKelvinOffset + 170 + 10 * (uniform(random.engine) - 0.5);
        PlantLine line(o, std::move(disturbances), initialSetpoint, random);
        PlantPiController pi;
        for (std::size_t k = 0; k < line.size(); ++k) {
            const PlantSample s = line.measure();
            line.apply(pi.next(s.xOutPct, s.xInForControlPct, o.targetXOutPct));
        }
        for (std::size_t c = 0; c < result.sensorFaultCounts.size(); ++c) {
            const auto& counts = line.sensors().sensors[c].counts();
            auto& sum = result.sensorFaultCounts[c];
            sum.spikes += counts.spikes;
            sum.stuck += counts.stuck;
            sum.dropouts += counts.dropouts;
            sum.samples += counts.samples;
        }
        PlantBatch pb = std::move(line.record());
        pb.id = batchId(b + 1);
        result.batches.push_back(std::move(pb));
    }
    reportProgress(progress, "generate", 1.0);
    result.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace drytwin::plant
