#pragma once

#include "common/Error.h"
#include "live/BrokerUrl.h"

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::live {

/// @brief How to reach and log in to a broker. The password is given here by the caller, who read
/// it from a file or the environment: never from a command line or a project (issue #73).
struct MqttConnectOptions {
    BrokerUrl broker;
    std::string clientId; ///< empty: the library makes one up
    std::string user;     ///< empty: anonymous
    std::string password; ///< only with a user
    std::string caFile;   ///< TLS: the CA certificate(s) the broker's certificate is checked against
    int keepAliveS = 30;  ///< the broker drops a client silent for 1.5 x this
    double connectTimeoutS = 10;
    /// Reconnect back-off after a drop: doubles from the first delay up to the last (libmosquitto's
    /// exponential back-off), so that a restarting broker is not hammered.
    int reconnectFirstDelayS = 1;
    int reconnectMaxDelayS = 30;
    Status validate() const;
};

/// @brief One MQTT connection (libmosquitto's C client, a PRIVATE dependency of the engine) with
/// its network thread; reconnects with back-off on its own and subscribes again after each
/// reconnect. RAII: the destructor disconnects and joins the thread.
///
/// Thread-safety: publish() may be called from any thread. The handlers run on the client's
/// network thread, one at a time; they must not call back into the client's connect or destructor.
class MqttClient {
public:
    using MessageHandler = std::function<void(const std::string& topic, std::string_view payload)>;
    /// connected, and the library's reason text when not.
    using ConnectionHandler = std::function<void(bool connected, const std::string& reason)>;

    /// @brief Connects (waiting for the broker's answer up to connectTimeoutS) and starts the
    /// network thread. A refused or unreachable broker, or refused credentials, come back as a
    /// BadInput error naming the broker and the cause. The handlers are set before the first
    /// message can arrive; @p subscriptions are subscribed at QoS 1 after every (re)connect.
    static Expected<std::unique_ptr<MqttClient>> connect(const MqttConnectOptions& options,
                                                         std::vector<std::string> subscriptions = {},
                                                         MessageHandler onMessage = {},
                                                         ConnectionHandler onConnection = {});
    ~MqttClient();
    MqttClient(const MqttClient&) = delete;
    MqttClient& operator=(const MqttClient&) = delete;

    /// @brief Queues a message at QoS 1 (at least once: the broker acknowledges it). Fails only
    /// when the client cannot queue it (out of memory, topic not valid UTF-8, payload too large);
    /// while the link is down messages wait in the queue and go out after the reconnect.
    Status publish(const std::string& topic, std::string_view payload);
    /// @brief Waits until the broker has acknowledged every message published so far, or
    /// @p timeoutS passed; false on the time-out.
    bool waitUntilDelivered(double timeoutS);
    /// @brief Whether the link is up now.
    bool connected() const;
    /// @brief How often the link went down since connect().
    int disconnects() const;
    /// @brief Messages queued by publish() and not yet acknowledged.
    long pendingDeliveries() const;
    /// @brief The broker's URL, for messages.
    std::string brokerText() const;

    struct Impl;

private:
    explicit MqttClient(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

} // namespace drytwin::live
