// Topic names of docs/mqtt.md.
#include "topics.hpp"

namespace imess::mqtt {

std::string name_problem(std::string_view name) {
  if (name.empty() || name.size() > kMaxNameLength)
    return "a name of 1 to " + std::to_string(kMaxNameLength) + " characters, got " + std::to_string(name.size());
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    if (!ok) return "letters, digits, '-' and '_' only (one topic level, no '/', '+' or '#')";
  }
  return {};
}

Topics::Topics(const std::string& machine) {
  const std::string base = "imess/" + machine + "/";
  state = base + "state";
  hit = base + "hit";
  event = base + "event";
  online = base + "online";
  replay = base + "replay";
  stop = base + "cmd/stop";
}

bool split_topic(std::string_view topic, std::string& machine, std::string& what) {
  constexpr std::string_view prefix = "imess/";
  if (topic.substr(0, prefix.size()) != prefix) return false;
  topic.remove_prefix(prefix.size());
  const auto slash = topic.find('/');
  if (slash == std::string_view::npos || slash == 0) return false;
  machine = std::string(topic.substr(0, slash));
  what = std::string(topic.substr(slash + 1));
  return !what.empty();
}

}  // namespace imess::mqtt
