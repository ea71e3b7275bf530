// Lines out (IPPDME.md §§2-4): the server's `&`, `#`, `!`, `%` lines and `Error(...)`, and
// the client's command lines (for clients, tests and the fuzzer). Every line ends in CR LF.
#pragma once
#include <cstddef>
#include <optional>
#include <span>
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

// One scanned point: every value OnScanReport may ask for (docs/ippdme.md, "Scanning").
struct ScanPoint {
  Point3 xyz{};   // X() Y() Z(): the measured point, mm, in the session's coordinate system
  Vector3 ijk;    // IJK(): the surface normal there, out of the material
  double er = 0;  // ER(): the effective tip radius applied
  double q = 0;   // Q(): the point's quality, 0 good ... 100 bad
  double r = 0;   // R(): a rotary table's angle
  double tool_a = 0, tool_b = 0, tool_c = 0;  // Tool.A/B/C(): a probe head's angles
  friend bool operator==(const ScanPoint&, const ScanPoint&) = default;
};

// Points the server blocks into one data line while scanning (1.4.3 §11.1.2 lets it block
// several; a line of 16 points of every item stays below 4 KB, far under the 65 536 limit).
inline constexpr std::size_t kScanPointsPerLine = 16;
// Decimals of the scan values: mm and degrees as X(150.0000), directions as IJK's.
inline constexpr int kScanLengthDecimals = 4;
inline constexpr int kScanVectorDecimals = 6;

// How many numbers one point reports: one per item, three for IJK.
std::size_t scan_values_per_point(const std::vector<Item>& items);
// A scan's data line: "00016 # 118.5000,0.0001,-3.0002,0,118.4992,0.1614,-3.0002,0\r\n". The
// values of each point in the order of `items` (OnScanReport's), points one after the other,
// without names or parentheses, ',' between all numbers (1.4.3 §11.1.2): lengths, ER, R and
// Tool.A/B/C with kScanLengthDecimals, IJK with kScanVectorDecimals, Q a whole number 0..100.
// An empty string for no points; the server sends at most kScanPointsPerLine to a line.
std::string format_scan_data(Tag tag, const std::vector<Item>& items, std::span<const ScanPoint> points);
// The client's side: a data payload (the text after "tag # ") read back into points; nullopt
// when a value is no number or the count is not a whole multiple of scan_values_per_point.
// Items not asked for stay 0.
std::optional<std::vector<ScanPoint>> read_scan_data(std::string_view payload, const std::vector<Item>& items);

}  // namespace imess::ippdme
