// The I++ DME value grammar (IPPDME.md §2 "Syntax"): numbers, strings, names, event tags and
// calls such as `PtMeas(X(1), Y(2), Z(3), IJK(0,0,1))`, read into a tree and written back.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "imess/ippdme/error_code.hpp"

namespace imess::ippdme {

enum class ValueKind : unsigned char {
  Number,    // 1.003E01, -.77, 7.
  String,    // "RefTool" (text without the quotes)
  Word,      // a bare name: PartCsy, CartCMM
  EventTag,  // E0005 (a bare E + 4 digits)
  Call,      // Name(args...), the name possibly dotted: Tool.PtMeasPar.Speed()
};

struct Value {
  ValueKind kind = ValueKind::Number;
  double number = 0;        // Number
  std::string text;         // Number: as written; String: without quotes; Word, EventTag, Call: the name
  std::vector<Value> args;  // Call

  static Value of_number(double v);               // shortest text that reads back as v
  static Value of_fixed(double v, int decimals);  // e.g. X(150.0000) with 4 decimals
  static Value of_integer(long long v);
  static Value of_string(std::string_view s);     // quotes are not allowed inside: replaced by '
  static Value of_word(std::string_view w);
  static Value call(std::string_view name, std::vector<Value> args = {});

  friend bool operator==(const Value&, const Value&) = default;
};

// Deepest nesting of calls accepted (PtMeas(X(1)) is 2); deeper input is a ProtocolError.
inline constexpr std::size_t kMaxNesting = 8;
// Most digits in a number's mantissa (IPPDME.md: "at most 16 digits"); the exponent has 1-3.
inline constexpr std::size_t kMaxNumberDigits = 16;

struct SyntaxError {
  ErrorCode code;    // ProtocolError (garbled) or IncorrectArguments (a number beyond a double)
  std::size_t at;    // offset into the text where reading stopped
};

// Reads exactly one call filling all of `text` (the line from column 7): optional spaces only
// around commas, around `(` and before `)`; case kept. Never throws.
struct CallResult {
  std::optional<Value> call;
  std::optional<SyntaxError> error;
};
CallResult parse_call(std::string_view text);

// One number token as the grammar has it; nullopt when it is not one (or overflows a double).
std::optional<double> parse_number_token(std::string_view token);
bool is_name(std::string_view s);  // letters/digits from a letter, dotted parts allowed

// Writing: arguments separated by ", ", no other spaces: `Get(X(), Y(), Z())`.
void append_value(std::string& out, const Value& v);
std::string format_value(const Value& v);
// A data payload of several items: "X(1), Y(2)".
std::string format_values(const std::vector<Value>& values);
// A number in at most kMaxNumberDigits digits, shortest form that reads back the same where
// one exists; never "-0"; non-finite values (which the wire cannot carry) are written as 0.
std::string format_number(double v);
std::string format_fixed(double v, int decimals);

}  // namespace imess::ippdme
