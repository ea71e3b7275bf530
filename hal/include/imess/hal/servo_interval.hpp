// The time since the previous servo period, as the port backends' set-point profiles step it:
// 0 at the first period, at most kMaxServoInterval (a stalled caller does not make a profile jump).
#pragma once
#include <algorithm>

#include "imess/hal/types.hpp"

namespace imess::hal {

inline constexpr double kMaxServoInterval = 0.1;  // s

class ServoInterval {
 public:
  // Seconds since the previous call (0 at the first), clamped to [0, kMaxServoInterval].
  double next(Nanos now) noexcept {
    const double dt = started_ ? seconds(now - last_) : 0.0;
    last_ = now;
    started_ = true;
    return std::clamp(dt, 0.0, kMaxServoInterval);
  }

 private:
  Nanos last_{0};
  bool started_ = false;
};

}  // namespace imess::hal
