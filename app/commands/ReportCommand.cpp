// `drytwin report --project FILE --out DIR`: the pipeline's HTML and PDF report from what a saved
// project holds (its results file and its data), so that work done in the workbench, or step by
// step on the command line and saved as a project, reaches a report without re-running anything.

#include "HeadlessCommands.h"
#include "commands/CommandHelpers.h"

#include "common/AtomicFile.h"
#include "workflow/ProjectFile.h"
#include "workflow/ResultArchive.h"
#include "workflow/Session.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace drytwin::app {

using namespace detail;

int runReport(const CommandOptions& o) {
    std::error_code ec;
    if (std::filesystem::exists(o.outPath, ec) && !std::filesystem::is_directory(o.outPath, ec)) {
        return fail(Error{ErrorKind::Usage, "--out " + o.outPath,
                          "is a file; give a folder (made if missing; report.html and report.pdf in it are "
                          "replaced)"});
    }
    auto paths = workflow::readProjectPaths(o.projectPath);
    if (!paths) {
        return fail(paths.error());
    }
    if (paths->results.empty() || !std::filesystem::exists(paths->results, ec)) {
        return fail(Error{ErrorKind::BadInput, o.projectPath,
                          paths->results.empty()
                              ? "the project holds no results; run the steps in the workbench and save it"
                              : "its results file " + paths->results + " is missing"});
    }
    const auto text = readWholeFile(paths->results);
    if (!text) {
        return fail(text.error());
    }
    auto latest = workflow::parseLatestResults(*text, paths->results);
    if (!latest) {
        return fail(latest.error());
    }
    // Before the data are read: a project without every step's result fails at once, naming them.
    if (auto missing = workflow::reportInputs(*latest, {}); !missing) {
        return fail(
            Error{ErrorKind::BadInput, o.projectPath,
                  missing.error().reason +
                      " (run them in the workbench and save the project, or run `drytwin pipeline`)"});
    }
    // --data: the same data moved elsewhere (an archive folder); the fingerprint below still checks
    // that they are the batches and rows the results were made on.
    if (!o.dataPath.empty()) {
        paths->data = o.dataPath;
        if (!o.mappingPath.empty()) {
            paths->mapping = o.mappingPath;
        }
    }
    if (paths->data.empty()) {
        return fail(Error{ErrorKind::BadInput, o.projectPath, "the project names no data set (give --data)"});
    }
    if (!std::filesystem::exists(paths->data, ec)) {
        return fail(Error{ErrorKind::BadInput, o.projectPath,
                          "its data set is not where the project says, beside it or where it was saved (" +
                              paths->data + "); give --data where they are now, or put them back"});
    }
    // The report's figures draw the data the results came from.
    CommandOptions withData = o;
    withData.dataPath = paths->data;
    withData.mappingPath = paths->mapping;
    withData.modelPath.clear();
    workflow::Session session;
    int rc = 0;
    if (!open(withData, session, rc)) {
        return rc;
    }
    auto summary = session.inspect();
    if (!summary) {
        return fail(summary.error());
    }
    // The results were made on the data as saved: a report that drew other data beside them (and
    // hashed them as the results' source) would be wrong without a word.
    if (const auto change =
            workflow::dataChangeSince(paths->dataFingerprint, workflow::dataFingerprint(*summary));
        !paths->dataFingerprint.empty() && change) {
        return fail(Error{ErrorKind::BadInput, o.projectPath,
                          "its data at " + paths->data + " are not those its results were made on (" +
                              change->describe() +
                              "); run the steps again on these data and save the project"});
    }
    auto inputs = workflow::reportInputs(*latest, *summary);
    if (!inputs) {
        return fail(inputs.error());
    }
    inputs->resultsFrom = std::filesystem::absolute(paths->results, ec).string();
    if (!o.renderReport) {
        return fail(Error{ErrorKind::Usage, "report", "this build cannot draw the report's figures"});
    }
    if (std::filesystem::create_directories(o.outPath, ec); ec) {
        return fail(
            Error{ErrorKind::BadInput, o.outPath, "cannot create the report folder: " + ec.message()});
    }
    std::string error;
    const auto files = o.renderReport(*inputs, session, o.outPath, error);
    if (!error.empty()) {
        return fail(Error{ErrorKind::BadInput, o.outPath, "the HTML/PDF report: " + error});
    }
    std::printf("report of project %s (results %s, data %s)\n", o.projectPath.c_str(), paths->results.c_str(),
                paths->data.c_str());
    for (const auto& f : files) {
        std::printf("report %s\n", f.c_str());
    }
    return 0;
}

} // namespace drytwin::app
