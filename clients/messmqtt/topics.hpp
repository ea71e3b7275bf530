// The topics of one machine on the broker: imess/<machine>/state, hit, event, online, replay,
// replay/<reply_to>, cmd/stop (docs/mqtt.md). A machine name and a reply_to are one topic level
// of letters, digits, '-' and '_', never MQTT's wildcards or separators.
#pragma once
#include <string>
#include <string_view>

namespace imess::mqtt {

inline constexpr std::size_t kMaxNameLength = 64;

// Empty when `name` can be a topic level; else what is wrong and what is accepted.
std::string name_problem(std::string_view name);

struct Topics {
  explicit Topics(const std::string& machine);
  std::string state, hit, event, online, replay, stop;
  std::string replay_answer(std::string_view reply_to) const { return replay + "/" + std::string(reply_to); }
};

// The machine of a topic "imess/<machine>/<what>" and its <what> ("state", "cmd/stop" ...);
// false when the topic is not of that form.
bool split_topic(std::string_view topic, std::string& machine, std::string& what);

}  // namespace imess::mqtt
