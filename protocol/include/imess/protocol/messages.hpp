// Daemon -> client lines. Replies start with `Ok` or `Err`; every other verb is an unsolicited
// event (CurrCor, MeasPt, State, Limit, Warn, Fault, Homed). Formatting for the daemon,
// parsing for the clients.
#pragma once
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "imess/protocol/commands.hpp"
#include "imess/protocol/error_code.hpp"

namespace imess::protocol {

// ---- formatting (daemon side); every line ends in "\n" ----
std::string format_xyz(std::string_view verb, const Xyz& p);  // "CurrCor 1.000 2.000 3.000\n"
inline std::string format_curr_cor(const Xyz& p) { return format_xyz("CurrCor", p); }
inline std::string format_meas_pt(const Xyz& p) { return format_xyz("MeasPt", p); }
std::string format_ok(std::string_view verb, std::string_view data = {});
std::string format_err(ErrorCode code, std::string_view text);
std::string format_event(std::string_view verb, std::string_view text);  // "State idle\n", "Warn TipNotFree ...\n"

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
                             OkMsg, ErrMsg, DataMsg, OtherMsg>;

Message parse_message(std::string_view line);

}  // namespace imess::protocol
