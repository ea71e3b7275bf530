// LoopContext: the events, mode changes, braking and straight-line moves every mode shares.
#include "imess/core/loop_context.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace imess::core {

// ---------------------------------------------------------------- events

void LoopContext::emit(const Event& e) noexcept {
  if (events.push(e))
    pushed = true;
  else
    ++events_dropped;
}

void LoopContext::reply(const Command& c, Refusal r) noexcept {
  Event e;
  e.kind = EventKind::Reply;
  e.client = c.client;
  e.seq = c.seq;
  e.command = c.kind;
  e.refusal = r;
  emit(e);
}

void LoopContext::measured(const Vec3& point, const Vec3& dir, bool compensated, Nanos now, std::uint32_t id) noexcept {
  Event e;
  e.kind = EventKind::MeasPt;
  e.id = id;
  e.p = point;
  e.dir = dir;
  e.compensated = compensated;
  e.radius = compensated ? config.params.tip_radius : 0.0;
  e.time = now;
  emit(e);
}

void LoopContext::warn(Warning w, const AxisVec& where, Nanos now, const char* reason) noexcept {
  Event e;
  e.kind = EventKind::Warn;
  e.warning = w;
  e.reason = reason;
  e.p = cartesian(where);
  e.time = now;
  emit(e);
}

void LoopContext::segment_event(EventKind k, std::uint32_t id, FailReason why, Nanos now) noexcept {
  Event e;
  e.kind = k;
  e.id = id;
  e.fail = why;
  e.time = now;
  emit(e);
}

// ---------------------------------------------------------------- modes

void LoopContext::enter(Mode m, Nanos now) noexcept {
  state_stale = true;
  if (m == mode) return;
  mode = m;
  mode_since = now;
  if (m == Mode::Free) ++free_entries;
  Event e;
  e.kind = EventKind::State;
  e.mode = m;
  e.time = now;
  emit(e);
}

void LoopContext::stop_motion() noexcept {
  // The configured deceleration of every axis, never the runtime MaxAccel; along a line the
  // path deceleration is the largest every moving axis can give, so the stop stays on it.
  double path = std::numeric_limits<double>::infinity();
  for (int a = 0; a < n; ++a)
    if (motion_dir[a] != 0) path = std::min(path, config.axes[a].max_accel / std::abs(motion_dir[a]));
  AxisVec decel = AxisVec::Zero();  // the unused axes: 0, never read
  for (int a = 0; a < n; ++a)
    decel[a] = motion_dir[a] == 0 ? config.axes[a].max_accel : path * std::abs(motion_dir[a]);
  if (!hw.stop(decel)) ++hardware_errors;
}

void LoopContext::brake_to_rest(Mode from, Nanos now) noexcept {
  stop_motion();
  stopped_from = from;
  enter(Mode::Stopping, now);
}

// ---------------------------------------------------------------- straight lines

unsigned LoopContext::moving_axes(const AxisVec& u) const noexcept {
  unsigned mask = 0;
  for (int a = 0; a < n; ++a)
    if (u[a] != 0) mask |= 1u << a;
  return mask;
}

AxisArray<hal::AxisMove> LoopContext::straight_moves(const AxisVec& target, const AxisVec& u, double speed,
                                                    bool configured_accel) const noexcept {
  // Speeds and accelerations in proportion to the direction keep the path on a straight
  // line through acceleration, cruise and braking; the path values are the largest that
  // keep every moving axis within its own limit.
  double v = std::min(speed, config.max_velocity), acc = std::numeric_limits<double>::infinity();
  for (int a = 0; a < n; ++a) {
    const double ua = std::abs(u[a]);
    if (ua == 0) continue;
    const auto& ax = config.axes[a];
    v = std::min(v, ax.max_velocity / ua);
    acc = std::min(acc, (configured_accel ? ax.max_accel : std::min(config.params.max_accel, ax.max_accel)) / ua);
  }
  AxisArray<hal::AxisMove> m{};  // the unused axes: 0, never in the mask
  for (int a = 0; a < n; ++a) {
    const double ua = std::abs(u[a]);
    m[a] = ua == 0 ? hal::AxisMove{ms.position[a], config.axes[a].max_velocity, config.axes[a].max_accel}
                   : hal::AxisMove{target[a], v * ua, acc * ua};
  }
  return m;
}

Vec3 LoopContext::cartesian_dir(const AxisVec& d) const noexcept {
  Vec3 c = cartesian(d);
  const double len = c.norm();
  if (len < 1e-9) return Vec3::Zero();
  return std::abs(len - 1) > 1e-12 ? Vec3(c / len) : c;  // X Y Z alone: already unit, kept to the bit
}

}  // namespace imess::core
