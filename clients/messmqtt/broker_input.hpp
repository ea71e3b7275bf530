// What the bridge accepts from the broker, read strictly: a replay request on
// imess/<machine>/replay and a stop on imess/<machine>/cmd/stop (docs/mqtt.md). Anyone on the
// broker can publish there, so every payload is untrusted: a refusal says what was wrong and
// what is accepted, and nothing in a payload ever becomes a messd command but `Replay <from>`
// (read-only) and `StopMv`.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

namespace imess::mqtt {

inline constexpr std::size_t kMaxPayloadBytes = 4096;   // larger requests are refused unread
inline constexpr std::size_t kMaxReasonLength = 200;

// {"from": 12, "reply_to": "fleet-1"}: the hits from seq 12 on (at most 1000), published to
// imess/<machine>/replay/fleet-1.
struct ReplayRequest {
  std::uint64_t from = 1;
  std::string reply_to;
};
// {} or an empty payload, or {"reason": "...", "by": "..."}: both optional, printable text.
struct StopRequest {
  std::string reason, by;
};

struct Refusal {
  std::string text;  // "replay request: 'from' must be a whole number from 1 to 9007199254740991, got -3"
};

std::variant<ReplayRequest, Refusal> parse_replay_request(std::string_view payload);
std::variant<StopRequest, Refusal> parse_stop_request(std::string_view payload);

}  // namespace imess::mqtt
