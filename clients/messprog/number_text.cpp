// Number formatting with snprintf (locale-independent in the C locale the clients run in).
#include "number_text.hpp"

#include <cmath>
#include <cstdio>

namespace imess::messprog {

std::string fixed(double value, int decimals) {
  if (value == 0 || std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0;  // no "-0.000"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

std::string number_text(double value, int max_decimals) {
  std::string s = fixed(value, max_decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s;
}

}  // namespace imess::messprog
