#include "TagPayload.h"

#include "data/historian/TimeStamps.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace drytwin::live {

namespace {

/// Reads "t" of @p j into @p timeS (Unix seconds, or ISO 8601 text); absent: arrival time.
bool readStamp(const nlohmann::json& j, double arrivalS, double& timeS, bool& stamped, std::string& problem) {
    stamped = false;
    timeS = arrivalS;
    const auto t = j.find("t");
    if (t == j.end()) {
        return true;
    }
    if (t->is_number()) {
        timeS = t->get<double>();
    } else if (t->is_string()) {
        if (!data::parseTimeCell(t->get<std::string>(), data::TimeFormat::Iso8601, timeS)) {
            problem = "\"t\" is neither Unix seconds nor an ISO 8601 time";
            return false;
        }
    } else {
        problem = "\"t\" is neither Unix seconds nor an ISO 8601 time";
        return false;
    }
    if (!std::isfinite(timeS) || timeS < 0) {
        problem = "\"t\" is not a time";
        return false;
    }
    stamped = true;
    return true;
}

} // namespace

PayloadReading readTagPayload(std::string_view payload, double arrivalS) {
    PayloadReading r;
    // Without exceptions: a malformed message from the network is routine, not exceptional.
    const auto j = nlohmann::json::parse(payload.begin(), payload.end(), nullptr, false);
    if (j.is_discarded()) {
        r.problem = "not a number or JSON";
        return r;
    }
    const nlohmann::json* value = &j;
    if (j.is_object()) {
        const auto v = j.find("v");
        if (v == j.end()) {
            r.problem = "no \"v\"";
            return r;
        }
        value = &*v;
        if (!readStamp(j, arrivalS, r.sample.timeS, r.sample.stamped, r.problem)) {
            return r;
        }
    } else {
        r.sample.timeS = arrivalS;
    }
    if (value->is_null()) {
        r.sample.value = std::numeric_limits<double>::quiet_NaN();
    } else if (value->is_number()) {
        r.sample.value = value->get<double>();
        if (!std::isfinite(r.sample.value)) {
            r.problem = "the value is not finite";
            return r;
        }
    } else {
        r.problem = "the value is not a number";
        return r;
    }
    r.ok = true;
    return r;
}

bool readBatchIdPayload(std::string_view payload, double arrivalS, std::string& batchId, double& timeS,
                        std::string& problem) {
    const auto j = nlohmann::json::parse(payload.begin(), payload.end(), nullptr, false);
    bool stamped = false;
    timeS = arrivalS;
    if (j.is_discarded()) {
        // A bare id is not JSON text: taken as it is, when it is a plain word.
        batchId = std::string(payload);
    } else if (j.is_string()) {
        batchId = j.get<std::string>();
    } else if (j.is_object() && j.contains("v") && j["v"].is_string()) {
        if (!readStamp(j, arrivalS, timeS, stamped, problem)) {
            return false;
        }
        batchId = j["v"].get<std::string>();
    } else {
        problem = "a batch id is text, or {\"t\": …, \"v\": \"<id>\"}";
        return false;
    }
    // The id names a file: nothing that could leave the recording folder or break a line.
    if (batchId.empty() || batchId.size() > 64 ||
        batchId.find_first_of("/\\\n\r\t:*?\"<>|") != std::string::npos || batchId[0] == '.') {
        problem = "the batch id is empty, too long, or holds characters a file name cannot";
        return false;
    }
    return true;
}

std::string formatTagPayload(double timeS, double value) {
    nlohmann::json j;
    j["t"] = timeS;
    j["v"] = std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
    return j.dump();
}

std::string formatTextPayload(double timeS, const std::string& text) {
    nlohmann::json j;
    j["t"] = timeS;
    j["v"] = text;
    return j.dump();
}

} // namespace drytwin::live
