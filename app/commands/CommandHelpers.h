#pragma once

// What the subcommands share: the error exit, opening --data/--model, number formatting, the
// calibration and training options of the command line, and the printed tables.
#include "HeadlessCommands.h"

#include "workflow/Session.h"

#include <string>
#include <vector>

namespace drytwin::app::detail {

/// @brief Prints @p e (and each rejected file) to stderr; the contract's exit code.
int fail(const Error& e);
/// @brief Opens --data (with --mapping and the cleaning rules) and --model in @p session.
/// Notes on what the files did not say go to stderr unless @p printNotes is false (inspect lists them).
bool open(const CommandOptions& o, workflow::Session& session, int& exitCode, bool withData = true,
          bool printNotes = true);
/// @brief @p v with @p precision decimals, "-" for NaN.
std::string fmt(double v, int precision = 3);
/// @brief "--bound NAME=LO:HI" into the options; false with a message on a malformed one.
bool parseBounds(const std::vector<std::string>& specs, calibration::CalibrationOptions& co, int& exitCode);
/// @brief The calibration options of the command line; false with a message on a malformed one.
bool calibrateOptions(const CommandOptions& o, workflow::CalibrateOptions& options, int& exitCode);
void printCalibration(const workflow::CalibrateResult& result);
void printEvaluation(const evaluation::EvaluationResult& ev);
void printTraining(const workflow::TrainResult& t);
/// @brief The LSTM baseline's verdict on its validation part, one line, flagged when it does not
/// beat the trivial references.
void printLstmValidation(const baselines::LstmBaseline& lstm);
void printAblation(const hybrid::AblationResult& a);
/// @brief The training options of the command line; false with a message on a malformed one.
bool trainOptions(const CommandOptions& o, workflow::TrainOptions& options, int& exitCode);

} // namespace drytwin::app::detail
