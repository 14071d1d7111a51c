#include "MqttClient.h"

#include <mosquitto.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>

namespace drytwin::live {

namespace {

/// libmosquitto wants one init per process before any client; it is cheap and idempotent here.
void initLibraryOnce() {
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
}

/// The library's word for @p rc; for a socket error, the system's (errno), which names the cause
/// ("Connection refused", "Name or service not known").
std::string mosquittoReason(int rc) {
    if (rc == MOSQ_ERR_ERRNO) {
        return std::strerror(errno);
    }
    if (rc == MOSQ_ERR_EAI) {
        return "the host name cannot be resolved";
    }
    return mosquitto_strerror(rc);
}

} // namespace

Status MqttConnectOptions::validate() const {
    if (broker.host.empty()) {
        return invalidOption("--broker", "no broker host");
    }
    if (!password.empty() && user.empty()) {
        return invalidOption("--user", "a password was given without a user name");
    }
    if (keepAliveS < 5) {
        return invalidOption("keep-alive", "must be at least 5 s");
    }
    if (reconnectFirstDelayS < 1 || reconnectMaxDelayS < reconnectFirstDelayS) {
        return invalidOption("reconnect delay",
                             "must be at least 1 s, the largest no smaller than the first");
    }
    if (!caFile.empty() && !broker.tls) {
        return invalidOption("--cafile", "a CA file needs a TLS broker URL (mqtts://)");
    }
    return {};
}

struct MqttClient::Impl {
    mosquitto* handle = nullptr;
    std::string brokerText;
    std::vector<std::string> subscriptions;
    MessageHandler onMessage;
    ConnectionHandler onConnection;

    std::mutex mutex;
    std::condition_variable changed;
    int firstConnack = -1; ///< the first CONNACK's code, -1 before it came
    std::atomic<bool> up{false};
    std::atomic<int> drops{0};
    std::atomic<long> published{0};
    std::atomic<long> acknowledged{0};
    std::size_t firstSubacks = 0; ///< SUBACKs since the first connect, under mutex

    static Impl& of(void* userdata) { return *static_cast<Impl*>(userdata); }

    static void onConnect(mosquitto* m, void* userdata, int rc) {
        Impl& self = of(userdata);
        if (rc == 0) {
            // Subscribed again after every reconnect: a clean session forgets them.
            for (const auto& topic : self.subscriptions) {
                mosquitto_subscribe(m, nullptr, topic.c_str(), 1);
            }
            self.up = true;
        }
        {
            std::lock_guard<std::mutex> lock(self.mutex);
            if (self.firstConnack < 0) {
                self.firstConnack = rc;
            }
        }
        self.changed.notify_all();
        if (self.onConnection) {
            self.onConnection(rc == 0, rc == 0 ? std::string() : mosquitto_connack_string(rc));
        }
    }
    static void onDisconnect(mosquitto*, void* userdata, int rc) {
        Impl& self = of(userdata);
        const bool wasUp = self.up.exchange(false);
        if (rc != 0 && wasUp) { // rc 0: we asked for it
            ++self.drops;
        }
        self.changed.notify_all();
        if (self.onConnection && rc != 0 && wasUp) {
            self.onConnection(false, mosquittoReason(rc));
        }
    }
    static void onSubscribed(mosquitto*, void* userdata, int, int, const int*) {
        Impl& self = of(userdata);
        {
            std::lock_guard<std::mutex> lock(self.mutex);
            ++self.firstSubacks;
        }
        self.changed.notify_all();
    }
    static void onMessageArrived(mosquitto*, void* userdata, const mosquitto_message* message) {
        Impl& self = of(userdata);
        if (self.onMessage && message->topic) {
            self.onMessage(message->topic,
                           std::string_view(
                               static_cast<const char*>(message->payload),
                               message->payloadlen > 0 ? static_cast<std::size_t>(message->payloadlen) : 0));
        }
    }
    static void onPublishAcknowledged(mosquitto*, void* userdata, int) {
        Impl& self = of(userdata);
        {
            // Under the lock, so that a waiter between its check and its sleep cannot miss it.
            std::lock_guard<std::mutex> lock(self.mutex);
            ++self.acknowledged;
        }
        self.changed.notify_all();
    }

    ~Impl() {
        if (handle) {
            mosquitto_disconnect(handle);
            mosquitto_loop_stop(handle, false);
            mosquitto_destroy(handle);
        }
    }
};

MqttClient::MqttClient(std::unique_ptr<Impl> impl) : m_impl(std::move(impl)) {}

MqttClient::~MqttClient() = default;

Expected<std::unique_ptr<MqttClient>> MqttClient::connect(const MqttConnectOptions& options,
                                                          std::vector<std::string> subscriptions,
                                                          MessageHandler onMessage,
                                                          ConnectionHandler onConnection) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    initLibraryOnce();
    auto impl = std::make_unique<Impl>();
    impl->brokerText = options.broker.text();
    impl->subscriptions = std::move(subscriptions);
    impl->onMessage = std::move(onMessage);
    impl->onConnection = std::move(onConnection);
    const std::string place = "broker " + impl->brokerText;
    impl->handle =
        mosquitto_new(options.clientId.empty() ? nullptr : options.clientId.c_str(), true, impl.get());
    if (!impl->handle) {
        return Error{ErrorKind::BadInput, place,
                     "cannot create an MQTT client: " + std::string(std::strerror(errno))};
    }
    mosquitto* m = impl->handle;
    mosquitto_connect_callback_set(m, &Impl::onConnect);
    mosquitto_disconnect_callback_set(m, &Impl::onDisconnect);
    mosquitto_message_callback_set(m, &Impl::onMessageArrived);
    mosquitto_publish_callback_set(m, &Impl::onPublishAcknowledged);
    mosquitto_subscribe_callback_set(m, &Impl::onSubscribed);
    mosquitto_reconnect_delay_set(m, static_cast<unsigned>(options.reconnectFirstDelayS),
                                  static_cast<unsigned>(options.reconnectMaxDelayS), true);
    if (!options.user.empty()) {
        if (int rc = mosquitto_username_pw_set(m, options.user.c_str(),
                                               options.password.empty() ? nullptr : options.password.c_str());
            rc != MOSQ_ERR_SUCCESS) {
            return Error{ErrorKind::BadInput, place, "cannot set the user: " + mosquittoReason(rc)};
        }
    }
    if (options.broker.tls) {
        // Without a CA file the system's certificates are trusted (OpenSSL's default paths).
        const char* caPath = options.caFile.empty() ? "/etc/ssl/certs" : nullptr;
        if (int rc = mosquitto_tls_set(m, options.caFile.empty() ? nullptr : options.caFile.c_str(), caPath,
                                       nullptr, nullptr, nullptr);
            rc != MOSQ_ERR_SUCCESS) {
            return Error{ErrorKind::BadInput, options.caFile.empty() ? place : "--cafile " + options.caFile,
                         "cannot use the CA certificate(s): " + mosquittoReason(rc)};
        }
    }
    if (int rc = mosquitto_connect(m, options.broker.host.c_str(), options.broker.port, options.keepAliveS);
        rc != MOSQ_ERR_SUCCESS) {
        return Error{ErrorKind::BadInput, place,
                     "cannot connect: " + mosquittoReason(rc) +
                         " (is the broker running and listening there?)"};
    }
    if (int rc = mosquitto_loop_start(m); rc != MOSQ_ERR_SUCCESS) {
        return Error{ErrorKind::BadInput, place, "cannot start the network thread: " + mosquittoReason(rc)};
    }
    // The TCP link is up; the broker's CONNACK says whether it takes us (credentials, protocol).
    std::unique_lock<std::mutex> lock(impl->mutex);
    const bool answered = impl->changed.wait_for(lock, std::chrono::duration<double>(options.connectTimeoutS),
                                                 [&] { return impl->firstConnack >= 0; });
    // Back only once the broker has confirmed every subscription: a sender started after this
    // returns loses nothing to a subscription still on its way.
    const bool subscribed =
        impl->firstConnack == 0 &&
        impl->changed.wait_for(lock, std::chrono::duration<double>(options.connectTimeoutS),
                               [&] { return impl->firstSubacks >= impl->subscriptions.size(); });
    const int connack = impl->firstConnack;
    lock.unlock();
    if (!answered) {
        return Error{ErrorKind::BadInput, place,
                     "the broker did not answer the connection within " +
                         std::to_string(static_cast<int>(options.connectTimeoutS)) + " s"};
    }
    if (connack != 0) {
        return Error{ErrorKind::BadInput, place,
                     std::string("the broker refused the connection: ") + mosquitto_connack_string(connack)};
    }
    if (!subscribed) {
        return Error{ErrorKind::BadInput, place, "the broker did not confirm the subscriptions"};
    }
    return std::unique_ptr<MqttClient>(new MqttClient(std::move(impl)));
}

Status MqttClient::publish(const std::string& topic, std::string_view payload) {
    int mid = 0;
    const int rc = mosquitto_publish(m_impl->handle, &mid, topic.c_str(), static_cast<int>(payload.size()),
                                     payload.data(), 1, false);
    // NO_CONN: libmosquitto keeps QoS 1 messages queued while the link is down and sends them
    // after the reconnect.
    if (rc != MOSQ_ERR_SUCCESS && rc != MOSQ_ERR_NO_CONN) {
        return Error{ErrorKind::BadInput, "topic " + topic, "cannot publish: " + mosquittoReason(rc)};
    }
    ++m_impl->published;
    return {};
}

bool MqttClient::waitUntilDelivered(double timeoutS) {
    std::unique_lock<std::mutex> lock(m_impl->mutex);
    return m_impl->changed.wait_for(lock, std::chrono::duration<double>(timeoutS),
                                    [&] { return m_impl->acknowledged.load() >= m_impl->published.load(); });
}

bool MqttClient::connected() const {
    return m_impl->up;
}

int MqttClient::disconnects() const {
    return m_impl->drops;
}

long MqttClient::pendingDeliveries() const {
    return m_impl->published - m_impl->acknowledged;
}

std::string MqttClient::brokerText() const {
    return m_impl->brokerText;
}

} // namespace drytwin::live
