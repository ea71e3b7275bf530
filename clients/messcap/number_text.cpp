#include "number_text.hpp"

#include <cstdio>
#include <cstring>

namespace imess::messcap {

namespace {
// "-0.000" and "-0" as printed: a minus before nothing but zeros, which becomes the sign a zero
// has in that format ('+' where the format signs every value, none otherwise).
std::string without_negative_zero(std::string s, bool signed_format) {
  if (s.size() < 2 || s[0] != '-' || s[1] < '0' || s[1] > '9') return s;
  const auto after = s.find_first_not_of("0.", 1);  // where the number's zeros end (text may follow)
  if (after != std::string::npos && s[after] >= '0' && s[after] <= '9') return s;
  if (signed_format)
    s[0] = '+';
  else
    s.erase(0, 1);
  return s;
}
}  // namespace

std::string number_text(double v, const char* format) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return without_negative_zero(buf, std::strstr(format, "%+") != nullptr);
}

std::string fixed_text(double v, int decimals, bool sign) {
  char buf[64];
  std::snprintf(buf, sizeof buf, sign ? "%+.*f" : "%.*f", decimals, v);
  return without_negative_zero(buf, sign);
}

}  // namespace imess::messcap
