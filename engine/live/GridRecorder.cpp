#include "GridRecorder.h"

#include "data/BatchWriter.h"
#include "data/historian/TimeStamps.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace drytwin::live {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::uint32_t bitOf(data::Column c) {
    return 1u << static_cast<unsigned>(c);
}

/// "20250603T080000" of Unix seconds: a file-name-safe UTC stamp.
std::string compactUtc(std::int64_t second) {
    std::string iso = data::historian::isoTimestamp(static_cast<double>(second));
    iso.erase(std::remove_if(iso.begin(), iso.end(), [](char ch) { return ch == '-' || ch == ':'; }),
              iso.end());
    return iso;
}

} // namespace

Status GridRecorderOptions::validate() const {
    if (!(reorderWindowS >= 0 && reorderWindowS <= 3600)) {
        return invalidOption("--reorder-window", "must lie in [0, 3600] s");
    }
    if (!(splitGapS >= 1)) {
        return invalidOption("--split-gap", "must be at least 1 s");
    }
    if (!(writeEveryS > 0)) {
        return invalidOption("write interval", "must be positive");
    }
    return {};
}

GridRecorder::GridRecorder(GridRecorderOptions options)
    : m_options(std::move(options)), m_lastWrite(std::chrono::steady_clock::now()) {}

void GridRecorder::addSample(data::Column c, const TagSample& sample) {
    const auto second = static_cast<std::int64_t>(std::llround(sample.timeS));
    const std::uint32_t bit = bitOf(c);
    if (m_anyFinal && second < m_finalBefore) {
        // A second copy of a sample already written (a QoS 1 redelivery after a reconnect) is a
        // duplicate; anything else for a final row came too late to be placed.
        const auto& rows = m_batch.rows;
        const auto it = std::lower_bound(rows.begin(), rows.end(), second,
                                         [](const Row& r, std::int64_t s) { return r.second < s; });
        if (m_open && it != rows.end() && it->second == second && (it->present & bit)) {
            ++m_counts.duplicates;
        } else {
            ++m_counts.late;
        }
        return;
    }
    auto [it, added] = m_pending.try_emplace(second);
    Row& row = it->second;
    if (added) {
        row.second = second;
        row.values.fill(kNaN);
    }
    if (row.present & bit) {
        ++m_counts.duplicates;
        return;
    }
    row.values[static_cast<std::size_t>(c)] = sample.value;
    row.present |= bit;
    ++m_counts.samples;
    m_newest = m_anySample ? std::max(m_newest, second) : second;
    m_anySample = true;
}

void GridRecorder::addBatchStart(const std::string& id, double timeS) {
    auto second = static_cast<std::int64_t>(std::llround(timeS));
    if (m_anyFinal && second < m_finalBefore) {
        second = m_finalBefore; // announced late: the batch begins with the next row written
    }
    m_batchStarts[second] = id;
}

Status GridRecorder::flush(bool everything) {
    if (m_anySample) {
        const auto window = static_cast<std::int64_t>(std::ceil(m_options.reorderWindowS));
        const std::int64_t limit = everything ? m_newest + 1 : m_newest - window + 1;
        while (!m_pending.empty() && m_pending.begin()->first < limit) {
            Row row = m_pending.begin()->second;
            m_pending.erase(m_pending.begin());
            finalise(std::move(row));
        }
        if (!m_anyFinal || limit > m_finalBefore) {
            m_finalBefore = limit;
            m_anyFinal = true;
        }
    }
    const double sinceWrite =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_lastWrite).count();
    if (everything || sinceWrite >= m_options.writeEveryS) {
        if (auto st = writeOpenBatch(); !st) {
            return st;
        }
    }
    if (!m_writeError) {
        return m_writeError;
    }
    return {};
}

void GridRecorder::finalise(Row row) {
    // A batch announced for this second or before it begins here.
    std::string announced;
    std::int64_t announcedAt = row.second;
    while (!m_batchStarts.empty() && m_batchStarts.begin()->first <= row.second) {
        announced = m_batchStarts.begin()->second;
        announcedAt = m_batchStarts.begin()->first;
        m_batchStarts.erase(m_batchStarts.begin());
    }
    const std::int64_t last =
        m_open ? (m_batch.rows.empty() ? m_batch.startSecond - 1 : m_batch.rows.back().second)
               : row.second - 1;
    if (!announced.empty() && (!m_open || announced != m_batch.id)) {
        beginBatch(announced, std::clamp(announcedAt, last + 1, row.second));
    } else if (!m_open || static_cast<double>(row.second - last - 1) > m_options.splitGapS) {
        beginBatch(m_options.unnamedPrefix + "_" + compactUtc(row.second), row.second);
    }
    // Seconds without any message before this row: rows of missing cells, never interpolated.
    const std::int64_t from = m_batch.rows.empty() ? m_batch.startSecond : m_batch.rows.back().second + 1;
    for (std::int64_t s = from; s < row.second; ++s) {
        Row gap;
        gap.second = s;
        gap.values.fill(kNaN);
        appendRow(gap);
    }
    appendRow(row);
}

void GridRecorder::appendRow(const Row& row) {
    m_batch.columnsSeen |= row.present;
    m_batch.rows.push_back(row);
    m_batch.dirty = true;
    ++m_counts.rows;
    if (m_options.keepFinalRows) {
        m_finalRows.push_back({m_batch.id, static_cast<double>(m_batch.startSecond),
                               static_cast<double>(row.second - m_batch.startSecond), row.values});
    }
}

std::vector<FinalRow> GridRecorder::takeFinalRows() {
    std::vector<FinalRow> rows;
    rows.swap(m_finalRows);
    return rows;
}

void GridRecorder::beginBatch(const std::string& id, std::int64_t second) {
    if (m_open) {
        if (auto st = writeOpenBatch(); !st) {
            m_writeError = st;
        }
    }
    m_batch = OpenBatch{};
    m_batchMissingCounted = 0;
    m_batch.id = id;
    m_batch.startSecond = second;
    m_batch.path = pathFor(id);
    m_open = true;
    ++m_counts.batches;
    if (!m_batch.path.empty()) {
        m_files.push_back(m_batch.path);
    }
}

std::string GridRecorder::pathFor(const std::string& id) const {
    if (m_options.folder.empty()) {
        return {};
    }
    namespace fs = std::filesystem;
    // Never over an earlier recording's file, nor over this run's own (a batch id sent twice).
    for (int n = 1;; ++n) {
        const std::string stem = n == 1 ? id : id + "_" + std::to_string(n);
        const std::string path = (fs::path(m_options.folder) / (stem + ".csv")).string();
        std::error_code ec;
        if (!fs::exists(path, ec) && std::find(m_files.begin(), m_files.end(), path) == m_files.end()) {
            return path;
        }
    }
}

data::Batch GridRecorder::toBatch(const OpenBatch& b) const {
    data::Batch batch;
    batch.id = b.id;
    batch.metadataLines = {"# batch: " + b.id, "# source: " + m_options.sourceText,
                           "# start: " + data::historian::isoTimestamp(static_cast<double>(b.startSecond)) +
                               "Z",
                           "# sampling: 1 s"};
    const std::size_t n = b.rows.size();
    std::vector<double> time(n);
    for (std::size_t i = 0; i < n; ++i) {
        time[i] = static_cast<double>(b.rows[i].second - b.startSecond);
    }
    batch.setValues(data::Column::Time, std::move(time));
    // Only the columns the line sends: a tag it never published is absent, as from a file.
    for (const auto& s : data::columnSpecs()) {
        if (s.id == data::Column::Time || !(b.columnsSeen & bitOf(s.id))) {
            continue;
        }
        std::vector<double> v(n);
        for (std::size_t i = 0; i < n; ++i) {
            v[i] = b.rows[i].values[static_cast<std::size_t>(s.id)];
        }
        batch.setValues(s.id, std::move(v));
    }
    batch.lineOfRow.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        batch.lineOfRow[i] = static_cast<int>(i + batch.metadataLines.size() + 2);
    }
    return batch;
}

Status GridRecorder::writeOpenBatch() {
    if (!m_open || !m_batch.dirty) {
        return {};
    }
    // The missing cells of the batch's own columns, recounted at each write of its rows.
    long missing = 0;
    for (const auto& row : m_batch.rows) {
        missing += __builtin_popcount(m_batch.columnsSeen & ~row.present);
    }
    m_counts.missingCells += missing - m_batchMissingCounted;
    m_batchMissingCounted = missing;
    m_lastWrite = std::chrono::steady_clock::now();
    if (m_batch.path.empty()) {
        m_batch.dirty = false;
        return {};
    }
    std::error_code ec;
    std::filesystem::create_directories(m_options.folder, ec);
    if (ec) {
        return Error{ErrorKind::BadInput, m_options.folder,
                     "cannot create the recording folder: " + ec.message()};
    }
    if (auto st = data::writeBatchFile(toBatch(m_batch), m_batch.path); !st) {
        return st;
    }
    m_batch.dirty = false;
    return {};
}

} // namespace drytwin::live
