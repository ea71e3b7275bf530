// Daemon -> client lines. Replies start with `Ok` or `Err`; every other verb is an unsolicited
// event (CurrCor, Hit, MeasPt, State, Limit, Warn, Fault, Homed). Formatting for the daemon,
// parsing for the clients.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "imess/protocol/commands.hpp"
#include "imess/protocol/error_code.hpp"

namespace imess::protocol {

// A journaled hit: `Hit seq id x y z i j k r t`. The ball centre was p - radius * dir; a ForcePt
// point has dir 0 0 0 and radius 0. time: seconds on the daemon's monotonic clock.
// A scanning point is journaled and numbered like a hit, with the same words under the verb
// `Scan` (`scan` true): dir is then the measured direction from the ball centre toward the
// surface (minus the surface's outward normal), id the scan's.
struct HitMsg {
  std::uint64_t seq = 0;  // the journal's sequence number (gap-free, survives restarts)
  std::uint64_t id = 0;   // the Probe that took it; 0 = none (hand and jog hits)
  Xyz p;                  // surface point, mm
  Xyz dir;                // unit approach direction
  double radius = 0;      // tip radius applied, mm
  double time = 0;        // trigger time, s
  bool scan = false;      // a scanning point: the line's verb is `Scan`, not `Hit` (same words)
  friend bool operator==(const HitMsg&, const HitMsg&) = default;
};

// ---- formatting (daemon side); every line ends in "\n" ----
std::string format_xyz(std::string_view verb, const Xyz& p);  // "CurrCor 1.000 2.000 3.000\n"
inline std::string format_curr_cor(const Xyz& p) { return format_xyz("CurrCor", p); }
inline std::string format_meas_pt(const Xyz& p) { return format_xyz("MeasPt", p); }
std::string format_ok(std::string_view verb, std::string_view data = {});
std::string format_err(ErrorCode code, std::string_view text);
std::string format_event(std::string_view verb, std::string_view text);  // "State idle\n", "Warn TipNotFree ...\n"
// "Hit 17 0 430.0000 330.0000 80.0000 0.000000 0.000000 -1.000000 2.0000 1234.567890\n":
// point and radius with 4 decimals (0.1 um), direction with 6, time with 6 (1 us); a scanning
// point "Scan 18 5 …" in the same words.
std::string format_hit(const HitMsg& hit);
// A data line of Replay's reply, in the place of journaled hits first … last whose records
// cannot be read back (damaged, missing): "Replay Lost 5 5 damaged or missing in the journal\n".
std::string format_replay_lost(std::uint64_t first, std::uint64_t last);

// ---- parsing (client side) ----
struct CurrCorMsg { Xyz p; };
struct MeasPtMsg { Xyz p; };
struct StateMsg { std::string state; };
struct LimitMsg { std::string axis; std::string side; };  // "X", "neg"|"pos"
struct WarnMsg { std::string name; std::string text; };
struct FaultMsg { std::string name; std::string text; };
struct HomedMsg {};
struct OkMsg { std::string verb; std::vector<std::string> args; };
struct ErrMsg { int code = 0; std::string text; };
struct DataMsg { std::string verb; std::string text; };     // data lines before an Ok (e.g. Help ...)
struct OtherMsg { std::string line; };                       // anything else: ignore it

using Message = std::variant<CurrCorMsg, MeasPtMsg, StateMsg, LimitMsg, WarnMsg, FaultMsg, HomedMsg,
                             OkMsg, ErrMsg, DataMsg, OtherMsg, HitMsg>;

Message parse_message(std::string_view line);

// The numbers a `Replay Lost first last ...` line names (data: DataMsg::text of verb Replay).
struct LostHits {
  std::uint64_t first = 0, last = 0;
};
std::optional<LostHits> parse_replay_lost(std::string_view data);

}  // namespace imess::protocol
