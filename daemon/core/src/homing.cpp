// Homing phases; every phase has a timeout so a missing switch fails instead of hanging.
#include "imess/core/homing.hpp"

#include <algorithm>
#include <cmath>

namespace imess::core {

namespace in = hal::input;

void Homing::begin(const CoreConfig& config, Nanos now) noexcept {
  config_ = &config;
  order_pos_ = 0;
  failure_ = "";
  enter(Phase::Start, now);
}

bool Homing::jog(hal::MotionBackend& hw, double target, double speed) noexcept {
  AxisArray<hal::AxisMove> m{};
  // Homing is the machine's own procedure: the axis' configured limits, never runtime values.
  const auto& ax = config_->axes[axis_];
  m[axis_] = {target, std::min(speed, ax.max_velocity), ax.max_accel};
  return hw.move(m, 1u << axis_);
}

void Homing::brake(hal::MotionBackend& hw) noexcept {
  Vec3 decel;
  for (int a = 0; a < kAxes; ++a) decel[a] = config_->axes[a].max_accel;
  hw.stop(decel);
}

Homing::Result Homing::step(const hal::MachineState& ms, hal::MotionBackend& hw, Nanos now) noexcept {
  const auto& h = config_->homing;
  const double pos = ms.position[axis_];
  const bool cam = ms.input(axis_, in::kHome);
  const bool index = ms.input(axis_, in::kIndex);
  const bool limit_here = ms.input(axis_, dir_ < 0 ? in::kLimitNeg : in::kLimitPos);
  const bool limit_away = ms.input(axis_, dir_ < 0 ? in::kLimitPos : in::kLimitNeg);
  const bool done = (ms.status[axis_] & hal::status::kProfileEnd) != 0;
  constexpr double kFar = 1e5;
  if (phase_ != Phase::Start && hal::seconds(now - phase_start_) > h.phase_timeout)
    return fail("a homing phase timed out: switch or index not found");

  switch (phase_) {
    case Phase::Start:
      if (order_pos_ >= kAxes) return Result::Done;
      axis_ = h.order[order_pos_];
      dir_ = config_->axes[axis_].home_direction < 0 ? -1 : 1;
      backed_off_ = reversed_ = have_entry_ = false;
      if (ms.input(axis_, dir_ < 0 ? in::kLimitNeg : in::kLimitPos)) {
        if (!jog(hw, pos - dir_ * h.limit_escape, h.search_speed)) return fail("the controller refused a move");
        enter(Phase::EscapeLimit, now);
      } else {
        if (!jog(hw, pos + dir_ * kFar, h.search_speed)) return fail("the controller refused a move");
        search_start_ = now;
        enter(Phase::Search, now);
      }
      return Result::Running;

    case Phase::EscapeLimit:
      if (limit_away) return fail("ran into the opposite limit while leaving a limit switch");
      if (done) {
        if (!jog(hw, pos + dir_ * kFar, h.search_speed)) return fail("the controller refused a move");
        search_start_ = now;
        enter(Phase::Search, now);
      }
      return Result::Running;

    case Phase::Search:
      if (cam) {
        brake(hw);
        enter(Phase::SearchStopping, now);
      } else if (limit_here && !reversed_) {  // switch not on this side of us: reverse at the limit
        reversed_ = true;
        if (!jog(hw, pos - dir_ * kFar, h.search_speed)) return fail("the controller refused a move");
      } else if (limit_away || (limit_here && reversed_ && done)) {
        return fail("home switch not found between the limits");
      }
      return Result::Running;

    case Phase::SearchStopping:
      if (!done) return Result::Running;
      if (!backed_off_ && hal::seconds(now - search_start_) < h.min_search_time) {
        backed_off_ = true;  // found too soon: approach again from a distance at full speed
        if (!jog(hw, pos - dir_ * h.backoff, h.search_speed)) return fail("the controller refused a move");
        enter(Phase::BackOff, now);
      } else {
        if (!jog(hw, pos - dir_ * kFar, h.index_speed)) return fail("the controller refused a move");
        prev_index_ = index;
        enter(Phase::LeaveSwitch, now);
      }
      return Result::Running;

    case Phase::BackOff:
      if (limit_away) return fail("ran into the opposite limit while backing off");
      if (done) {
        if (!jog(hw, pos + dir_ * kFar, h.search_speed)) return fail("the controller refused a move");
        search_start_ = now;
        reversed_ = false;
        enter(Phase::Search, now);
      }
      return Result::Running;

    case Phase::LeaveSwitch:
      if (limit_away) return fail("no encoder index found after the home switch");
      if (!cam && index && !prev_index_) {
        brake(hw);
        enter(Phase::IndexStopping, now);
      }
      prev_index_ = index;
      return Result::Running;

    case Phase::IndexStopping:
      if (done) {  // go back past the index, then creep over it
        if (!jog(hw, pos + dir_ * 0.1, h.index_speed)) return fail("the controller refused a move");
        enter(Phase::CreepBack, now);
      }
      return Result::Running;

    case Phase::CreepBack:
      if (done) {
        if (!jog(hw, pos - dir_ * kFar, h.creep_speed)) return fail("the controller refused a move");
        prev_index_ = index;
        have_entry_ = false;
        enter(Phase::Creep, now);
      }
      return Result::Running;

    case Phase::Creep:
      if (index && !prev_index_) {
        entry_ = pos;
        have_entry_ = true;
      } else if (!index && prev_index_ && have_entry_) {
        exit_ = pos;
        brake(hw);
        enter(Phase::CreepStopping, now);
      }
      prev_index_ = index;
      return Result::Running;

    case Phase::CreepStopping:
      if (done) {
        double centre = 0.5 * (entry_ + exit_);
        if (!hw.set_position(axis_, config_->axes[axis_].home_position + (pos - centre)))
          return fail("the controller refused to set the home position");
        ++order_pos_;
        enter(Phase::Start, now);
      }
      return Result::Running;
  }
  return Result::Running;
}

}  // namespace imess::core
