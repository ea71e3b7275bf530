// JSON payloads (payloads.hpp).
#include "payloads.hpp"

#include <ctime>

namespace imess::mqtt {

std::string iso_utc(std::chrono::system_clock::time_point t) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(t.time_since_epoch()).count();
  const std::time_t secs = static_cast<std::time_t>(ms / 1000);
  std::tm tm{};
  gmtime_r(&secs, &tm);
  char buf[96];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday,
                tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms % 1000));
  return buf;
}

std::string hit_payload(const std::string& machine, const protocol::HitMsg& h) {
  return nlohmann::json{{"machine", machine}, {"seq", h.seq}, {"id", h.id},       {"x", h.p.x},
                        {"y", h.p.y},         {"z", h.p.z},   {"i", h.dir.x},     {"j", h.dir.y},
                        {"k", h.dir.z},       {"r", h.radius}, {"t", h.time}}
      .dump();
}

std::string state_payload(const std::string& machine, const MachineState& s, const std::string& now) {
  nlohmann::json j{{"machine", machine}, {"time", now}, {"messd", s.messd}, {"state", s.state}, {"control", s.control}};
  j["position"] = s.position ? nlohmann::json(*s.position) : nlohmann::json(nullptr);
  j["program"] = {{"name", s.program.name},
                  {"state", s.program.state},
                  {"line", s.program.line},
                  {"block", s.program.block},
                  {"result", s.program.result}};
  j["last_fault"] = s.last_fault ? nlohmann::json{{"name", s.last_fault->name},
                                                  {"text", s.last_fault->text},
                                                  {"time", s.last_fault->time}}
                                 : nlohmann::json(nullptr);
  j["last_hit"] = s.last_hit ? nlohmann::json{{"seq", s.last_hit->seq},
                                              {"x", s.last_hit->p[0]},
                                              {"y", s.last_hit->p[1]},
                                              {"z", s.last_hit->p[2]},
                                              {"time", s.last_hit->time}}
                             : nlohmann::json(nullptr);
  return j.dump();
}

std::string online_payload(const std::string& machine, bool online, bool messd, const std::string& now) {
  nlohmann::json j{{"machine", machine}, {"online", online}};
  if (online) j["messd"] = messd;
  if (!now.empty()) j["time"] = now;
  return j.dump();
}

std::string event_payload(const std::string& machine, nlohmann::json fields, const std::string& now) {
  fields["machine"] = machine;
  fields["time"] = now;
  return fields.dump();
}

}  // namespace imess::mqtt
