// messmon output formats. JSON keys keep their order (t, line, type, fields) for readability;
// bytes that are not UTF-8 are replaced, so every output line stays valid JSON.
#include "monitor_line.hpp"

#include <nlohmann/json.hpp>
#include <type_traits>

#include "imess/protocol/messages.hpp"

namespace imess::messmon {
namespace {

using Json = nlohmann::ordered_json;
namespace p = protocol;

constexpr const char* kTypeNames[] = {"CurrCor", "MeasPt", "State", "Limit", "Warn", "Fault",
                                      "Homed",   "Ok",     "Err",   "Data",  "Other", "Hit"};
static_assert(std::size(kTypeNames) == std::variant_size_v<p::Message>,
              "one name per protocol::Message alternative");

void add_fields(Json& j, const p::Message& message) {
  std::visit(
      [&](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, p::CurrCorMsg> || std::is_same_v<T, p::MeasPtMsg>) {
          j["x"] = m.p.x;
          j["y"] = m.p.y;
          j["z"] = m.p.z;
        } else if constexpr (std::is_same_v<T, p::StateMsg>) {
          j["state"] = m.state;
        } else if constexpr (std::is_same_v<T, p::LimitMsg>) {
          j["axis"] = m.axis;
          j["side"] = m.side;
        } else if constexpr (std::is_same_v<T, p::WarnMsg> || std::is_same_v<T, p::FaultMsg>) {
          j["name"] = m.name;
          j["text"] = m.text;
        } else if constexpr (std::is_same_v<T, p::OkMsg>) {
          j["verb"] = m.verb;
          j["args"] = m.args;
        } else if constexpr (std::is_same_v<T, p::ErrMsg>) {
          j["code"] = m.code;
          j["text"] = m.text;
        } else if constexpr (std::is_same_v<T, p::DataMsg>) {
          j["verb"] = m.verb;
          j["text"] = m.text;
        } else if constexpr (std::is_same_v<T, p::HitMsg>) {
          j["seq"] = m.seq;
          j["id"] = m.id;
          j["x"] = m.p.x;
          j["y"] = m.p.y;
          j["z"] = m.p.z;
          j["i"] = m.dir.x;
          j["j"] = m.dir.y;
          j["k"] = m.dir.z;
          j["r"] = m.radius;
          j["time"] = m.time;
        }
      },
      message);
}

}  // namespace

std::string text_line(std::string_view time, std::string_view line) {
  return std::string(time) + " " + std::string(line);
}

std::string message_type(std::string_view line) { return kTypeNames[p::parse_message(line).index()]; }

std::string json_line(std::string_view time, std::string_view line) {
  auto message = p::parse_message(line);
  Json j;
  j["t"] = time;
  j["line"] = line;
  j["type"] = kTypeNames[message.index()];
  add_fields(j, message);
  return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace imess::messmon
