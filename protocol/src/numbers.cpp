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

std::optional<std::uint64_t> parse_sequence_number(std::string_view token) {
  if (token.empty() || token.size() > 16) return std::nullopt;
  std::uint64_t value = 0;
  auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc{} || end != token.data() + token.size() || value > kMaxSequenceNumber) return std::nullopt;
  return value;
}

void append_fixed(std::string& out, double value, int decimals) {
  char buf[64];
  int n = std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  if (n <= 0) return;
  std::string_view text(buf, static_cast<std::size_t>(n < int(sizeof buf) ? n : int(sizeof buf) - 1));
  if (text.front() == '-' && text.find_first_not_of("-0.") == std::string_view::npos) text.remove_prefix(1);
  out.append(text);
}

void append_mm(std::string& out, double value) { append_fixed(out, value, 3); }

}  // namespace imess::protocol
