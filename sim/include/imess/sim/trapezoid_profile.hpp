// TrapezoidProfile: the card firmware's 1-D jog profile. Accelerates to the speed limit,
// brakes so it ends exactly on the target, and may be retargeted while moving.
#pragma once

namespace imess::sim {

class TrapezoidProfile {
 public:
  void reset(double position) noexcept;
  // New target; vmax > 0 and amax > 0 (mm/s, mm/s²). Works from any current velocity.
  void start(double target, double vmax, double amax) noexcept;
  // Brakes to rest with the given deceleration.
  void stop(double decel) noexcept;
  void step(double dt) noexcept;
  // Shifts the coordinate system (the axis position was redefined).
  void shift(double delta) noexcept;

  double position() const noexcept { return pos_; }
  double velocity() const noexcept { return vel_; }
  double target() const noexcept { return target_; }
  bool done() const noexcept { return done_; }

 private:
  double pos_ = 0, vel_ = 0, target_ = 0, vmax_ = 1, amax_ = 1;
  bool done_ = true;
};

}  // namespace imess::sim
