// Number reading and writing on the wire: millimetres with three decimals, as in 1996.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace imess::protocol {

// A finite decimal number ("12", "-0.5", ".25", "1e3"); nothing else, no trailing bytes.
std::optional<double> parse_number(std::string_view token);

// A hit sequence number: plain decimal digits, 0 ... kMaxSequenceNumber (exact in a double,
// so clients in any language can hold it).
inline constexpr std::uint64_t kMaxSequenceNumber = 9007199254740991;  // 2^53 - 1
std::optional<std::uint64_t> parse_sequence_number(std::string_view token);

// Appends value with `decimals` decimals; never "-0.000..." (a negative zero prints unsigned).
void append_fixed(std::string& out, double value, int decimals);

// Appends value as %.3f; a value that rounds to zero prints as 0.000, never -0.000.
void append_mm(std::string& out, double value);

}  // namespace imess::protocol
