// Oblique move arithmetic.
#include "oblique.hpp"

#include <cmath>

namespace imess::messjog {

double dot(const Xyz& a, const Xyz& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

std::optional<Xyz> unit_direction(const Xyz& from, const Xyz& to) {
  Xyz d{to.x - from.x, to.y - from.y, to.z - from.z};
  double length = std::sqrt(dot(d, d));
  if (!(length >= kSamePointMm)) return std::nullopt;
  return Xyz{d.x / length, d.y / length, d.z / length};
}

Xyz jog_speeds(const Xyz& unit, double percent) {
  return {unit.x * percent, unit.y * percent, unit.z * percent};
}

}  // namespace imess::messjog
