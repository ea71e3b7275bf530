// RestWatch: tells the motion loop when the position leaves a rest — still (every axis within
// kEpsilon of where the rest began) for kStillCycles cycles, then moved. The loop counts these
// departures into the snapshot and wakes the io side on that cycle and the kDepartureWakes
// after it, so the io side shows the first changed position right after the cycle that
// measured it instead of polling every millisecond (docs/architecture.md, "The position
// stream"). Real-time: no allocation, no branch on anything but the positions.
#pragma once

#include <cmath>

#include "imess/core/core_types.hpp"

namespace imess::core {

class RestWatch {
 public:
  static constexpr double kEpsilon = 1e-4;  // mm or degrees: a tenth of the last printed digit
  static constexpr int kStillCycles = 5;    // shorter than the fastest shared report period (10 ms)
  // Cycles after a departure on which the loop wakes the io side, which looks each time
  // whether the printed position changed (a tenth of a digit is not yet a printed change).
  static constexpr int kDepartureWakes = 20;

  // One call per cycle with the measured position; true on the cycle it leaves a rest.
  bool left_rest(const AxisVec& p, int axes) noexcept {
    bool moved = false;
    for (int a = 0; a < axes; ++a) moved = moved || std::abs(p[a] - anchor_[a]) > kEpsilon;
    if (!moved) {
      if (still_ < kStillCycles) ++still_;
      return false;
    }
    const bool was_at_rest = still_ >= kStillCycles;
    anchor_ = p;
    still_ = 0;
    return was_at_rest;
  }

 private:
  AxisVec anchor_ = AxisVec::Zero();
  int still_ = 0;
};

}  // namespace imess::core
