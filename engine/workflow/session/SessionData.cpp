// How data get into the session and plant data out of it: open() of batch files and a model
// (all read first, taken over only when everything was accepted), the reference period discovery
// compares with, the column-mapping dialog's guess and preview, and generate(), which writes the
// virtual plant's batches as files and leaves the session alone.

#include "workflow/Session.h"

#include "common/AtomicFile.h"
#include "data/BatchReader.h"
#include "data/BatchWriter.h"
#include "data/ColumnMapping.h"
#include "data/PlantFileReader.h"
#include "discovery/DiscoveryNotes.h"
#include "io/ModelFile.h"
#include "io/ResultFiles.h"
#include "plant/PlantExport.h"
#include "workflow/session/SessionInternal.h"

#include <algorithm>
#include <filesystem>

namespace drytwin::workflow {

namespace {

/// The first @p maxBytes of a file, cut after its last whole line (0: all of it); only that much
/// is read, so a preview of a month's export or of a file without line breaks stays small.
Expected<std::string> headOf(const std::string& path, std::size_t maxBytes) {
    return data::readPlantFileHead(path, maxBytes);
}

} // namespace

Expected<OpenResult> Session::open(const OpenOptions& options, const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    // Everything is read first and only then taken over, so a rejection changes nothing.
    std::optional<hybrid::HybridModel> model;
    if (!options.modelPath.empty()) {
        auto m = io::readModelFile(options.modelPath);
        if (!m) {
            return m.error();
        }
        model = std::move(*m);
    }
    OpenResult result;
    std::shared_ptr<const data::DataSet> dataSet;
    if (!options.dataPath.empty()) {
        data::ReadOptions ro;
        if (!options.mappingPath.empty()) {
            auto mapping = data::readColumnMapping(options.mappingPath);
            if (!mapping) {
                return mapping.error();
            }
            ro.mapping = *mapping;
        }
        auto loaded = data::loadDataSet(options.dataPath, ro, progress);
        if (loaded.cancelled) {
            return cancelledError("load");
        }
        if (!loaded.errors.empty()) {
            Error e{ErrorKind::BadInput,
                    options.dataPath,
                    std::to_string(loaded.errors.size()) + " file(s) rejected; nothing was changed",
                    ErrorCode::Unspecified,
                    {}};
            // One rejected file: its own error is the most useful one to show.
            if (loaded.errors.size() == 1) {
                e = loaded.errors.front();
                e.reason += " (nothing was changed)";
            }
            e.causes = std::move(loaded.errors);
            return e;
        }
        dataSet = std::make_shared<const data::DataSet>(std::move(loaded.dataSet));
        result.summary = data::summarize(*dataSet, options.cleaning);
    }
    if (model) {
        result.modelNotes = model->readNotes;
        m_model = std::move(*model);
        result.modelLoaded = true;
    }
    if (dataSet) {
        m_dataSet = dataSet;
        m_dataPath = options.dataPath;
        m_cleaning = options.cleaning;
        m_si = data::toSi(*m_dataSet, data::clean(*m_dataSet, m_cleaning));
        m_latest = {};
        result.dataSet = dataSet;
    }
    result.ending = {Termination::Completed,
                     dataSet ? std::to_string(dataSet->batches.size()) + " batch(es) loaded" : "model loaded",
                     secondsSince(t0)};
    return result;
}

Expected<std::vector<data::SiBatch>> Session::loadReference(const std::string& path,
                                                            const std::string& mappingPath,
                                                            const Progress& progress,
                                                            std::vector<std::string>& notes) const {
    data::ReadOptions ro;
    if (!mappingPath.empty()) {
        auto mapping = data::readColumnMapping(mappingPath);
        if (!mapping) {
            return mapping.error();
        }
        ro.mapping = *mapping;
    }
    auto loaded = data::loadDataSet(path, ro, progress);
    if (loaded.cancelled) {
        return cancelledError("load");
    }
    if (!loaded.errors.empty()) {
        Error e = loaded.errors.front();
        e.reason = "the reference period: " + e.reason;
        e.causes = std::move(loaded.errors);
        return e;
    }
    if (loaded.dataSet.batches.empty()) {
        return Error{ErrorKind::BadInput,
                     path,
                     "the reference period holds no batch file",
                     ErrorCode::NotEnoughData,
                     {"reference batches", "0"}};
    }
    // The same checks the data get (a hot air 74 K from its setpoint: °F under a °C header?):
    // a reference read wrong commissions the model wrong, and every later verdict with it.
    for (const auto& n : data::summarize(loaded.dataSet, m_cleaning).notes) {
        notes.push_back(discovery::notes::aboutReferenceFiles(n));
    }
    return data::toSi(loaded.dataSet, data::clean(loaded.dataSet, m_cleaning));
}

Expected<data::MappingGuess> Session::guessMapping(const std::string& path) {
    auto text = headOf(path, 4u << 20);
    if (!text) {
        return text.error();
    }
    return data::guessMapping(*text, path);
}

Expected<data::PlantFileRuns> Session::previewRuns(const std::string& path,
                                                   const data::ColumnMapping& mapping, std::size_t maxBytes) {
    auto text = headOf(path, maxBytes);
    if (!text) {
        return text.error();
    }
    data::ReadOptions o;
    o.mapping = mapping;
    return data::parsePlantText(*text, path, o);
}

namespace {

/// The CSV files in @p folder other than the B01.csv ... B<n>.csv a generate of @p batches writes.
std::vector<std::string> batchFilesNotWritten(const std::string& folder, int batches) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const auto name = entry.path().filename().string();
        if (entry.path().extension() != ".csv") {
            continue;
        }
        bool written = false;
        for (int b = 1; b <= batches && !written; ++b) {
            written = name == plant::batchId(b) + ".csv";
        }
        if (!written) {
            out.push_back(name);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

Expected<GenerateResult> Session::generate(const GenerateOptions& options, const Progress& progress) const {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    std::error_code ec;
    std::filesystem::create_directories(options.outFolder, ec);
    if (ec) {
        return Error{ErrorKind::BadInput, options.outFolder, "cannot create the folder: " + ec.message()};
    }
    // Batch files this run would not overwrite (an earlier, larger data set) would be read with
    // the new ones as one mixed data set: refused before anything is written, nothing deleted.
    if (auto stale = batchFilesNotWritten(options.outFolder, options.plant.batches); !stale.empty()) {
        std::string names;
        for (std::size_t i = 0; i < stale.size() && i < 5; ++i) {
            names += (i ? ", " : "") + stale[i];
        }
        if (stale.size() > 5) {
            names += ", ... (" + std::to_string(stale.size()) + " in all)";
        }
        return Error{ErrorKind::Usage, options.outFolder,
                     "the folder already holds batch files that this run would not overwrite (" + names +
                         "): they would be read with the new batches as one data set; choose an empty "
                         "folder or remove them"};
    }
    auto plantResult = plant::runPlant(options.plant, progress);
    if (!plantResult) {
        return plantResult.error();
    }
    GenerateResult result;
    for (const auto& pb : plantResult->batches) {
        const std::string path = (std::filesystem::path(options.outFolder) / (pb.id + ".csv")).string();
        if (auto st = data::writeBatchFile(plant::toBatch(pb, options.plant.seed), path); !st) {
            return st.error();
        }
        result.files.push_back(path);
    }
    if (!options.truthPath.empty()) {
        if (auto st = writeFileAtomically(options.truthPath, io::truthJson(options.plant, *plantResult));
            !st) {
            return st.error();
        }
    }
    result.samplesPerBatch = options.plant.samples;
    result.ending = {Termination::Completed, std::to_string(result.files.size()) + " batch file(s) written",
                     secondsSince(t0)};
    return result;
}

} // namespace drytwin::workflow
