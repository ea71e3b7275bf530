// fixed(): the one way coordinates are printed in every export format.
#include <cstdio>
#include <string>

#include "imess/exchange/export_data.hpp"

namespace imess::exchange {

std::string fixed(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s(buf);
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // -0.000
  return s;
}

}  // namespace imess::exchange
