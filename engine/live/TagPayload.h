#pragma once

#include <string>
#include <string_view>

namespace drytwin::live {

/// @brief One tag's sample as a message carries it (CONTRACT.md §2): a bare number, stamped on
/// arrival, or `{"t": <Unix seconds or ISO 8601>, "v": <number or null>}`. A null value is a
/// sample the line itself reports missing (a sensor dropout): recorded as a missing cell.
struct TagSample {
    double timeS = 0;     ///< Unix seconds
    bool stamped = false; ///< the sender gave the time ("t"); else arrival time
    double value = 0;     ///< NaN: the sender says the value is missing
};

/// @brief What reading a payload gave: a sample, or why the message is malformed.
struct PayloadReading {
    bool ok = false;
    TagSample sample;
    std::string problem; ///< set when !ok: what is wrong, in a few words
};

/// @brief Reads a numeric tag's payload; @p arrivalS stamps a bare number. Never throws: anything
/// unexpected (not JSON, no "v", text where a number belongs, an unreadable "t") is a problem.
PayloadReading readTagPayload(std::string_view payload, double arrivalS);

/// @brief The production run's id from a batch-id payload: `{"t": …, "v": "B07"}` or a bare
/// string; false with @p problem set when it is neither.
bool readBatchIdPayload(std::string_view payload, double arrivalS, std::string& batchId, double& timeS,
                        std::string& problem);

/// @brief `{"t":<timeS>,"v":<value>}`, the value in its shortest exact decimal form (reading it
/// back gives the same double), null for NaN.
std::string formatTagPayload(double timeS, double value);
/// @brief `{"t":<timeS>,"v":"<text>"}` (a batch id).
std::string formatTextPayload(double timeS, const std::string& text);

} // namespace drytwin::live
