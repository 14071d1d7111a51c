#pragma once

#include "common/Error.h"

#include <string>

namespace drytwin::live {

/// @brief Where an MQTT broker listens, from `mqtt://host:port` (plain) or `mqtts://host:port`
/// (TLS); the port defaults to 1883 and 8883 as MQTT's registered ports.
struct BrokerUrl {
    std::string host;
    int port = 1883;
    bool tls = false;
    /// @brief "mqtt://host:port" again, for messages.
    std::string text() const;
};

/// @brief Parses @p url; a malformed one comes back as a Usage error naming @p option and what
/// is wrong with it (scheme, host, port).
Expected<BrokerUrl> parseBrokerUrl(const std::string& url, const std::string& option);

} // namespace drytwin::live
