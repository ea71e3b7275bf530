// Wire numbers: strict parsing (from_chars, finite only) and %.3f output.
#include "imess/protocol/numbers.hpp"

#include <charconv>
#include <cmath>
#include <string_view>
#include <cstdio>

namespace imess::protocol {

std::optional<double> parse_number(std::string_view token) {
  if (token.empty()) return std::nullopt;
  const char* first = token.data();
  const char* last = first + token.size();
  if (*first == '+') ++first;  // from_chars does not take a leading plus; people type it
  double value = 0;
  auto [end, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (ec != std::errc{} || end != last || !std::isfinite(value)) return std::nullopt;
  return value;
}

void append_mm(std::string& out, double value) {
  char buf[48];
  int n = std::snprintf(buf, sizeof buf, "%.3f", value);
  if (n <= 0) return;
  std::string_view text(buf, static_cast<std::size_t>(n < int(sizeof buf) ? n : int(sizeof buf) - 1));
  if (text == "-0.000") text.remove_prefix(1);
  out.append(text);
}

}  // namespace imess::protocol
