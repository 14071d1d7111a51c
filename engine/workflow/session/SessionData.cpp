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
#include "io/ModelFile.h"
#include "io/ResultFiles.h"
#include "plant/PlantExport.h"
#include "workflow/session/SessionInternal.h"

#include <filesystem>

namespace drytwin::workflow {

namespace {

/// The first @p maxBytes of a file, cut after its last whole line (0: all of it).
Expected<std::string> headOf(const std::string& path, std::size_t maxBytes) {
    auto text = readWholeFile(path);
    if (!text) {
        return text.error();
    }
    if (maxBytes > 0 && text->size() > maxBytes) {
        text->resize(maxBytes);
        const auto nl = text->rfind('\n');
        if (nl != std::string::npos) {
            text->resize(nl + 1);
        }
    }
    return text;
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
                                                            const Progress& progress) const {
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
