// One offset's values, checked the same way whichever format they came in.
#include "field_checks.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "offset_table.hpp"

namespace imess::messoffs {
namespace {

std::string shown(double value) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}

int check_whole(double value, const std::string& where, int lo, int hi, std::string_view what) {
  if (!(value >= lo && value <= hi) || value != std::floor(value))
    throw TableError(where + ": expected " + std::string(what) + ", a whole number " + std::to_string(lo) + ".." +
                     std::to_string(hi) + ", got " + shown(value));
  return static_cast<int>(value);
}

}  // namespace

std::string check_name(std::string_view name, const std::string& where) {
  if (!valid_offset_name(name))
    throw TableError(where + ": expected an offset name of letters, digits, '.', '_' or '-' (1 to 32), got '" +
                     std::string(name) + "'");
  return std::string(name);
}

int check_clamping(double value, const std::string& where) {
  return check_whole(value, where, 1, 999, "the clamping");
}

int check_p(double value, const std::string& where) {
  return check_whole(value, where, kMinP, kMaxP, "the G10 L2 P number (P1..P9 = G54..G59.3)");
}

double check_finite(double value, const std::string& where, std::string_view what) {
  if (!std::isfinite(value)) throw TableError(where + ": expected " + std::string(what) + ", a finite number");
  return value;
}

double parse_number(std::string_view text, const std::string& where, std::string_view what) {
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-') digits.remove_prefix(1);  // "+0.2"
  double value = 0.0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc{} || end != digits.data() + digits.size() || !std::isfinite(value))
    throw TableError(where + ": expected " + std::string(what) + ", a finite number, got '" + std::string(text) + "'");
  return value;
}

}  // namespace imess::messoffs
