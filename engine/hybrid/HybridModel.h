#pragma once

#include "baselines/LstmBaseline.h"
#include "physics/LineSimulator.h"
#include "properties/Parameters.h"
#include "residual/ResidualModel.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace drytwin::hybrid {

/// @brief Model keys of the learnt models (CONTRACT.md §3), in files, JSON results and tables.
inline constexpr const char* kPbmKey = "pbm";
inline constexpr const char* kPgrlCcKey = "pgrl_cc";
inline constexpr const char* kExtInputKey = "ext_input_residual";
inline constexpr const char* kLstmKey = "lstm";

/// @brief What a calibration left in the model: the estimates with their intervals, how well
/// the fit went and how it was found.
struct CalibrationRecord {
    struct Estimate {
        std::string symbol;
        double value = 0;
        double ci95Low = 0;
        double ci95High = 0;
        bool atBound = false;
        double standardErrorFisher = 0; ///< F⁻¹ alone, for comparison with the sandwich interval
    };
    std::vector<Estimate> estimates;
    std::string intervalMethod;
    double lossBefore = 0;
    double lossAfter = 0;
    int evaluations = 0;
    unsigned seed = 0;
    std::string algorithm;
};

/// @brief What discovery found for a mechanism extension of CONTRACT.md §4: its fitted value
/// and 95 % interval. The value the model simulates with is its parameter in
/// HybridModel::parameters (theta_wall, …); this keeps the evidence beside it.
struct MechanismValue {
    double value = 0;
    std::string unit;
    double ci95Low = 0;
    double ci95High = 0;
};

/// @brief The model as a whole: the physics model (parameters, switches, winnower form,
/// mechanism extensions) and what later stages learnt on top of it. Copies are cheap: the
/// learnt models are immutable once trained and shared between copies. Thread-safe for
/// concurrent const use.
struct HybridModel {
    properties::ParameterSet parameters;
    properties::ModelSwitches switches;
    physics::WinnowerForm winnower = physics::WinnowerForm::Transient;
    /// Intervals of the mechanisms discovery fitted, by CONTRACT.md §4 name (the values are the
    /// mechanism parameters in `parameters`; all 0: the paper's base model).
    std::map<std::string, MechanismValue> mechanisms;
    std::optional<CalibrationRecord> calibration;
    std::shared_ptr<const residual::ResidualModel> pgrlCc;   ///< PGRL-CC residual model
    std::shared_ptr<const residual::ResidualModel> extInput; ///< external-input residual baseline
    std::shared_ptr<const baselines::LstmBaseline> lstm;     ///< black-box LSTM baseline
    /// Top-level keys of a model file that this version does not know, as their JSON text,
    /// written back unchanged so that nothing a newer stage stored is lost. Nothing reads them.
    std::map<std::string, std::string> foreignKeys;
    /// What reading the file had to assume (a parameter it lacks, taken at its default), for
    /// the user to see; not written back.
    std::vector<std::string> readNotes;

    /// @brief The simulation options this model implies (switches, winnower form).
    physics::SimulationOptions simulationOptions() const {
        physics::SimulationOptions o;
        o.switches = switches;
        o.winnower = winnower;
        return o;
    }
    /// @brief True when any learnt model is present.
    bool hasResidualModels() const { return pgrlCc || extInput || lstm; }
};

} // namespace drytwin::hybrid
