// BaseRateDriver: a backend with a fast periodic routine besides the servo-rate calls
// (the step generator's pulse making). The daemon runs base_tick() in its own thread on
// real hardware; the simulator calls it in virtual time, in lock-step with the machine.
#pragma once
#include "imess/hal/types.hpp"

namespace imess::hal {

class BaseRateDriver {
 public:
  virtual ~BaseRateDriver() = default;
  // Real-time, base rate: integer only, no allocation, no locks, no logging.
  virtual void base_tick() noexcept = 0;
  virtual Nanos base_period() const noexcept = 0;
};

}  // namespace imess::hal
