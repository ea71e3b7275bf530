// The planner's view of the machine the core drives: the configured axes (letters, kinds,
// travel) with the resolved per-axis limits (MotionCore::config()), and the loop's period.
// The io side builds its Planner from this; tests do the same.
#pragma once
#include "imess/core/core_types.hpp"
#include "imess/planner/planner.hpp"

namespace imess::core {

// The configuration with every axis' limits resolved: an axis without its own max_velocity
// or max_accel (0) takes the machine's (MotionCore does this at construction).
inline CoreConfig resolved_limits(CoreConfig c) {
  for (auto& a : c.axes) {  // the unused entries too: they are never moved
    if (a.max_velocity <= 0) a.max_velocity = c.max_velocity;
    if (a.max_accel <= 0) a.max_accel = c.params.max_accel;
  }
  return c;
}

inline planner::Machine path_machine(const CoreConfig& resolved) {
  planner::Machine m;
  m.count = resolved.layout.count;
  for (int a = 0; a < m.count; ++a) {
    auto& ax = m.axes[a];
    ax.letter = resolved.layout.letters[a];
    ax.kind = resolved.layout.kinds[a] == hal::AxisKind::Rotary ? planner::AxisKind::Rotary : planner::AxisKind::Linear;
    ax.travel_min = resolved.axes[a].travel_min;
    ax.travel_max = resolved.axes[a].travel_max;
    ax.max_velocity = resolved.axes[a].max_velocity;
    ax.max_accel = resolved.axes[a].max_accel;
  }
  return m;
}

inline planner::PlannerOptions path_options(const CoreConfig& resolved) {
  planner::PlannerOptions o;
  o.loop_period = resolved.period_s;
  o.min_feed = kMinSpeed;  // as for jog and GoTo: slower than this nothing visibly moves
  return o;
}

}  // namespace imess::core
