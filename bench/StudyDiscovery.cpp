// The discovery study of issue #10: every mechanism x 3 seeds x 2 strengths, plus 10 data sets
// without any mechanism (half with unmeasured drift). Prints how often the hidden cause is named
// first and how often a cause is named that is not there, as a Markdown table.
// Run: build/bench/study_discovery [--quick] [--plant distributed|lumped] [--sensors realistic|ideal|default]
// (lumped, its built-in sensors: about 8 min on 2 cores; --quick: one seed). The default plant is
// the distributed one with realistic sensors (issue #22), whose nulls include its own structure.
#include "discovery/Discovery.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

using namespace drytwin;

namespace {

struct Outcome {
    bool rightFirst = false;
    int falseNames = 0;
    std::string named;
    double seconds = 0;
};

Outcome run(plant::PlantOptions o, const std::string& hidden) {
    o.batches = 4;
    o.samples = 3000;
    auto p = plant::runPlant(o);
    Outcome out;
    if (!p) {
        out.named = "plant failed: " + p.error().message();
        return out;
    }
    const auto t0 = std::chrono::steady_clock::now();
    auto r = discovery::discover(plant::toSiBatches(*p, o.seed), hybrid::HybridModel{});
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!r) {
        out.named = "error: " + r.error().message();
        return out;
    }
    for (const auto& f : r->findings) {
        out.named += (out.named.empty() ? "" : "+") + f.cause;
        out.falseNames += f.cause != hidden;
    }
    out.rightFirst = !r->findings.empty() && r->findings.front().cause == hidden;
    if (out.named.empty()) {
        out.named = "(" + r->verdict + ")";
    }
    return out;
}

} // namespace

int main(int argc, char** argv) {
    bool quick = false;
    plant::PlantKind kind = plant::PlantKind::Distributed;
    plant::SensorMode sensors = plant::SensorMode::Default;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const std::string next = i + 1 < argc ? argv[i + 1] : "";
        if (a == "--quick") {
            quick = true;
        } else if (a == "--plant" && (next == "distributed" || next == "lumped")) {
            kind = next == "lumped" ? plant::PlantKind::Lumped : plant::PlantKind::Distributed;
            ++i;
        } else if (a == "--sensors" && (next == "realistic" || next == "ideal" || next == "default")) {
            sensors = next == "realistic" ? plant::SensorMode::Realistic
                      : next == "ideal"   ? plant::SensorMode::Ideal
                                          : plant::SensorMode::Default;
            ++i;
        } else {
            std::fprintf(stderr, "usage: study_discovery [--quick] [--plant distributed|lumped] "
                                 "[--sensors realistic|ideal|default]\n");
            return 2;
        }
    }
    const auto options = [&] {
        plant::PlantOptions o;
        o.plant = kind;
        o.sensors = sensors;
        return o;
    };
    std::printf("Plant: %s, sensors: %s\n\n", std::string(plant::plantKindName(kind)).c_str(),
                options().realisticSensors()          ? "realistic"
                : sensors == plant::SensorMode::Ideal ? "ideal"
                                                      : "built-in");
    const unsigned seeds[] = {101, 102, 103};
    const int nSeeds = quick ? 1 : 3;
    // The test suite's realistic strength, and half of it.
    const std::pair<plant::Mechanism, double> cases[] = {
        {plant::Mechanism::TubeWallHeatLoss, 0.3},          {plant::Mechanism::GasPhaseCoupling, 0.5},
        {plant::Mechanism::HeatTransferFouling, 0.2},       {plant::Mechanism::MoistureMeterLag, 30},
        {plant::Mechanism::MoistureMeterOffset, 0.2},       {plant::Mechanism::TransportDelayError, 15},
        {plant::Mechanism::FallingRateDrying, 0.5},         {plant::Mechanism::AmbientReabsorption, 3},
        {plant::Mechanism::InletMoistureSensorOffset, 0.5}, {plant::Mechanism::HotAirSensorLag, 30},
        {plant::Mechanism::InletMoistureSensorNoise, 0.4}};
    int runs = 0, right = 0, withFalse = 0;
    std::printf(
        "| mechanism | strength | seed | named | right first | s |\n| --- | --- | --- | --- | --- | --- |\n");
    for (const auto& [m, strength] : cases) {
        for (double scale : {1.0, 0.5}) {
            for (int s = 0; s < nSeeds; ++s) {
                plant::PlantOptions o = options();
                o.seed = seeds[s];
                o.effects[m] = strength * scale;
                const std::string hidden(plant::info(m).name);
                const auto out = run(o, hidden);
                ++runs;
                right += out.rightFirst;
                withFalse += out.falseNames > 0;
                std::printf("| %s | %g | %u | %s | %s | %.1f |\n", hidden.c_str(), strength * scale, o.seed,
                            out.named.c_str(), out.rightFirst ? "yes" : "no", out.seconds);
                std::fflush(stdout);
            }
        }
    }
    int nullRuns = 0, nullFalse = 0;
    for (int s = 0; s < (quick ? 2 : 10); ++s) {
        plant::PlantOptions o = options();
        o.seed = 201 + static_cast<unsigned>(s);
        o.unmeasuredDrift = s % 2 == 1;
        const auto out = run(o, "");
        ++nullRuns;
        nullFalse += out.falseNames > 0;
        std::printf("| none%s | - | %u | %s | - | %.1f |\n", o.unmeasuredDrift ? " (drift)" : "", o.seed,
                    out.named.c_str(), out.seconds);
        std::fflush(stdout);
    }
    std::printf("\nHidden cause named first: %d of %d (%.0f %%). Runs with a cause named that is not there: "
                "%d of %d with a mechanism, %d of %d without (%.0f %% of all %d).\n",
                right, runs, 100.0 * right / runs, withFalse, runs, nullFalse, nullRuns,
                100.0 * (withFalse + nullFalse) / (runs + nullRuns), runs + nullRuns);
    return 0;
}
