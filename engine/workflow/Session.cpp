// The Session itself (workflow/Session.h): the guard every action on the data passes (data
// loaded), the loaded data at a glance, and the model as the user keeps or edits it (save, set one
// parameter). The actions live in workflow/session/, one file per question: SessionOptions.cpp
// (is the request well formed), SessionData.cpp (data and plant files in and out),
// SessionModelSteps.cpp (simulate, calibrate, train, evaluate, ablation), SessionDiscover.cpp,
// SessionScenarios.cpp (mpc and training, which need no data) and SessionPipeline.cpp.

#include "workflow/Session.h"

#include "data/BatchWriter.h"

#include "io/ModelFile.h"

#include <algorithm>

namespace drytwin::workflow {

Status Session::requireData(const std::string& action) const {
    if (!m_dataSet) {
        return Error{ErrorKind::Usage,
                     action,
                     "no data loaded; open a batch file or folder first",
                     ErrorCode::NoDataLoaded,
                     {}};
    }
    return {};
}

Status Session::requireUsableRows(const std::string& action) const {
    std::size_t kept = 0, rows = 0;
    for (const auto& b : m_si) {
        rows += b.rows();
        kept += static_cast<std::size_t>(std::count(b.keep.begin(), b.keep.end(), 1));
    }
    if (kept > 0) {
        return {};
    }
    // Say why, from what the loading noted (a column with no value at all, say), instead of a
    // later "0 usable rows" that names neither the file nor the column.
    std::string why;
    const auto summary = data::summarize(*m_dataSet, m_cleaning);
    for (const auto& note : summary.emptyRequiredColumns) {
        why += (why.empty() ? "" : "; ") + note;
    }
    // Else the rule that dropped the most rows, by its name, and a frozen transmitter by its column.
    const auto& c = summary.cleaning;
    const auto rules = data::droppedByRule(c, m_cleaning);
    const auto most = std::max_element(rules.begin(), rules.end(),
                                       [](const auto& x, const auto& y) { return x.rows < y.rows; });
    if (why.empty() && most->rows > 0) {
        why = "most rows (" + std::to_string(most->rows) + ") fail the rule " + most->rule;
        if (most == rules.end() - 1 && !c.stuck.empty()) {
            why += " (" + std::string(data::spec(c.stuck.front().column).name) + " holds " +
                   data::formatNumber(c.stuck.front().value) + " for " +
                   std::to_string(static_cast<long>(c.stuck.front().seconds)) +
                   " s: a transmitter that does not move)";
        }
        why += "; `drytwin inspect` lists what each rule dropped";
    }
    return Error{
        ErrorKind::BadInput,
        action,
        "no row of the loaded data (" + std::to_string(rows) + " rows) passes the cleaning" +
            (why.empty() ? std::string("; `drytwin inspect` lists what each rule dropped") : ": " + why),
        ErrorCode::NotEnoughData,
        {"usable rows", "0"}};
}

Expected<data::DataSetSummary> Session::inspect() const {
    if (auto st = requireData("inspect"); !st) {
        return st.error();
    }
    return data::summarize(*m_dataSet, m_cleaning);
}

Status Session::saveModel(const std::string& path) const {
    return io::writeModelFile(m_model, path);
}

Status Session::setParameter(properties::Param param, double value) {
    properties::ParameterSet p = m_model.parameters;
    p[param] = value;
    if (auto st = p.validate(); !st) {
        return st;
    }
    m_model.parameters = p;
    return {};
}

} // namespace drytwin::workflow
