// messfleet's table (fleet_view.hpp).
#include "fleet_view.hpp"

#include <cstdio>

#include "imess/jsontext/strict_json.hpp"
#include "topics.hpp"

namespace imess::mqtt {

namespace {

std::string cell(const nlohmann::json& j) {
  if (j.is_null()) return "-";
  if (j.is_string()) return j.get<std::string>();
  return j.dump();
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
    if (j.contains("last_hit") && j["last_hit"].is_object() &&
        (!m.last_hit.is_object() || j["last_hit"].value("seq", 0ULL) >= m.last_hit.value("seq", 0ULL)))
      m.last_hit = j["last_hit"];
  } else if (what == "online") {
    m.online = j;
  } else if (what == "hit") {
    if (!m.last_hit.is_object() || j.value("seq", 0ULL) >= m.last_hit.value("seq", 0ULL)) m.last_hit = j;
  } else if (what == "event") {
    m.last_event = j;
    if (j.value("type", "") == "inspection") m.last_inspection = j;
  } else {
    return false;  // replay answers, commands: not the view's
  }
  return true;
}

nlohmann::json FleetView::to_json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [name, m] : machines_)
    list.push_back({{"machine", name},
                    {"online", m.online.is_object() ? m.online.value("online", false) : false},
                    {"messd", m.online.is_object() ? m.online.value("messd", false) : false},
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
      online = !m.online.value("online", false) ? "offline" : m.online.value("messd", false) ? "yes" : "no messd";
    std::string state = "-", control = "-", position = "-", program = "-";
    if (m.state.is_object()) {
      state = cell(m.state.value("state", nlohmann::json(nullptr)));
      control = cell(m.state.value("control", nlohmann::json(nullptr)));
      const auto& p = m.state.value("position", nlohmann::json(nullptr));
      if (p.is_array() && p.size() == 3) position = fixed3(p[0]) + " " + fixed3(p[1]) + " " + fixed3(p[2]);
      const auto& pr = m.state.value("program", nlohmann::json(nullptr));
      if (pr.is_object() && pr.value("name", "none") != "none")
        program = pr.value("name", "") + " " + pr.value("state", "") + " " + pr.value("block", "");
    }
    std::string hit = "-";
    if (m.last_hit.is_object())
      hit = "#" + std::to_string(m.last_hit.value("seq", 0ULL)) + " " + fixed3(m.last_hit.value("x", nlohmann::json(nullptr))) +
            " " + fixed3(m.last_hit.value("y", nlohmann::json(nullptr))) + " " + fixed3(m.last_hit.value("z", nlohmann::json(nullptr)));
    std::string insp = "-";
    if (m.last_inspection.is_object())
      insp = cell(m.last_inspection.value("plan", nlohmann::json(nullptr))) + " " +
             cell(m.last_inspection.value("result", nlohmann::json(nullptr)));
    std::snprintf(line, sizeof line, "%-12s %-8s %-9s %-24s %-26s %-22s %-20s %s\n", name.c_str(), online.c_str(),
                  state.c_str(), control.c_str(), position.c_str(), program.c_str(), hit.c_str(), insp.c_str());
    out += line;
  }
  if (machines_.empty()) out += "(no machine on the broker yet)\n";
  return out;
}

}  // namespace imess::mqtt
