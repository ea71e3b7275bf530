// TrapezoidPlanner: the servo-rate 1-D jog profile of the hal backends that plan motion
// themselves (steppers in step units, drive kits in mm). Same velocity law as the card
// firmware's profile in sim/: accelerate to vmax, brake so it ends exactly on the target,
// retarget while moving. Floating point, servo rate only — never in a base-period routine.
#pragma once

namespace imess::hal {

class TrapezoidPlanner {
 public:
  void reset(double position) noexcept;
  // vmax > 0, amax > 0 (units/s, units/s²); works from any current velocity.
  void start(double target, double vmax, double amax) noexcept;
  // Path following (the card firmware's setpoint interpolation, the port backends' follow()):
  // the profile is placed where a planned path puts the axis (position, velocity) instead of
  // running toward a target; done only when the path holds the axis at rest. stop() then
  // brakes from that velocity, start() begins a move from it.
  void track(double position, double velocity, bool at_rest = false) noexcept;
  // Brakes to rest with the given deceleration.
  void stop(double decel) noexcept;
  // Where the profile is going: -1, +1, or 0 when it stands at its target.
  int heading() const noexcept;
  // Limit protection (the card firmware's and the host planners' alike): a profile heading
  // into a closed limit switch brakes with decel.
  void brake_into_limits(bool limit_neg, bool limit_pos, double decel) noexcept;
  void step(double dt) noexcept;
  void shift(double delta) noexcept { pos_ += delta; target_ += delta; }

  double position() const noexcept { return pos_; }
  double velocity() const noexcept { return vel_; }
  double target() const noexcept { return target_; }
  double accel_limit() const noexcept { return amax_; }
  bool done() const noexcept { return done_; }

 private:
  double pos_ = 0, vel_ = 0, target_ = 0, vmax_ = 1, amax_ = 1;
  bool done_ = true;
};

}  // namespace imess::hal
