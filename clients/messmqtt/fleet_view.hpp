// FleetView: every machine on the broker as messfleet shows it, folded from the messages of
// imess/+/state, online, hit and event (docs/mqtt.md): state, control, position, program,
// last hit, last inspection result, online. Messages that are not of the bridge's form are
// counted and otherwise ignored: anyone can publish on a broker.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace imess::mqtt {

class FleetView {
 public:
  // True when the view changed.
  bool fold(std::string_view topic, std::string_view payload);
  // {"machines": [{"machine": ..., "online": ..., "state": {...}, "last_hit": {...},
  //  "last_inspection": {...}, "last_event": {...}}, ...], "ignored": n}
  nlohmann::json to_json() const;
  // The terminal table, one line per machine.
  std::string table() const;
  std::size_t machines() const { return machines_.size(); }

 private:
  struct Machine {
    nlohmann::json online = nullptr, state = nullptr, last_hit = nullptr, last_inspection = nullptr, last_event = nullptr;
  };
  std::map<std::string, Machine> machines_;
  std::uint64_t ignored_ = 0;
};

}  // namespace imess::mqtt
