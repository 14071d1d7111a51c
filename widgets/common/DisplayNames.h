#pragma once

#include "common/Progress.h"
#include "control/ClosedLoop.h"

#include <QString>
#include <string>
#include <string_view>

namespace drytwin::widgets {

// The engine names things by their contract keys (pgrl_cc, heat_transfer_fouling, cause_found),
// which the CLI and the result files keep. A process engineer reads the GUI: these word them in
// plain language, translated; the key and the paper's name go into tooltips (issue #26).

/// @brief A controller or prediction model in an engineer's words ("Physics + learnt correction"),
/// in the workbench's language, or in English with @p translated false (the report is English).
QString controllerDisplayName(control::ControllerKind kind, bool translated = true);
/// @brief A model by its contract key (pbm, pgrl_cc, ext_input_residual, lstm, persistence,
/// pbm_residual_hold, pi); the key itself when unknown. @p translated as for controllerDisplayName().
QString modelDisplayName(const std::string& key, bool translated = true);
/// @brief A cause of CONTRACT.md §4 by its name ("heat-transfer fouling"); the name when unknown.
QString causeDisplayName(const std::string& cause);
/// @brief A monitored column by its contract name ("T_hot_C": "hot-air temperature", "error_X_out_pct":
/// "model error, outlet moisture"); the name when unknown.
QString columnDisplayName(const std::string& column);
/// @brief A data column's meaning (data/Columns.cpp's English text) in the user's language.
QString columnMeaningText(std::string_view english);
/// @brief A time-stamp format by its mapping-file name ("iso8601", "d.m.Y", "epoch_s") in words.
QString timeFormatText(const std::string& format);
/// @brief Why a production run ended, by the engine's word ("line stop", "gap", "end of file").
QString runEndText(const std::string& reason);
/// @brief Why the column-mapping guess proposed a header (the engine's English: "values in
/// 100–230, name, tag TIC", "the contract's own name", "time stamps: iso8601"), in words.
QString mappingReasonText(const std::string& reason);
/// @brief A progress report's detail with the engine's keys worded: a what-if run's "pgrl_cc, step
/// 600/1300" becomes "Physics + learnt correction (PGRL-CC): second 600 of 1300"; other details as
/// they are.
QString progressDetailText(const std::string& stage, const std::string& detail);
/// @brief An engine unit after a value, in the user's language: " % wb" (" % 湿基"), " 1/h", and
/// nothing for a dimensionless one ("-"), which read as a stray dash in a sentence.
QString unitSuffix(std::string_view unit);
/// @brief A look-alike group by its name ("outlet response time: meter lag or transport time").
QString groupDisplayName(const std::string& group);
/// @brief Discovery's verdict as a heading ("Cause found: heat-transfer fouling").
QString verdictDisplayText(const std::string& verdict, const QString& firstCause = {});
/// @brief What to do next after a discovery verdict, in plant words (issue #43 item 15); empty
/// for a verdict key it does not know.
QString verdictNextStep(const std::string& verdict, bool aCauseFitsButFailedACheck = false,
                        bool againstReference = false);
/// @brief How an iterative action ended, as the first words of a sentence ("Converged").
QString terminationText(Termination termination);
/// @brief A what-if run's ending in words ("Scenario x: 5 controllers, 1000 scored seconds").
QString mpcEndingText(const control::ClosedLoopResult& result);
/// @brief A unit as a column mapping names it ("degC", "% db", "fraction wb") in the user's words.
QString mappingUnitText(const std::string& unit);
/// @brief How a calibration's intervals were made, in plain words (the engine's method string is
/// English); the statistician's names are in intervalMethodDetails().
QString intervalMethodText(const std::string& method);
/// @brief The same with the method's technical names (sandwich covariance, Newey-West), for a tooltip.
QString intervalMethodDetails(const std::string& method);
/// @brief What an R² says in words, for the tooltips of R² cells (R² < 0: worse than the mean).
QString r2Explanation(double r2);

} // namespace drytwin::widgets
