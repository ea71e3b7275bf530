// Axis letters, groups and the machine's validation (set-up code: throws with a message).
#include "imess/planner/axes.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace imess::planner {

AxisGroup group_of(char letter) {
  switch (letter) {
    case 'X': case 'Y': case 'Z': return AxisGroup::Primary;
    case 'U': case 'V': case 'W': return AxisGroup::Secondary;
    case 'A': case 'B': case 'C': return AxisGroup::Rotary;
    default: break;
  }
  throw std::invalid_argument(std::string("planner: axis letter '") + letter + "' is not one of XYZABCUVW");
}

AxisKind default_kind(char letter) {
  return group_of(letter) == AxisGroup::Rotary ? AxisKind::Rotary : AxisKind::Linear;
}

Machine make_machine(const char* letters, double travel_min, double travel_max, double max_velocity,
                     double max_accel) {
  Machine m;
  m.count = static_cast<int>(std::strlen(letters));
  if (m.count < 1 || m.count > kMaxAxes) throw std::invalid_argument("planner: 1 to 9 axis letters expected");
  for (int i = 0; i < m.count; ++i)
    m.axes[i] = Axis{letters[i], default_kind(letters[i]), travel_min, travel_max, max_velocity, max_accel};
  validate(m);
  return m;
}

void validate(const Machine& m) {
  if (m.count < 1 || m.count > kMaxAxes)
    throw std::invalid_argument("planner: axis count " + std::to_string(m.count) + " outside 1..9");
  for (int i = 0; i < m.count; ++i) {
    const Axis& a = m.axes[i];
    const std::string name = std::string("planner: axis ") + a.letter;
    group_of(a.letter);
    for (int j = 0; j < i; ++j)
      if (m.axes[j].letter == a.letter) throw std::invalid_argument(name + " appears twice");
    if (!std::isfinite(a.travel_min) || !std::isfinite(a.travel_max) || a.travel_min > a.travel_max)
      throw std::invalid_argument(name + ": travel_min <= travel_max expected");
    if (!(a.max_velocity > 0) || !std::isfinite(a.max_velocity))
      throw std::invalid_argument(name + ": max_velocity > 0 expected");
    if (!(a.max_accel > 0) || !std::isfinite(a.max_accel))
      throw std::invalid_argument(name + ": max_accel > 0 expected");
  }
}

}  // namespace imess::planner
