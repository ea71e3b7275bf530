// Per tick: the speed from which the axis can still stop at the target, capped by vmax,
// reached with at most amax; arrival snaps to the target (no overshoot).
#include "imess/hal/trapezoid_planner.hpp"

#include <algorithm>
#include <cmath>

namespace imess::hal {

void TrapezoidPlanner::reset(double position) noexcept {
  pos_ = target_ = position;
  vel_ = 0;
  done_ = true;
}

void TrapezoidPlanner::start(double target, double vmax, double amax) noexcept {
  target_ = target;
  vmax_ = vmax;
  amax_ = amax;
  done_ = false;
}

void TrapezoidPlanner::track(double position, double velocity, bool at_rest) noexcept {
  pos_ = target_ = position;
  vel_ = at_rest ? 0.0 : velocity;
  vmax_ = std::max(std::abs(vel_), 1e-9);
  done_ = at_rest;
}

void TrapezoidPlanner::stop(double decel) noexcept {
  if (done_) return;
  amax_ = decel;
  vmax_ = std::max(std::abs(vel_), 1e-9);
  target_ = pos_ + vel_ * std::abs(vel_) / (2 * decel);
}

void TrapezoidPlanner::step(double dt) noexcept {
  if (done_ || dt <= 0) return;
  double d = target_ - pos_;
  double dv_max = amax_ * dt;
  if (std::abs(d) < 1e-9 && std::abs(vel_) <= dv_max) {
    pos_ = target_;
    vel_ = 0;
    done_ = true;
    return;
  }
  double v_stop = std::sqrt(dv_max * dv_max + 2 * amax_ * std::abs(d)) - dv_max;
  double v_des = std::copysign(std::min(vmax_, v_stop), d);
  vel_ += std::clamp(v_des - vel_, -dv_max, dv_max);
  double travel = vel_ * dt;
  if ((d > 0 && travel >= d) || (d < 0 && travel <= d)) {
    pos_ = target_;
    vel_ = 0;
    done_ = true;
    return;
  }
  pos_ += travel;
}

int TrapezoidPlanner::heading() const noexcept {
  if (vel_ != 0) return vel_ > 0 ? 1 : -1;
  if (done_ || target_ == pos_) return 0;
  return target_ > pos_ ? 1 : -1;
}

void TrapezoidPlanner::brake_into_limits(bool limit_neg, bool limit_pos, double decel) noexcept {
  const int h = heading();
  if ((h < 0 && limit_neg) || (h > 0 && limit_pos)) stop(decel);
}

}  // namespace imess::hal
