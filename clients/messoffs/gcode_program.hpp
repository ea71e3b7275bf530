// The offset program: one `G10 L2 P<n> X.. Y.. Z..` line per offset of one clamping, the values
// being the rotated offsets Rx(-A)·Ry(-B)·(base + correction) the controller works with.
#pragma once
#include <string>

#include "offset_table.hpp"

namespace imess::messoffs {

// Throws TableError when an offset of the clamping has no P number (names the offset and how
// to give one) or the clamping has no offsets.
std::string offset_program(const OffsetTable& table, int clamping, const std::string& source);

// A G-code number: up to six decimals, trailing zeros dropped but never the decimal point
// (a Fanuc-style control reads "X222" as 0.222 mm), never "-0.0".
std::string gcode_number(double value);

}  // namespace imess::messoffs
