// MqttLink: one connection to an MQTT broker through libmosquitto, driven from the caller's
// poll() loop (no thread of libmosquitto's own: the bridge and messfleet are single-threaded
// loops like every IMESS client). Each connection attempt gets a fresh libmosquitto instance,
// so nothing of a broken session is sent again behind the caller's back: after a break the
// caller decides what to publish again (the bridge: every hit after the acknowledged one).
#pragma once
#include <chrono>
#include <functional>
#include <string>
#include <string_view>

struct mosquitto;
struct mosquitto_message;

namespace imess::mqtt {

struct LinkOptions {
  std::string host = "localhost";
  int port = 1883;
  std::string client_id;            // empty: the library makes one
  std::string user, password;       // password: never logged
  std::string tls_ca;               // TLS when given
  std::string will_topic, will_payload;  // retained last will, QoS 1, when given
  int keepalive_s = 10;
  std::chrono::milliseconds retry_interval{500};
};

struct LinkHandlers {
  std::function<void()> connected;                     // CONNACK accepted: subscribe, publish
  std::function<void(const std::string& why)> lost;    // the connection ended or an attempt failed
  std::function<void(int mid)> acknowledged;           // PUBACK of a QoS 1 message
  std::function<void(std::string_view topic, std::string_view payload, bool retained)> message;
};

class MqttLink {
 public:
  MqttLink(LinkOptions options, LinkHandlers handlers);
  ~MqttLink();
  MqttLink(const MqttLink&) = delete;
  MqttLink& operator=(const MqttLink&) = delete;

  // Call every loop turn: connects when due, handles the socket's traffic (`readable`,
  // `writable`: what poll() said of fd()), keep-alives and retries.
  void service(bool readable, bool writable, std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());
  int fd() const;               // the socket for poll(), -1 while there is none
  bool wants_write() const;     // poll for POLLOUT too
  bool connected() const { return connected_; }
  std::chrono::milliseconds until_due(std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now()) const;

  // The message id (for `acknowledged`), or -1 when not connected or refused.
  int publish(const std::string& topic, std::string_view payload, int qos, bool retain);
  bool subscribe(const std::string& pattern, int qos);
  // Ends the connection cleanly (DISCONNECT: the broker does not send the last will).
  void disconnect();

  const std::string& last_error() const { return last_error_; }

 private:
  static void on_connect(::mosquitto*, void*, int);
  static void on_disconnect(::mosquitto*, void*, int);
  static void on_publish(::mosquitto*, void*, int);
  static void on_message(::mosquitto*, void*, const ::mosquitto_message*);
  void attempt(std::chrono::steady_clock::time_point now);
  void drop(const std::string& why, std::chrono::steady_clock::time_point now);

  LinkOptions options_;
  LinkHandlers handlers_;
  ::mosquitto* mosq_ = nullptr;
  bool connected_ = false;
  bool dropping_ = false;
  std::chrono::steady_clock::time_point next_attempt_{};
  std::string last_error_;
};

}  // namespace imess::mqtt
