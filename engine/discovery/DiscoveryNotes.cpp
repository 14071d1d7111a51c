// The notes of discovery, one function per form (DiscoveryNotes.h says why in one place).
#include "discovery/DiscoveryNotes.h"

#include "common/TextList.h"
#include "discovery/DiscoveryInternal.h"

namespace drytwin::discovery::notes {

using detail::format;

std::string tubeOutletMoistureNotMeasured() {
    return "X_hdt_pct is not measured: the tube-outlet moisture cannot separate meter and conveyor causes "
           "from tube causes; outlet channels only";
}

std::string tubeOutletTemperatureNotMeasured() {
    return "T_hdt_C is not measured: tube-outlet temperature not used";
}

std::string airSpeedConstant() {
    return "air_speed_m_s is constant (not measured?): gas_phase_coupling works with that one value and "
           "cannot use the air speed's variation";
}

std::string onlyCausesAsked(const std::vector<std::string>& causes) {
    return kOnlyCausesAsked + commaList(causes);
}

std::string outletMixing(double lagS) {
    return format("the line's outlet mixing (belt and winnower, both outlet channels): a first-order lag of "
                  "%.1f s fitted with h_HDT and k_HDT (0: plug flow)",
                  lagS);
}

std::string inletGaugeScatter(double sharePercent, double scatterPct) {
    return format("the inlet gauge's normal scatter: %.0f %% of X_in's fast variation (%.2g %% wb, 1σ about "
                  "its 30 s mean) is taken as gauge scatter, not moisture, in the starting model",
                  sharePercent, scatterPct);
}

std::string withdrawnAfterLaterCauses(const std::string& cause, const std::string& why) {
    return cause + ": named first, then withdrawn: refitted with the causes named after it, it is " + why +
           "; it had taken up what they explain";
}

namespace {
/// "T_amb_C is typically 31.6 °C, outside what the reference saw (11 to 23 °C); RH_pct is …": a
/// batch's inputs in one list, so that a winter batch (cold and dry) is one note, not two.
std::string inputsOutside(const std::vector<InputOutsideRange>& inputs, const char* seenBy) {
    std::string list;
    for (const auto& in : inputs) {
        list += (list.empty() ? "" : "; ") +
                format("%s is typically %.4g %s, outside what %s saw (%.4g to %.4g %s)", in.input.c_str(),
                       in.typical, in.unit.c_str(), seenBy, in.low, in.high, in.unit.c_str());
    }
    return list;
}
} // namespace

std::string outsideReference(const std::string& batch, const std::vector<InputOutsideRange>& inputs,
                             bool levelNotJudged) {
    return format("%s: %s: %s", batch.c_str(), inputsOutside(inputs, "the reference").c_str(),
                  levelNotJudged ? "the reference has no normal level for these conditions, so the detectors "
                                   "judge only changes within this batch, not its level"
                                 : "the model's error there is judged beyond the reference's conditions, and "
                                   "an alarm there may be that condition rather than a change of the line");
}

std::string referenceDrifts(const std::string& output, double changePerBatch, const std::string& unit,
                            double perHour, double perHourSe) {
    return format("the reference period itself drifts: the model's %s error changes by %.2g %s within a mean "
                  "batch (%.3g ± %.2g %s/h); a reference should be a period when the line ran well, or a "
                  "change since may read as none",
                  output.c_str(), changePerBatch, unit.c_str(), perHour, perHourSe, unit.c_str());
}

std::string commissionedOnReference(std::size_t batches, std::size_t rows, double hHdt, double kHdt) {
    return format("commissioned on the reference period (%zu batch(es), %zu rows): h_HDT %.4g W/(m²·K), "
                  "k_HDT %.4g m/s, held fixed on the data judged",
                  batches, rows, hHdt, kHdt);
}

std::string lineStructureLearnt(double lambda) {
    return format("the line's own structure (what the model always gets wrong, a ridge regression on the "
                  "inputs and the model's outputs, penalty %.0e) learnt on the reference and taken off the "
                  "measurements: the residuals below are what is left",
                  lambda);
}

std::string referenceBatchBeyondOthers(const std::string& batch,
                                       const std::vector<InputOutsideRange>& inputs) {
    return format(
        "reference batch %s: %s: the line's structure there is the map's extrapolation, so the batch is "
        "left out of the causes' normal spread",
        batch.c_str(), inputsOutside(inputs, "the other reference batches").c_str());
}

std::string shortReference(std::size_t batches) {
    return format("the reference holds %zu batch(es): a period's normal spread comes from thirds of them, "
                  "which share their day and weather; a change named here may be a difference of conditions "
                  "the reference never showed. A reference of several batches over the conditions the line "
                  "runs in (weeks, seasons) judges better",
                  batches);
}

std::string judgedFromChangeOn(const std::vector<std::string>& before, const std::string& firstJudged) {
    return "the causes are judged on the batches from " + firstJudged + " on, where the change began; " +
           commaList(before) + " before it ran as the reference did";
}

std::string changeGoesOnFromStart(const std::vector<std::string>& batches) {
    return "the change goes on from the start of " + commaList(batches) +
           " (the monitor reads them changed before the onset time too): the causes act there from the "
           "batch's start";
}

std::string measuredInOnePeriodOnly(const std::string& column, bool inData) {
    return column + " is measured in " +
           (inData ? "the data but not in every batch of the reference period"
                   : "the reference period but not in every batch of the data") +
           ": the periods are compared on the outputs both measure, without it";
}

std::string aboutReferenceFiles(const std::string& note) {
    return kAboutReferenceFiles + note;
}

} // namespace drytwin::discovery::notes
