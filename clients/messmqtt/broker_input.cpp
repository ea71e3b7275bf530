// Strict reading of the broker's requests (docs/mqtt.md, "Requests").
#include "broker_input.hpp"

#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"
#include "topics.hpp"

namespace imess::mqtt {

namespace {

constexpr std::uint64_t kMaxSeq = 9007199254740991ULL;  // 2^53 - 1: exact in every JSON reader

// The payload as a JSON object, or the refusal naming `what`.
std::variant<nlohmann::json, Refusal> read_object(std::string_view payload, const std::string& what, bool empty_ok) {
  if (payload.size() > kMaxPayloadBytes)
    return Refusal{what + ": payload of " + std::to_string(payload.size()) + " bytes; accepted: at most " +
                   std::to_string(kMaxPayloadBytes)};
  if (empty_ok && payload.find_first_not_of(" \t\r\n") == std::string_view::npos) return nlohmann::json::object();
  jsontext::Options options;
  options.max_depth = 4;
  options.depth_hint = "a request is one flat object";
  nlohmann::json j;
  try {
    j = jsontext::parse_strict(payload, what, options);
  } catch (const jsontext::JsonTextError& e) {
    return Refusal{e.what()};
  }
  if (!j.is_object()) return Refusal{what + ": a JSON object { ... } is accepted, got " + std::string(j.type_name())};
  return j;
}

std::string keys_problem(const nlohmann::json& j, std::initializer_list<std::string_view> accepted, const std::string& what) {
  for (const auto& [key, value] : j.items()) {
    bool known = false;
    for (auto a : accepted) known = known || key == a;
    if (known) continue;
    std::string list;
    for (auto a : accepted) list += (list.empty() ? "" : ", ") + std::string(a);
    std::string shown = key.size() > 40 ? key.substr(0, 40) + "..." : key;
    for (auto& c : shown)
      if (c < 32 || c > 126) c = '?';
    return what + ": unknown key '" + shown + "'; accepted: " + list;
  }
  return {};
}

// A printable ASCII text of at most kMaxReasonLength, or the problem.
std::string text_problem(const nlohmann::json& j, const char* key, std::string& out, const std::string& what) {
  if (!j.contains(key)) return {};
  const auto& v = j.at(key);
  if (!v.is_string()) return what + ": '" + key + "' must be a text, got " + v.type_name();
  const auto& s = v.get_ref<const std::string&>();
  if (s.size() > kMaxReasonLength)
    return what + ": '" + key + "' has " + std::to_string(s.size()) + " characters; accepted: at most " +
           std::to_string(kMaxReasonLength);
  for (unsigned char c : s)
    if (c < 32 || c > 126) return what + ": '" + key + "' holds a control or non-ASCII character; accepted: printable ASCII";
  out = s;
  return {};
}

}  // namespace

std::variant<ReplayRequest, Refusal> parse_replay_request(std::string_view payload) {
  const std::string what = "replay request";
  auto r = read_object(payload, what, false);
  if (auto* refusal = std::get_if<Refusal>(&r)) return *refusal;
  const auto& j = std::get<nlohmann::json>(r);
  if (auto p = keys_problem(j, {"from", "reply_to"}, what); !p.empty()) return Refusal{p};
  ReplayRequest req;
  if (!j.contains("from")) return Refusal{what + ": 'from' is missing; accepted: {\"from\": <seq>, \"reply_to\": \"<name>\"}"};
  const auto& from = j.at("from");
  const bool whole = from.is_number_unsigned() || (from.is_number_integer() && from.get<std::int64_t>() >= 0);
  if (!whole || from.get<std::uint64_t>() < 1 || from.get<std::uint64_t>() > kMaxSeq)
    return Refusal{what + ": 'from' must be a whole number from 1 to " + std::to_string(kMaxSeq) + ", got " +
                   from.dump().substr(0, 40)};
  req.from = from.get<std::uint64_t>();
  if (!j.contains("reply_to") || !j.at("reply_to").is_string())
    return Refusal{what + ": 'reply_to' must be a text naming the answer's topic level (imess/<machine>/replay/<reply_to>)"};
  req.reply_to = j.at("reply_to").get<std::string>();
  if (auto p = name_problem(req.reply_to); !p.empty()) return Refusal{what + ": 'reply_to': " + p};
  return req;
}

std::variant<StopRequest, Refusal> parse_stop_request(std::string_view payload) {
  const std::string what = "stop request";
  auto r = read_object(payload, what, true);
  if (auto* refusal = std::get_if<Refusal>(&r)) return *refusal;
  const auto& j = std::get<nlohmann::json>(r);
  if (auto p = keys_problem(j, {"reason", "by"}, what); !p.empty()) return Refusal{p};
  StopRequest req;
  if (auto p = text_problem(j, "reason", req.reason, what); !p.empty()) return Refusal{p};
  if (auto p = text_problem(j, "by", req.by, what); !p.empty()) return Refusal{p};
  return req;
}

}  // namespace imess::mqtt
