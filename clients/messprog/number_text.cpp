// Number formatting: the wire's fixed-point writer (locale-independent, never "-0.000").
#include "number_text.hpp"

#include "imess/protocol/numbers.hpp"

namespace imess::messprog {

std::string fixed(double value, int decimals) {
  std::string s;
  protocol::append_fixed(s, value, decimals);  // no "-0.000"
  return s;
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
