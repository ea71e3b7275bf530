// Homing phases; every phase has a timeout so a missing switch fails instead of hanging.
#include "imess/core/homing.hpp"

#include <algorithm>
#include <cmath>

namespace imess::core {

namespace in = hal::input;

AxisArray<int> default_home_order(const AxisLayout& layout) noexcept {
  AxisArray<int> order{};
  int k = 0;
  const int z = layout.cartesian_axis(2);
  if (z >= 0) order[k++] = z;
  for (int a = 0; a < layout.count; ++a)
    if (a != z) order[k++] = a;
  return order;
}

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
  AxisVec decel = AxisVec::Zero();
  for (int a = 0; a < config_->layout.count; ++a) decel[a] = config_->axes[a].max_accel;
  hw.stop(decel);
}

// What one cycle's machine state says about the axis being homed.
struct Homing::Sense {
  double pos;
  bool cam, index, limit_here, limit_away, done;
};

namespace {
constexpr double kFar = 1e5;  // mm: a target beyond any travel; the switch or index ends the move
constexpr const char* kRefused = "the controller refused a move";
}  // namespace

Homing::Result Homing::go(hal::MotionBackend& hw, double target, double speed, Phase next, Nanos now) noexcept {
  if (!jog(hw, target, speed)) return fail(kRefused);
  enter(next, now);
  return Result::Running;
}

Homing::Result Homing::search_from(hal::MotionBackend& hw, double pos, Nanos now) noexcept {
  search_start_ = now;
  return go(hw, pos + dir_ * kFar, config_->homing.search_speed, Phase::Search, now);
}

Homing::Result Homing::step(const hal::MachineState& ms, hal::MotionBackend& hw, Nanos now) noexcept {
  const Sense s{ms.position[axis_],
                ms.input(axis_, in::kHome),
                ms.input(axis_, in::kIndex),
                ms.input(axis_, dir_ < 0 ? in::kLimitNeg : in::kLimitPos),
                ms.input(axis_, dir_ < 0 ? in::kLimitPos : in::kLimitNeg),
                (ms.status[axis_] & hal::status::kProfileEnd) != 0};
  if (phase_ != Phase::Start && hal::seconds(now - phase_start_) > config_->homing.phase_timeout)
    return fail("a homing phase timed out: switch or index not found");
  switch (phase_) {
    case Phase::Start: return start_axis(ms, hw, now);
    case Phase::EscapeLimit:
      if (s.limit_away) return fail("ran into the opposite limit while leaving a limit switch");
      return s.done ? search_from(hw, s.pos, now) : Result::Running;
    case Phase::Search: return search(s, hw, now);
    case Phase::SearchStopping: return s.done ? after_search(s, hw, now) : Result::Running;
    case Phase::BackOff:
      if (s.limit_away) return fail("ran into the opposite limit while backing off");
      if (!s.done) return Result::Running;
      reversed_ = false;
      return search_from(hw, s.pos, now);
    case Phase::LeaveSwitch: return leave_switch(s, hw, now);
    case Phase::IndexStopping:  // go back past the index, then creep over it
      return s.done ? go(hw, s.pos + dir_ * 0.1, config_->homing.index_speed, Phase::CreepBack, now) : Result::Running;
    case Phase::CreepBack:
      if (!s.done) return Result::Running;
      prev_index_ = s.index;
      have_entry_ = false;
      return go(hw, s.pos - dir_ * kFar, config_->homing.creep_speed, Phase::Creep, now);
    case Phase::Creep: return creep(s, hw, now);
    case Phase::CreepStopping: return s.done ? set_home(s, hw, now) : Result::Running;
  }
  return Result::Running;
}

// The next axis in the homing order: out of a limit switch first if it sits in the one on
// its home side, else straight into the search.
Homing::Result Homing::start_axis(const hal::MachineState& ms, hal::MotionBackend& hw, Nanos now) noexcept {
  const auto& h = config_->homing;
  if (order_pos_ >= config_->layout.count) return Result::Done;
  axis_ = h.order[order_pos_];
  dir_ = config_->axes[axis_].home_direction < 0 ? -1 : 1;
  backed_off_ = reversed_ = have_entry_ = false;
  const double pos = ms.position[axis_];
  if (ms.input(axis_, dir_ < 0 ? in::kLimitNeg : in::kLimitPos))
    return go(hw, pos - dir_ * h.limit_escape, h.search_speed, Phase::EscapeLimit, now);
  return search_from(hw, pos, now);
}

// Fast search for the home cam; reverses once at the limit when the cam is behind us.
Homing::Result Homing::search(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept {
  if (s.cam) {
    brake(hw);
    enter(Phase::SearchStopping, now);
  } else if (s.limit_here && !reversed_) {
    reversed_ = true;
    if (!jog(hw, s.pos - dir_ * kFar, config_->homing.search_speed)) return fail(kRefused);
  } else if (s.limit_away || (s.limit_here && reversed_ && s.done)) {
    return fail("home switch not found between the limits");
  }
  return Result::Running;
}

// Stopped on the cam: found too soon (no full-speed approach), back off and search again;
// else leave the cam slowly toward the index.
Homing::Result Homing::after_search(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept {
  const auto& h = config_->homing;
  if (!backed_off_ && hal::seconds(now - search_start_) < h.min_search_time) {
    backed_off_ = true;
    return go(hw, s.pos - dir_ * h.backoff, h.search_speed, Phase::BackOff, now);
  }
  prev_index_ = s.index;
  return go(hw, s.pos - dir_ * kFar, h.index_speed, Phase::LeaveSwitch, now);
}

Homing::Result Homing::leave_switch(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept {
  if (s.limit_away) return fail("no encoder index found after the home switch");
  if (!s.cam && s.index && !prev_index_) {
    brake(hw);
    enter(Phase::IndexStopping, now);
  }
  prev_index_ = s.index;
  return Result::Running;
}

// Creep across the index and remember where it began and ended.
Homing::Result Homing::creep(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept {
  if (s.index && !prev_index_) {
    entry_ = s.pos;
    have_entry_ = true;
  } else if (!s.index && prev_index_ && have_entry_) {
    exit_ = s.pos;
    brake(hw);
    enter(Phase::CreepStopping, now);
  }
  prev_index_ = s.index;
  return Result::Running;
}

// The index's centre becomes the axis' home position; on to the next axis.
Homing::Result Homing::set_home(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept {
  const double centre = 0.5 * (entry_ + exit_);
  if (!hw.set_position(axis_, config_->axes[axis_].home_position + (s.pos - centre)))
    return fail("the controller refused to set the home position");
  ++order_pos_;
  enter(Phase::Start, now);
  return Result::Running;
}

}  // namespace imess::core
