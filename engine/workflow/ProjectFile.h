#pragma once

#include "common/Error.h"
#include "workflow/Session.h"

#include <optional>
#include <string>
#include <vector>

namespace drytwin::workflow {

/// @brief The files a project (`.dtproj`, written by the workbench's File ▸ Save project) points
/// to, each resolved: relative to the project's folder where it exists there (a folder moved with
/// its data), else where it was when the project was saved (a project file mailed away from its
/// data). An entry the project does not have is empty. Read alike by the workbench and by
/// `drytwin report`.
struct ProjectPaths {
    std::string data, mapping, model, results, reference;
    struct DataSet {
        std::string label, path, mapping;
        /// Its latest results (a LatestResults archive) when it was not the loaded one; "" for none.
        std::string results;
        int batches = -1; ///< its batch count when saved (-1: a project that does not say)
        /// A reference period offered for it (a training recording's commissioning runs); "" for none.
        std::string suggestedReference;
    };
    std::vector<DataSet> dataSets; ///< every data set the window had open
    /// The data's batches and rows when the project was saved (dataFingerprint()); "" in a project
    /// that does not say.
    std::string dataFingerprint;
};

/// @brief A data set's batches and rows, and a digest of its values, as a project stores them
/// ("B01:1500 B02:1500 values:3f9a…"): whether the data a project names are still those its
/// results were made on, a value edited in place included.
std::string dataFingerprint(const data::DataSetSummary& summary);

/// @brief How a data set differs from the one a project's results were made on.
struct DataChange {
    std::string batchesThen, batchesNow; ///< "B01:1500 B02:1500"; "" for none
    bool valuesOnly = false;             ///< the same batches and rows, other values
    /// In English for the command line and logs; the workbench words it from the fields.
    std::string describe() const;
};

/// @brief Whether the data @p now (a dataFingerprint()) differ from those @p saved describes, and
/// how. A fingerprint saved before the digest existed ("B01:1500 B02:1500") is compared by its
/// batches and rows alone.
std::optional<DataChange> dataChangeSince(const std::string& saved, const std::string& now);

/// @brief Reads @p projectPath; a BadInput error naming the file when it cannot be read or is not a
/// DryTwin project.
Expected<ProjectPaths> readProjectPaths(const std::string& projectPath);

/// @brief The steps a report needs whose result @p latest lacks, by their subcommand's name
/// (calibrate, train, evaluate, ablation, discover, mpc), in the pipeline's order. train counts as
/// missing when the evaluation holds no PGRL-CC (a project's results do not keep the training
/// itself: its models are in the model file), so that no report shows the PBM alone under the
/// paper's captions.
std::vector<std::string> stepsMissingForReport(const LatestResults& latest);

/// @brief What the pipeline's report is drawn from, put together from a session's (or a saved
/// project's) latest results and the data's summary; a Usage error naming the steps still to run
/// when one is missing (stepsMissingForReport()), so that no section shows numbers of another
/// model or none.
Expected<PipelineResult> reportInputs(const LatestResults& latest, const data::DataSetSummary& inspect);

} // namespace drytwin::workflow
