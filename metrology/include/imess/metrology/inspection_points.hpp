// Measured points labelled by feature, for re-evaluating an inspection from a file: lines
// `FEATURE x y z [i j k r]` (a messd Hit's point, approach and tip radius, machine coordinates),
// or the JSON report `messcap inspect --json` writes (its "points": feature, machine, approach,
// radius). docs/metrology.md §16.
#pragma once

#include <stdexcept>
#include <string_view>
#include <vector>

#include "imess/metrology/inspection.hpp"

namespace imess::metrology {

// "<source>:<line>: <what was wrong, what is accepted>" (JSON: "<source>: points[3].machine: ...").
class MeasuredPointsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Text or JSON (a text whose first non-blank character is '{'). A zero approach with radius 0
// (messd's ForcePt) is a plain point.
std::vector<MeasuredPoint> parse_measured_points(std::string_view text, std::string_view source = "<points>");

}  // namespace imess::metrology
