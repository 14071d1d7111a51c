#pragma once
// The notes discovery adds to its result (DiscoveryResult::notes), one function per form. The
// engine writes each form here and nowhere else; the workbench words them in its language from
// these forms (widgets/discovery/DiscoverPanel.cpp, DiscoverPanel::noteText), and a widget test
// feeds it every form built here (tests/widgets/TestMainWindow.cpp,
// everyDiscoveryNoteIsWordedInChinese): a form changed here and not there fails that test
// instead of reaching a Chinese window in English. The notes stay plain sentences (discover.json
// and saved projects keep them as text, CONTRACT.md), so a project saved before still reads.

#include <cstddef>
#include <string>
#include <vector>

namespace drytwin::discovery::notes {

/// The data hold no tube-outlet moisture (X_hdt_pct).
std::string tubeOutletMoistureNotMeasured();
/// The data hold no tube-outlet temperature (T_hdt_C).
std::string tubeOutletTemperatureNotMeasured();
/// The air speed never changes in the data.
std::string airSpeedConstant();
/// Only @p causes were tried (discover --causes).
std::string onlyCausesAsked(const std::vector<std::string>& causes);
/// The outlet mixing fitted with h_HDT and k_HDT, a first-order lag of @p lagS.
std::string outletMixing(double lagS);
/// The inlet gauge's normal scatter: @p sharePercent of X_in's fast variation of @p scatterPct.
std::string inletGaugeScatter(double sharePercent, double scatterPct);
/// @p cause named first, then withdrawn: refitted with the causes after it, it is @p why.
std::string withdrawnAfterLaterCauses(const std::string& cause, const std::string& why);
/// An input whose typical value in a batch lies outside a range seen elsewhere.
struct InputOutsideRange {
    std::string input, unit;
    double typical = 0, low = 0, high = 0;
};
/// A batch whose typical value of one or more inputs lies outside what the reference saw: one
/// note for the batch, its inputs listed.
std::string outsideReference(const std::string& batch, const std::vector<InputOutsideRange>& inputs,
                             bool levelNotJudged);
/// The reference's own error drifts within its batches.
std::string referenceDrifts(const std::string& output, double changePerBatch, const std::string& unit,
                            double perHour, double perHourSe);
/// The model commissioned on the reference (its batches and rows, h_HDT and k_HDT).
std::string commissionedOnReference(std::size_t batches, std::size_t rows, double hHdt, double kHdt);
/// The line's own structure learnt on the reference (a ridge with penalty @p lambda).
std::string lineStructureLearnt(double lambda);
/// A reference of fewer than three batches.
std::string shortReference(std::size_t batches);
/// A reference batch whose typical value of an input lies outside what the other reference
/// batches saw: left out of the causes' normal spread
/// (DiscoveryOptions::normalSpreadWithinReferenceConditions).
std::string referenceBatchBeyondOthers(const std::string& batch,
                                       const std::vector<InputOutsideRange>& inputs);
/// An output measured in one period and not in every batch of the other: compared without it.
std::string measuredInOnePeriodOnly(const std::string& column, bool inData);
/// A note on the reference period's own files (the data checks' @p note).
std::string aboutReferenceFiles(const std::string& note);
/// The causes judged on the batches from @p firstJudged on; @p before lie wholly before the change
/// point of DryTwin's monitor (DiscoveryOptions::judgeFromChangeOn).
std::string judgedFromChangeOn(const std::vector<std::string>& before, const std::string& firstJudged);
/// The batches after the one a change began in, taken as changed from their start
/// (DiscoveryOptions::changeGoesOnIntoLaterBatches).
std::string changeGoesOnFromStart(const std::vector<std::string>& batches);

/// The fixed starts of the forms above that carry a value after them.
inline constexpr const char* kOnlyCausesAsked = "only the causes asked were tried: ";
inline constexpr const char* kAboutReferenceFiles = "the reference period: ";

} // namespace drytwin::discovery::notes
