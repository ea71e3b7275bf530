// Wire numbers: strict parsing (from_chars, finite only; underflow reads as 0) and %.3f output,
// never cut short.
#include "imess/protocol/numbers.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace imess::protocol {

namespace {
// For a token from_chars read whole but found out of range: true when its magnitude is below
// 1 (so it underflowed to zero), false when it is above (overflow). Decides by the decimal
// exponent of the first significant digit, without the C locale's strtod.
bool is_underflow(std::string_view t) {
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) t.remove_prefix(1);
  const std::size_t mantissa_end = std::min(t.find_first_of("eE"), t.size());
  long long before_point = 0, first_nonzero = -1, index = 0;  // digit counts and indices
  bool point = false;
  for (std::size_t k = 0; k < mantissa_end; ++k) {
    if (t[k] == '.') {
      point = true;
      continue;
    }
    if (!point) ++before_point;
    if (first_nonzero < 0 && t[k] != '0') first_nonzero = index;
    ++index;
  }
  if (first_nonzero < 0) return true;  // all zeros never overflow
  long long exponent = 0;  // saturated: 1e-99999999999 is as small as 1e-999999999
  bool negative = false;
  std::size_t k = mantissa_end + 1;
  if (k < t.size() && (t[k] == '-' || t[k] == '+')) negative = t[k++] == '-';
  for (; k < t.size(); ++k)
    if (exponent < 1'000'000'000) exponent = exponent * 10 + (t[k] - '0');
  if (negative) exponent = -exponent;
  // 10^(before_point - 1 - first_nonzero) is the place of the first significant digit.
  return before_point - 1 - first_nonzero + exponent < 0;
}
}  // namespace

std::optional<double> parse_number(std::string_view token) {
  if (token.empty()) return std::nullopt;
  const char* first = token.data();
  const char* last = first + token.size();
  if (*first == '+') {  // from_chars does not take a leading plus; people type it
    ++first;
    if (first == last || *first == '-' || *first == '+') return std::nullopt;
  }
  double value = 0;
  auto [end, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (end != last) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    if (!is_underflow(std::string_view(first, static_cast<std::size_t>(last - first)))) return std::nullopt;
    return 0.0;  // too small to represent: it is zero for every purpose on the wire
  }
  if (ec != std::errc{} || !std::isfinite(value)) return std::nullopt;
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
  // Positions fit the stack buffer; anything longer (1e300 has 301 digits before the point) is
  // written whole into the string: a number is never cut short.
  char buf[64];
  const int n = std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  if (n <= 0) return;
  std::string wide;
  std::string_view text(buf, static_cast<std::size_t>(n));
  if (n >= int(sizeof buf)) {
    wide.resize(static_cast<std::size_t>(n) + 1);
    std::snprintf(wide.data(), wide.size(), "%.*f", decimals, value);
    wide.pop_back();  // the terminating NUL
    text = wide;
  }
  if (text.front() == '-' && text.find_first_not_of("-0.") == std::string_view::npos) text.remove_prefix(1);
  out.append(text);
}

void append_mm(std::string& out, double value) { append_fixed(out, value, 3); }

}  // namespace imess::protocol
