// libmosquitto in a poll() loop (mqtt_link.hpp).
#include "mqtt_link.hpp"

#include <mosquitto.h>

#include <cerrno>
#include <cstring>
#include <mutex>

namespace imess::mqtt {

namespace {

void init_library_once() {
  static std::once_flag once;
  std::call_once(once, [] { mosquitto_lib_init(); });
}

std::string error_text(int rc) {
  if (rc == MOSQ_ERR_ERRNO) return std::strerror(errno);
  return mosquitto_strerror(rc);
}

}  // namespace

MqttLink::MqttLink(LinkOptions options, LinkHandlers handlers)
    : options_(std::move(options)), handlers_(std::move(handlers)) {
  init_library_once();
}

MqttLink::~MqttLink() {
  if (mosq_) mosquitto_destroy(mosq_);
}

int MqttLink::fd() const { return mosq_ ? mosquitto_socket(mosq_) : -1; }
bool MqttLink::wants_write() const { return mosq_ && mosquitto_want_write(mosq_); }

std::chrono::milliseconds MqttLink::until_due(std::chrono::steady_clock::time_point now) const {
  if (mosq_) return std::chrono::milliseconds{250};  // keep-alives and retries of the library
  if (now >= next_attempt_) return std::chrono::milliseconds{0};
  return std::chrono::duration_cast<std::chrono::milliseconds>(next_attempt_ - now) + std::chrono::milliseconds{1};
}

void MqttLink::attempt(std::chrono::steady_clock::time_point now) {
  next_attempt_ = now + options_.retry_interval;
  mosq_ = mosquitto_new(options_.client_id.empty() ? nullptr : options_.client_id.c_str(), true, this);
  if (!mosq_) {
    drop("cannot make a libmosquitto instance: " + std::string(std::strerror(errno)), now);
    return;
  }
  mosquitto_int_option(mosq_, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
  mosquitto_max_inflight_messages_set(mosq_, 100);
  mosquitto_connect_callback_set(mosq_, &MqttLink::on_connect);
  mosquitto_disconnect_callback_set(mosq_, &MqttLink::on_disconnect);
  mosquitto_publish_callback_set(mosq_, &MqttLink::on_publish);
  mosquitto_message_callback_set(mosq_, &MqttLink::on_message);
  int rc = MOSQ_ERR_SUCCESS;
  if (!options_.user.empty()) rc = mosquitto_username_pw_set(mosq_, options_.user.c_str(), options_.password.c_str());
  if (rc == MOSQ_ERR_SUCCESS && !options_.tls_ca.empty())
    rc = mosquitto_tls_set(mosq_, options_.tls_ca.c_str(), nullptr, nullptr, nullptr, nullptr);
  if (rc == MOSQ_ERR_SUCCESS && !options_.will_topic.empty())
    rc = mosquitto_will_set(mosq_, options_.will_topic.c_str(), static_cast<int>(options_.will_payload.size()),
                            options_.will_payload.data(), 1, true);
  if (rc != MOSQ_ERR_SUCCESS) {
    drop("cannot set up the connection: " + error_text(rc), now);
    return;
  }
  rc = mosquitto_connect(mosq_, options_.host.c_str(), options_.port, options_.keepalive_s);
  if (rc != MOSQ_ERR_SUCCESS) drop(error_text(rc), now);
}

void MqttLink::drop(const std::string& why, std::chrono::steady_clock::time_point now) {
  const bool was = connected_;
  connected_ = false;
  if (mosq_) {
    dropping_ = true;
    mosquitto_destroy(mosq_);
    dropping_ = false;
    mosq_ = nullptr;
  }
  next_attempt_ = std::max(next_attempt_, now + (was ? std::chrono::milliseconds{0} : options_.retry_interval));
  const bool news = why != last_error_ || was;
  last_error_ = why;
  if (handlers_.lost && news) handlers_.lost(why);
}

void MqttLink::service(bool readable, bool writable, std::chrono::steady_clock::time_point now) {
  if (!mosq_) {
    if (now >= next_attempt_) attempt(now);
    return;
  }
  int rc = MOSQ_ERR_SUCCESS;
  if (readable) rc = mosquitto_loop_read(mosq_, 1);
  if (rc == MOSQ_ERR_SUCCESS && mosq_ && (writable || mosquitto_want_write(mosq_))) rc = mosquitto_loop_write(mosq_, 1);
  if (rc == MOSQ_ERR_SUCCESS && mosq_) rc = mosquitto_loop_misc(mosq_);
  if (rc != MOSQ_ERR_SUCCESS && mosq_) drop(rc == MOSQ_ERR_CONN_LOST ? "the broker closed the connection" : error_text(rc), now);
}

int MqttLink::publish(const std::string& topic, std::string_view payload, int qos, bool retain) {
  if (!mosq_ || !connected_) return -1;
  int mid = 0;
  const int rc = mosquitto_publish(mosq_, &mid, topic.c_str(), static_cast<int>(payload.size()), payload.data(), qos, retain);
  if (rc != MOSQ_ERR_SUCCESS) {
    if (rc == MOSQ_ERR_NO_CONN || rc == MOSQ_ERR_CONN_LOST || rc == MOSQ_ERR_ERRNO)
      drop("publishing failed: " + error_text(rc), std::chrono::steady_clock::now());
    return -1;
  }
  return mid;
}

bool MqttLink::subscribe(const std::string& pattern, int qos) {
  if (!mosq_ || !connected_) return false;
  return mosquitto_subscribe(mosq_, nullptr, pattern.c_str(), qos) == MOSQ_ERR_SUCCESS;
}

void MqttLink::disconnect() {
  if (!mosq_) return;
  if (connected_) {
    mosquitto_disconnect(mosq_);
    mosquitto_loop_write(mosq_, 1);
  }
  connected_ = false;
  dropping_ = true;
  mosquitto_destroy(mosq_);
  dropping_ = false;
  mosq_ = nullptr;
}

void MqttLink::on_connect(mosquitto*, void* self, int rc) {
  auto* link = static_cast<MqttLink*>(self);
  if (rc != 0) {
    link->last_error_.clear();
    // The CONNACK refused us (bad credentials, not authorised): say so; the drop happens in
    // the loop (the library calls on_disconnect next or the read fails).
    if (link->handlers_.lost) link->handlers_.lost(std::string("the broker refused the connection: ") + mosquitto_connack_string(rc));
    link->last_error_ = mosquitto_connack_string(rc);
    return;
  }
  link->connected_ = true;
  link->last_error_.clear();
  if (link->handlers_.connected) link->handlers_.connected();
}

void MqttLink::on_disconnect(mosquitto*, void*, int) {
  // The loop call that noticed it returns an error next: drop() ends the session there.
}

void MqttLink::on_publish(mosquitto*, void* self, int mid) {
  auto* link = static_cast<MqttLink*>(self);
  if (!link->dropping_ && link->handlers_.acknowledged) link->handlers_.acknowledged(mid);
}

void MqttLink::on_message(mosquitto*, void* self, const mosquitto_message* m) {
  auto* link = static_cast<MqttLink*>(self);
  if (!link->handlers_.message) return;
  link->handlers_.message(m->topic ? std::string_view(m->topic) : std::string_view(),
                          std::string_view(static_cast<const char*>(m->payload), static_cast<std::size_t>(m->payloadlen)),
                          m->retain);
}

}  // namespace imess::mqtt
