// Lines out (IPPDME.md §§2-4): the server's `&`, `#`, `!`, `%` lines and `Error(...)`, and
// the client's command lines (for clients, tests and the fuzzer). Every line ends in CR LF.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "imess/ippdme/commands.hpp"
#include "imess/ippdme/error_code.hpp"
#include "imess/ippdme/parser.hpp"
#include "imess/ippdme/syntax.hpp"
#include "imess/ippdme/tag.hpp"

namespace imess::ippdme {

inline constexpr std::string_view kLineEnd = "\r\n";

std::string format_ack(Tag tag);                                      // "00001 &\r\n"
std::string format_done(Tag tag);                                     // "00001 %\r\n"
std::string format_data(Tag tag, std::string_view payload);           // "00002 # X(1), Y(2)\r\n"
std::string format_data(Tag tag, const std::vector<Value>& items);    // items joined by ", "

// How F3 (what raised the error) is written. The 1.4.3 prose and our digest's examples write a
// method name bare (`GoTo`); the formal grammar and the NIST server quote it (`"GoTo"`). Bare
// falls back to quoted when the cause is not a name (the start of a garbled line).
enum class CauseStyle : unsigned char { Bare, Quoted };

// `Error(3, 0502, GoTo, "Incorrect arguments")`: severity and text from the error table,
// the number in four digits.
std::string error_payload(ErrorCode code, std::string_view cause, CauseStyle style = CauseStyle::Bare);
// "00003 ! Error(...)\r\n"
std::string format_error(Tag tag, ErrorCode code, std::string_view cause, CauseStyle style = CauseStyle::Bare);
// The `!` line for a parse error, on answer_tag(error, open_tags).
std::string format_error(const LineError& error, const TagTracker& open_tags, CauseStyle style = CauseStyle::Bare);

// A command as a client writes it: "00001 PtMeas(X(1), Y(2), Z(3), IJK(0, 0, 1))\r\n";
// parse_line reads it back to the same command.
std::string format_command(Tag tag, const Command& cmd);
// The call alone, as a tree: PtMeas(X(1), ...).
Value command_call(const Command& cmd);

}  // namespace imess::ippdme
