#include "HeadlessCommands.h"
#include "commands/CommandHelpers.h"
#include "commands/LiveHelpers.h"

#include "common/AtomicFile.h"
#include "common/Units.h"
#include "control/BundledScenarios.h"
#include "io/ModelFile.h"
#include "io/ResultFiles.h"
#include "plant/Mechanisms.h"
#include "workflow/Session.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace drytwin::app {

using namespace detail;

int runGenerate(const CommandOptions& o) {
    workflow::GenerateOptions go;
    const plant::PlantKind kind =
        o.plantKind == "lumped" ? plant::PlantKind::Lumped : plant::PlantKind::Distributed;
    go.plant = o.demo ? plant::PlantOptions::demo(o.seed, kind) : plant::PlantOptions{};
    go.plant.plant = kind;
    // Unless told otherwise, each plant reads through its own default instruments: realistic
    // transmitters on the distributed line, the lumped plant's built-in noise on the lumped one
    // (which keeps its files byte-identical to earlier versions).
    if (o.sensorModeGiven) {
        if (o.sensorMode == "builtin" && kind != plant::PlantKind::Lumped) {
            return fail(
                Error{ErrorKind::Usage, "--sensors builtin", "only the lumped plant has built-in sensors"});
        }
        go.plant.sensors = o.sensorMode == "ideal"       ? plant::SensorMode::Ideal
                           : o.sensorMode == "realistic" ? plant::SensorMode::Realistic
                                                         : plant::SensorMode::Default;
    }
    go.plant.sensorFaults = o.sensorFaults;
    go.plant.seed = o.seed;
    go.plant.batches = o.batches;
    go.plant.samples = o.samples;
    go.outFolder = o.outPath;
    go.truthPath = o.truthPath;
    go.plant.unmeasuredDrift = go.plant.unmeasuredDrift || o.drift;
    if (!o.periodic.empty()) {
        if (std::sscanf(o.periodic.c_str(), "%lf:%lf", &go.plant.hiddenPeriodS, &go.plant.hiddenAmplitudeK) !=
            2) {
            return fail(Error{ErrorKind::Usage, "--periodic " + o.periodic, "expected PERIOD_S:AMPLITUDE_K"});
        }
    }
    for (const auto& e : o.effects) {
        const auto eq = e.find('=');
        const std::string name = e.substr(0, eq);
        const auto m = plant::mechanismByName(name);
        if (!m) {
            std::string known;
            for (const auto& i : plant::mechanisms()) {
                known += " " + std::string(i.name);
            }
            return fail(Error{ErrorKind::Usage, "--effect " + name, "unknown mechanism; known:" + known});
        }
        double strength = plant::info(*m).defaultStrength;
        if (eq != std::string::npos) {
            try {
                std::size_t used = 0;
                strength = std::stod(e.substr(eq + 1), &used);
                if (used != e.size() - eq - 1) {
                    throw std::invalid_argument("trailing text");
                }
            } catch (const std::exception&) {
                return fail(Error{ErrorKind::Usage, "--effect " + e, "strength is not a number"});
            }
        }
        go.plant.effects[*m] = strength;
    }
    for (const auto& e : o.onsets) {
        const auto eq = e.find('=');
        const auto m = plant::mechanismByName(e.substr(0, eq));
        if (!m || eq == std::string::npos) {
            return fail(
                Error{ErrorKind::Usage, "--onset " + e, "expected NAME=SECONDS with a mechanism's name"});
        }
        try {
            std::size_t used = 0;
            const double s = std::stod(e.substr(eq + 1), &used);
            if (used != e.size() - eq - 1 || !(s >= 0)) {
                throw std::invalid_argument("not a time");
            }
            go.plant.effectOnsetS[*m] = s;
        } catch (const std::exception&) {
            return fail(Error{ErrorKind::Usage, "--onset " + e, "the onset is not a time in seconds >= 0"});
        }
        if (!go.plant.effects.count(*m)) {
            return fail(Error{ErrorKind::Usage, "--onset " + e, "give the mechanism with --effect too"});
        }
    }
    if (o.outPath.empty() && o.brokerUrl.empty()) {
        return fail(invalidOption("generate",
                                  "give --out DIR (batch files) or --publish URL (a live line), or both"));
    }
    if (o.outPath.empty()) {
        return publishPlant(o, go.plant);
    }
    auto result = workflow::Session().generate(go, o.progress);
    if (!result) {
        return fail(result.error());
    }
    std::printf("wrote %zu batch(es) of %d samples of the %s plant (%s sensors) to %s in %.2f s\n",
                result->files.size(), result->samplesPerBatch,
                std::string(plant::plantKindName(kind)).c_str(),
                go.plant.realisticSensors()                    ? "realistic"
                : go.plant.sensors == plant::SensorMode::Ideal ? "ideal"
                                                               : "built-in",
                o.outPath.c_str(), result->ending.elapsedSeconds);
    // Both: the files first, then the same samples on the broker (a recording to compare with).
    return o.brokerUrl.empty() ? 0 : publishPlant(o, go.plant);
}

} // namespace drytwin::app
