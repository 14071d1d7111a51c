#pragma once

#include "common/Error.h"
#include "data/Batch.h"
#include "data/Columns.h"
#include "live/TagPayload.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace drytwin::live {

/// @brief How the stream is put on the 1 s grid and written.
struct GridRecorderOptions {
    std::string folder; ///< where the batch files go (made if missing); empty: nothing is written
    /// Seconds of line time a sample may come after newer ones and still be placed: a row is
    /// final once a sample this much newer has arrived. Later samples are counted late, not placed.
    double reorderWindowS = 10;
    /// A stretch without any sample longer than this ends the batch file (a line stop, a broker
    /// down for long): the next sample starts a new one. Shorter gaps are rows of missing cells.
    double splitGapS = 600;
    /// How often (wall clock) the open batch file is rewritten, so that a crash loses little.
    double writeEveryS = 5;
    /// Names a batch when the line sends no batch id: `<prefix>_<UTC start, YYYYmmddTHHMMSS>`.
    std::string unnamedPrefix = "live";
    std::string sourceText;     ///< `# source:` of every file (the broker)
    bool keepFinalRows = false; ///< keep each final row for takeFinalRows() (the live monitor)
    Status validate() const;
};

/// @brief What happened to the messages so far.
struct RecorderCounts {
    long samples = 0;      ///< tag samples placed on the grid (explicit nulls included)
    long duplicates = 0;   ///< a second sample of a tag in one grid second: the first is kept
    long late = 0;         ///< for a row already final (older than the reorder window): not placed
    long malformed = 0;    ///< unreadable payloads: counted, never recorded
    long missingCells = 0; ///< cells of final rows that no message filled (gaps)
    long rows = 0;         ///< final rows written
    long batches = 0;      ///< batch files begun
};

/// @brief A row of the grid as it became final: what the live monitor is fed.
struct FinalRow {
    std::string batch;
    double batchStartS = 0;                          ///< Unix second of the batch's first row
    double timeS = 0;                                ///< since the batch's start
    std::array<double, data::kColumnCount> values{}; ///< by contract column; NaN missing
};

/// @brief Puts tag samples on the 1 s grid of line time (the sender's stamps), one row per second,
/// and records the rows as batch files (CONTRACT.md §1) that `drytwin discover` can open. A new
/// file begins at each new batch id and after a long gap. Not thread-safe: one thread feeds it
/// (the live loop takes the client's messages through a queue).
class GridRecorder {
public:
    explicit GridRecorder(GridRecorderOptions options);
    /// @brief Places one sample of column @p c (not time_s).
    void addSample(data::Column c, const TagSample& sample);
    /// @brief The production run @p id starts at @p timeS: rows from that second go to its file.
    void addBatchStart(const std::string& id, double timeS);
    /// @brief Counts a message that could not be read.
    void addMalformed() { ++m_counts.malformed; }
    /// @brief Makes final the rows older than the reorder window (every row when @p everything),
    /// and writes the batch files that changed when due (always when @p everything).
    Status flush(bool everything = false);
    const RecorderCounts& counts() const { return m_counts; }
    /// @brief The rows made final since the last call (keepFinalRows), in time order, gap rows included.
    std::vector<FinalRow> takeFinalRows();
    /// @brief The files written so far, in the order begun.
    const std::vector<std::string>& files() const { return m_files; }

private:
    static constexpr int kCells = data::kColumnCount;
    struct Row {
        std::int64_t second = 0;
        std::array<double, kCells> values{};
        std::uint32_t present = 0; ///< bit per column: a message filled the cell (a null included)
    };
    struct OpenBatch {
        std::string id;
        std::string path;
        std::int64_t startSecond = 0;
        std::vector<Row> rows;
        std::uint32_t columnsSeen = 0;
        bool dirty = false;
    };

    void finalise(Row row);
    void appendRow(const Row& row);
    void beginBatch(const std::string& id, std::int64_t second);
    Status writeOpenBatch();
    data::Batch toBatch(const OpenBatch& b) const;
    std::string pathFor(const std::string& id) const;

    GridRecorderOptions m_options;
    RecorderCounts m_counts;
    std::map<std::int64_t, Row> m_pending;             ///< rows not yet final, by grid second
    std::map<std::int64_t, std::string> m_batchStarts; ///< batch ids announced, by first second
    bool m_anyFinal = false;
    std::int64_t m_finalBefore = 0; ///< rows before this second are final
    std::int64_t m_newest = 0;
    bool m_anySample = false;
    bool m_open = false;
    OpenBatch m_batch;
    long m_batchMissingCounted = 0; ///< the open batch's missing cells already in m_counts
    std::vector<std::string> m_files;
    std::vector<FinalRow> m_finalRows;
    std::chrono::steady_clock::time_point m_lastWrite;
    Status m_writeError;
};

} // namespace drytwin::live
