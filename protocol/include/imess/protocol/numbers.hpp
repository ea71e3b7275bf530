// Number reading and writing on the wire: millimetres with three decimals, as in 1996.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace imess::protocol {

// A finite decimal number ("12", "-0.5", ".25", "1e3"); nothing else, no trailing bytes.
std::optional<double> parse_number(std::string_view token);

// Appends value as %.3f; a value that rounds to zero prints as 0.000, never -0.000.
void append_mm(std::string& out, double value);

}  // namespace imess::protocol
