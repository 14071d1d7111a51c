#include "BrokerUrl.h"

#include <charconv>

namespace drytwin::live {

std::string BrokerUrl::text() const {
    const bool ipv6 = host.find(':') != std::string::npos;
    return std::string(tls ? "mqtts://" : "mqtt://") + (ipv6 ? "[" + host + "]" : host) + ":" +
           std::to_string(port);
}

Expected<BrokerUrl> parseBrokerUrl(const std::string& url, const std::string& option) {
    const std::string place = option + " " + url;
    BrokerUrl broker;
    std::string rest;
    if (url.rfind("mqtt://", 0) == 0) {
        rest = url.substr(7);
    } else if (url.rfind("mqtts://", 0) == 0) {
        rest = url.substr(8);
        broker.tls = true;
        broker.port = 8883;
    } else {
        return invalidOption(place,
                             "a broker URL begins with mqtt:// or mqtts:// (e.g. mqtt://127.0.0.1:1883)");
    }
    if (!rest.empty() && rest.back() == '/') {
        rest.pop_back();
    }
    if (rest.find('/') != std::string::npos || rest.find('@') != std::string::npos) {
        // A path or user@ in the URL would be silently ignored; user and password have their options.
        return invalidOption(place, "the URL holds only host and port; give the user with --user and the "
                                    "password with --password-file or DRYTWIN_MQTT_PASSWORD");
    }
    std::string portText;
    if (!rest.empty() && rest.front() == '[') { // [::1]:1883
        const auto close = rest.find(']');
        if (close == std::string::npos) {
            return invalidOption(place, "an IPv6 address in [ ] lacks its ']'");
        }
        broker.host = rest.substr(1, close - 1);
        if (close + 1 < rest.size()) {
            if (rest[close + 1] != ':') {
                return invalidOption(place, "expected ':' and a port after ']'");
            }
            portText = rest.substr(close + 2);
        }
    } else {
        const auto colon = rest.rfind(':');
        broker.host = rest.substr(0, colon);
        if (colon != std::string::npos) {
            portText = rest.substr(colon + 1);
        }
        if (colon != std::string::npos && portText.empty()) {
            return invalidOption(place, "no port after ':'");
        }
    }
    if (broker.host.empty()) {
        return invalidOption(place, "no host name (e.g. mqtt://127.0.0.1:1883)");
    }
    if (!portText.empty()) {
        int port = 0;
        const auto [end, ec] = std::from_chars(portText.data(), portText.data() + portText.size(), port);
        if (ec != std::errc() || end != portText.data() + portText.size() || port < 1 || port > 65535) {
            return invalidOption(place, "the port '" + portText + "' is not a number from 1 to 65535");
        }
        broker.port = port;
    }
    return broker;
}

} // namespace drytwin::live
