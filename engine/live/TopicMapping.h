#pragma once

#include "common/Error.h"
#include "data/Columns.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace drytwin::live {

/// @brief Which MQTT topic carries each contract column (CONTRACT.md §2, the column mapping's idea
/// for a live line): `{"X_out_pct": "plant/line1/NIR_OUT", …, "prefix": "…"}`. A column the file
/// does not name is on `<line prefix>/<contract column>`; without a file every column is there.
struct TopicMapping {
    /// Where the line's unnamed tags are: `<linePrefix>/<contract column>`.
    std::string linePrefix = "drytwin/line1";
    /// Where the twin publishes what it computes (alarms): the file's "prefix", else
    /// `<linePrefix>/twin`.
    std::string twinPrefix;
    /// Topics named by the file, by contract column name.
    std::map<std::string, std::string> columnToTopic;
    /// A topic that names the production run (`"batch_id": "plant/line1/BATCH"`); the recorder
    /// starts a new batch file when it changes. Empty: `<linePrefix>/batch_id`.
    std::string batchTopic;
    /// The file this was read from, for messages ("" when built in code).
    std::string sourceName;

    /// @brief The topic of contract column @p c (never time_s).
    std::string topicOf(data::Column c) const;
    /// @brief The topic of the production run's id.
    std::string batchIdTopic() const;
    /// @brief The twin's prefix (twinPrefix, else `<linePrefix>/twin`).
    std::string twinTopicPrefix() const;
    /// @brief The contract column a topic carries, if any.
    std::optional<data::Column> columnOf(const std::string& topic) const;
    /// @brief Every topic to subscribe to: the twelve measured columns and the run's id.
    std::vector<std::string> subscriptions() const;
    /// @brief Keys must be contract columns (not time_s), "prefix" or "batch_id"; topics must be
    /// non-empty, without MQTT wildcards, and no topic may carry two columns.
    Status validate() const;
};

/// @brief Reads a topic-mapping file; a file that is not JSON or names a wrong key comes back as a
/// BadInput error at file:line:column with the reason.
Expected<TopicMapping> readTopicMapping(const std::string& path);
/// @brief readTopicMapping of JSON text; @p name is used in messages.
Expected<TopicMapping> readTopicMappingText(const std::string& text, const std::string& name);

} // namespace drytwin::live
