#pragma once

#include "common/Error.h"
#include "physics/LineSimulator.h"
#include "plant/VirtualPlant.h"
#include "properties/Parameters.h"

#include <map>
#include <string>
#include <vector>

namespace drytwin::io {

/// @brief Current version of the model-file format.
inline constexpr int kModelFormatVersion = 1;

/// @brief What a calibration left in the model file.
struct CalibrationRecord {
    struct Estimate {
        std::string symbol;
        double value = 0;
        double ci95Low = 0;
        double ci95High = 0;
        bool atBound = false;
    };
    std::vector<Estimate> estimates;
    double lossBefore = 0;
    double lossAfter = 0;
    int evaluations = 0;
    unsigned seed = 0;
    std::string algorithm;
};

/// @brief A model file: physics parameters, switches, and what later stages add.
/// Unknown top-level keys are kept and written back, so newer stages' data survive.
struct ModelFile {
    properties::ParameterSet parameters;
    properties::ModelSwitches switches;
    physics::WinnowerForm winnower = physics::WinnowerForm::Transient;
    bool hasCalibration = false;
    CalibrationRecord calibration;
    std::string extraJson = "{}"; ///< other top-level keys, verbatim JSON object
};

/// @brief Reads and validates a model file; errors name the file and the key (exit code 3).
Expected<ModelFile> readModelFile(const std::string& path);
/// @brief Parses model-file text; @p name is used in messages.
Expected<ModelFile> parseModelFile(const std::string& text, const std::string& name);
/// @brief Writes a model file atomically.
Status writeModelFile(const ModelFile& model, const std::string& path);
std::string formatModelFile(const ModelFile& model);

/// @brief The `--truth` file of `generate`: the plant's parameters and effects (CONTRACT.md §2).
std::string formatTruth(const properties::ParameterSet& truth,
                        const std::map<plant::Mechanism, double>& effects, unsigned seed,
                        bool unmeasuredDrift);

} // namespace drytwin::io
