// Numbers as messprog prints them: fixed decimals for figures, or the shortest form
// (trailing zeros removed) for settings and SVG labels.
#pragma once
#include <string>

namespace imess::messprog {

std::string fixed(double value, int decimals);                  // fixed(2.5, 3) == "2.500"
std::string number_text(double value, int max_decimals = 6);    // number_text(2.50) == "2.5"

}  // namespace imess::messprog
