// Bridge: messmqtt's loop — one messd, one broker, the hits in between (docs/mqtt.md).
// Single-threaded: poll() on messd's socket and the broker's, nothing else.
#pragma once
#include <chrono>
#include <cstdint>
#include <list>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ack_tracker.hpp"
#include "bridge_config.hpp"
#include "hit_order.hpp"
#include "imess/protocol/messages.hpp"
#include "machine_state.hpp"
#include "messd_side.hpp"
#include "mqtt_link.hpp"
#include "topics.hpp"

namespace imess::mqtt {

class Bridge {
 public:
  // `acked`: from the state file (0: none yet, start at the journal's oldest hit).
  Bridge(BridgeConfig cfg, std::string password, std::uint64_t acked);
  // Until SIGINT/SIGTERM; returns the exit status.
  int run();

 private:
  using Clock = std::chrono::steady_clock;
  struct Collect {  // a broker's replay request being answered
    std::uint64_t from;
    std::string reply_to;
    std::map<std::uint64_t, protocol::HitMsg> hits;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> lost;
  };

  void messd_connected();
  void messd_lost(const std::string& why);
  void messd_line(std::string_view line);
  void messd_replied(const Command& c, std::string_view reply);
  void messd_replay_data(std::string_view line);
  void broker_connected();
  void broker_message(std::string_view topic, std::string_view payload, bool retained);
  void on_hit(const protocol::HitMsg& hit);
  void catch_up_replied(const Command& c, std::string_view reply);
  void request_replied(const Command& c, std::string_view reply);
  void handle_replay_request(std::string_view payload);
  void handle_stop(std::string_view payload);
  void publish_event(nlohmann::json fields);
  void publish_online(bool online);
  void pump(Clock::time_point now);
  void save(bool force);
  void log(const std::string& text) const;

  BridgeConfig cfg_;
  Topics topics_;
  AckTracker tracker_;
  HitOrder order_;
  MachineState state_;
  MqttLink broker_;
  MessdSide messd_;
  std::list<Collect> requests_;
  bool state_dirty_ = true;
  Clock::time_point last_state_{}, last_save_{}, catch_up_not_before_{};
  std::uint64_t saved_acked_ = 0;
  std::uint64_t hits_published_ = 0;
  std::string last_broker_error_;
};

}  // namespace imess::mqtt
