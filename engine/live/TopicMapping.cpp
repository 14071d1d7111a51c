#include "TopicMapping.h"

#include "common/AtomicFile.h"
#include "data/historian/JsonPlaces.h"
#include "data/historian/PlaceInFile.h"

#include <nlohmann/json.hpp>
#include <set>

namespace drytwin::live {

std::string TopicMapping::topicOf(data::Column c) const {
    const std::string name(data::spec(c).name);
    const auto it = columnToTopic.find(name);
    return it != columnToTopic.end() ? it->second : linePrefix + "/" + name;
}

std::string TopicMapping::batchIdTopic() const {
    return batchTopic.empty() ? linePrefix + "/batch_id" : batchTopic;
}

std::string TopicMapping::twinTopicPrefix() const {
    return twinPrefix.empty() ? linePrefix + "/twin" : twinPrefix;
}

std::optional<data::Column> TopicMapping::columnOf(const std::string& topic) const {
    for (const auto& s : data::columnSpecs()) {
        if (s.id != data::Column::Time && topicOf(s.id) == topic) {
            return s.id;
        }
    }
    return std::nullopt;
}

std::vector<std::string> TopicMapping::subscriptions() const {
    std::vector<std::string> topics;
    for (const auto& s : data::columnSpecs()) {
        if (s.id != data::Column::Time) {
            topics.push_back(topicOf(s.id));
        }
    }
    topics.push_back(batchIdTopic());
    return topics;
}

namespace {

/// Why @p topic cannot name one tag, or "".
std::string badTopicReason(const std::string& topic) {
    if (topic.empty()) {
        return "the topic is empty";
    }
    if (topic.find_first_of("+#") != std::string::npos) {
        return "the topic '" + topic + "' holds an MQTT wildcard (+ or #); name one tag's topic";
    }
    return {};
}

} // namespace

Status TopicMapping::validate() const {
    const std::string place = sourceName.empty() ? "topic mapping" : sourceName;
    if (const auto why = badTopicReason(linePrefix); !why.empty()) {
        return Error{ErrorKind::BadInput, place, "line prefix: " + why};
    }
    std::map<std::string, std::string> columnOfTopic;
    auto claim = [&](const std::string& topic, const std::string& what) -> Status {
        if (const auto why = badTopicReason(topic); !why.empty()) {
            return Error{ErrorKind::BadInput, place, what + ": " + why};
        }
        if (auto [it, added] = columnOfTopic.emplace(topic, what); !added) {
            return Error{ErrorKind::BadInput, place,
                         "'" + what + "' and '" + it->second + "' are both on topic '" + topic + "'"};
        }
        return {};
    };
    for (const auto& [column, topic] : columnToTopic) {
        const auto c = data::columnByName(column);
        if (!c || *c == data::Column::Time) {
            return Error{ErrorKind::BadInput, place, "'" + column + "' is not a measured contract column"};
        }
        (void)topic;
    }
    for (const auto& s : data::columnSpecs()) {
        if (s.id != data::Column::Time) {
            if (auto st = claim(topicOf(s.id), std::string(s.name)); !st) {
                return st;
            }
        }
    }
    return claim(batchIdTopic(), "batch_id");
}

Expected<TopicMapping> readTopicMapping(const std::string& path) {
    auto text = readWholeFile(path);
    if (!text) {
        return text.error();
    }
    return readTopicMappingText(*text, path);
}

Expected<TopicMapping> readTopicMappingText(const std::string& text, const std::string& name) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        int line = 0, column = 0;
        data::historian::lineAndColumnAt(text, e.byte == 0 ? 0 : e.byte - 1, line, column);
        std::string what = e.what();
        if (const auto p = what.find("syntax error"); p != std::string::npos) {
            what = what.substr(p);
        }
        return Error{ErrorKind::BadInput, name + ":" + std::to_string(line) + ":" + std::to_string(column),
                     "the topic mapping is not valid JSON: " + what};
    } catch (const nlohmann::json::exception& e) {
        return Error{ErrorKind::BadInput, name,
                     std::string("the topic mapping is not valid JSON: ") + e.what()};
    }
    const data::historian::JsonPlaces places(text);
    auto at = [&](const std::string& key, const std::string& reason) {
        int line = 0, column = 0;
        data::historian::lineAndColumnAt(text, places.keyAt(data::historian::JsonPlaces::child("", key)),
                                         line, column);
        return Error{ErrorKind::BadInput, name + ":" + std::to_string(line) + ":" + std::to_string(column),
                     reason};
    };
    if (!j.is_object()) {
        return Error{ErrorKind::BadInput, name,
                     "a topic mapping is a JSON object {\"<contract column>\": \"<topic>\", …}"};
    }
    TopicMapping mapping;
    mapping.sourceName = name;
    for (const auto& [key, value] : j.items()) {
        if (!value.is_string()) {
            return at(key, "'" + key + "' must be a topic (a string)");
        }
        const std::string topic = value.get<std::string>();
        if (key == "prefix") {
            mapping.twinPrefix = topic;
        } else if (key == "line_prefix") {
            mapping.linePrefix = topic;
        } else if (key == "batch_id") {
            mapping.batchTopic = topic;
        } else {
            const auto c = data::columnByName(key);
            if (!c || *c == data::Column::Time) {
                return at(key, "'" + key +
                                   "' is not a measured contract column (CONTRACT.md §1), \"prefix\", "
                                   "\"line_prefix\" or \"batch_id\"");
            }
            mapping.columnToTopic[key] = topic;
        }
    }
    if (auto st = mapping.validate(); !st) {
        return st.error();
    }
    return mapping;
}

} // namespace drytwin::live
