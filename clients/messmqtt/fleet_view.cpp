// messfleet's table (fleet_view.hpp).
#include "fleet_view.hpp"

#include <cstdio>

#include "imess/jsontext/strict_json.hpp"
#include "topics.hpp"

namespace imess::mqtt {

namespace {

// What a terminal may be sent of a text from the broker: no control characters (an escape
// sequence would rewrite the screen), at most 40 characters.
std::string shown(std::string s) {
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  for (auto& c : s)
    if (static_cast<unsigned char>(c) < 32 || c == 127) c = '?';
  return s;
}

std::string cell(const nlohmann::json& j) {
  if (j.is_null()) return "-";
  if (j.is_string()) return shown(j.get<std::string>());
  return shown(j.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace));
}

// Fields read without trusting their type: anyone can publish anything on a broker.
const nlohmann::json& field(const nlohmann::json& j, const char* key) {
  static const nlohmann::json none;
  if (!j.is_object()) return none;
  const auto it = j.find(key);
  return it == j.end() ? none : *it;
}
bool flag(const nlohmann::json& j, const char* key) {
  const auto& v = field(j, key);
  return v.is_boolean() && v.get<bool>();
}
std::uint64_t seq_of(const nlohmann::json& j) {
  const auto& v = field(j, "seq");
  return v.is_number_unsigned() ? v.get<std::uint64_t>() : 0;
}
std::string text(const nlohmann::json& j, const char* key, const std::string& def = "") {
  const auto& v = field(j, key);
  return v.is_string() ? v.get<std::string>() : def;
}

std::string fixed3(const nlohmann::json& v) {
  if (!v.is_number()) return "?";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v.get<double>());
  return buf;
}

}  // namespace

bool FleetView::fold(std::string_view topic, std::string_view payload) {
  std::string machine, what;
  if (!split_topic(topic, machine, what) || !name_problem(machine).empty()) return false;
  nlohmann::json j;
  try {
    j = jsontext::parse_strict(payload, topic);
  } catch (const jsontext::JsonTextError&) {
    ++ignored_;
    return false;
  }
  if (!j.is_object()) {
    ++ignored_;
    return false;
  }
  auto& m = machines_[machine];
  if (what == "state") {
    m.state = j;
    const auto& hit = field(j, "last_hit");
    if (hit.is_object() && (!m.last_hit.is_object() || seq_of(hit) >= seq_of(m.last_hit))) m.last_hit = hit;
  } else if (what == "online") {
    m.online = j;
  } else if (what == "hit") {
    if (!m.last_hit.is_object() || seq_of(j) >= seq_of(m.last_hit)) m.last_hit = j;
  } else if (what == "event") {
    m.last_event = j;
    if (text(j, "type") == "inspection") m.last_inspection = j;
  } else {
    return false;  // replay answers, commands: not the view's
  }
  return true;
}

nlohmann::json FleetView::to_json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [name, m] : machines_)
    list.push_back({{"machine", name},
                    {"online", flag(m.online, "online")},
                    {"messd", flag(m.online, "messd")},
                    {"state", m.state},
                    {"last_hit", m.last_hit},
                    {"last_inspection", m.last_inspection},
                    {"last_event", m.last_event}});
  return {{"machines", list}, {"ignored", ignored_}};
}

std::string FleetView::table() const {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "%-12s %-8s %-9s %-24s %-26s %-22s %-20s %s\n", "MACHINE", "ONLINE", "STATE", "CONTROL",
                "POSITION", "PROGRAM", "LAST HIT", "LAST INSPECTION");
  out += line;
  for (const auto& [name, m] : machines_) {
    std::string online = "?";
    if (m.online.is_object())
      online = !flag(m.online, "online") ? "offline" : flag(m.online, "messd") ? "yes" : "no messd";
    std::string state = "-", control = "-", position = "-", program = "-";
    if (m.state.is_object()) {
      state = cell(field(m.state, "state"));
      control = cell(field(m.state, "control"));
      const auto& p = field(m.state, "position");
      if (p.is_array() && p.size() == 3) position = fixed3(p[0]) + " " + fixed3(p[1]) + " " + fixed3(p[2]);
      const auto& pr = field(m.state, "program");
      if (pr.is_object() && text(pr, "name", "none") != "none")
        program = shown(text(pr, "name") + " " + text(pr, "state") + " " + text(pr, "block"));
    }
    std::string hit = "-";
    if (m.last_hit.is_object())
      hit = "#" + std::to_string(seq_of(m.last_hit)) + " " + fixed3(field(m.last_hit, "x")) + " " +
            fixed3(field(m.last_hit, "y")) + " " + fixed3(field(m.last_hit, "z"));
    std::string insp = "-";
    if (m.last_inspection.is_object())
      insp = cell(field(m.last_inspection, "plan")) + " " + cell(field(m.last_inspection, "result"));
    std::snprintf(line, sizeof line, "%-12s %-8s %-9s %-24s %-26s %-22s %-20s %s\n", shown(name).c_str(), online.c_str(),
                  state.c_str(), control.c_str(), position.c_str(), program.c_str(), hit.c_str(), insp.c_str());
    out += line;
  }
  if (machines_.empty()) out += "(no machine on the broker yet)\n";
  return out;
}

}  // namespace imess::mqtt
