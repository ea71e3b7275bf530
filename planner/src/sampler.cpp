// The sampler's non-template parts: evaluation, completion, and feed hold.
//
// Feed hold leaves the plan's time but never its path. On the plan's time, τ advances by
// dt. While braking (hold, or a queue about to run dry) and while resuming, the sampler
// drives the path speed w itself: each tick w changes by the segment's path acceleration
// a·dt, the tick covers exactly ½(w + w_new)·dt of path (so the path acceleration is a,
// and each axis', its share of it, within its limit; on arcs the centripetal part only
// shrinks as w falls), and τ is where the profile has covered that length. Braking never
// outruns the plan (w² falls by 2a per unit length, at least as fast as any planned
// deceleration), so a planned stop is never passed. Resuming rejoins the plan's time once
// w reaches the planned speed. End points are those of the segments: untouched.
// k = w / v_planned is reported as the time scale.
#include "imess/planner/sampler.hpp"

#include <algorithm>
#include <cmath>

namespace imess::planner {

void Sampler::set_position(const Pose& position) noexcept {
  position_ = position;
  has_current_ = has_next_ = false;
  tau_ = carry_ = 0;
  scaled_ = holding_;
  w_ = 0;
  k_ = holding_ ? 0 : 1;
  starving_ = false;
  sample_ = Sample{};
  sample_.pose = position;
}

void Sampler::begin_tick() noexcept {
  sample_.done_count = 0;
  sample_.switch_count = 0;
  sample_.starved = false;
}

void Sampler::promote() noexcept {
  current_ = next_;
  has_current_ = true;
  tau_ = 0;
  if (current_.kind == SegmentKind::SetOutput && sample_.switch_count < static_cast<int>(sample_.switches.size()))
    sample_.switches[sample_.switch_count++] = OutputSwitch{current_.id, current_.output, current_.output_value};
}

void Sampler::complete() noexcept {
  position_ = current_.end;
  has_current_ = false;
  if (sample_.done_count < kMaxCompletionsPerTick)
    sample_.done[sample_.done_count++] = Completion{current_.id, current_.kind, current_.probe, current_.scan.phase};
  if (!has_next_ && current_.v1 > 0 && !scaled_) starving_ = true;  // ran off the end at speed
}

const Sample& Sampler::rest() noexcept {
  sample_.pose = position_;
  sample_.velocity.fill(0);
  sample_.busy = false;
  sample_.held = holding_;
  sample_.starved = starving_;
  starving_ = false;
  w_ = 0;
  scaled_ = holding_;
  k_ = holding_ ? 0 : 1;
  return sample_;
}

const Sample& Sampler::evaluate(double path_speed) noexcept {
  const PathState st = current_.profile.at(tau_);
  Pose d;
  pose_at(current_, st.s, sample_.pose, d);
  for (int i = 0; i < kMaxAxes; ++i) sample_.velocity[i] = path_speed * d[i];
  sample_.busy = true;
  sample_.held = scaled_ && w_ <= 0;
  sample_.starved = starving_;
  return sample_;
}

bool Sampler::update_braking(double dt) noexcept {
  const PathState st = current_.profile.at(tau_);
  const double w = scaled_ ? w_ : st.v;
  // A feeder that fell behind: brake on the path before the last segment's end, and go on
  // when segments arrive again.
  if (!has_next_ && current_.v1 > 0 && current_.a > 0) {
    const double left = current_.length - st.s;
    if (left <= w * w / (2 * current_.a) + 2 * w * dt) starving_ = true;
  } else if (has_next_) {
    starving_ = false;
  }
  const bool braking = holding_ || starving_;
  if (braking && !scaled_) {
    scaled_ = true;
    w_ = st.v;
  }
  return braking;
}

double Sampler::time_at_length(double s) const noexcept {
  double lo = tau_, hi = current_.duration();
  for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    (current_.profile.at(mid).s < s ? lo : hi) = mid;
  }
  return hi;
}

double Sampler::resume_speed(double dw, double dt) const noexcept {
  const double s_now = current_.profile.at(tau_).s;
  double w = w_ + dw;
  for (int round = 0; round < 3; ++round) {
    const double s_end = std::min(current_.length, s_now + 0.5 * (w_ + w) * dt);
    w = std::min(w_ + dw, current_.profile.at(time_at_length(s_end)).v);
  }
  return std::max(w, std::max(0.0, w_ - dw));  // never brakes harder than a
}

const Sample& Sampler::finish_scaled(double w_target, bool braking, double dt) noexcept {
  const double v_plan = current_.profile.at(tau_).v;
  // Caught up with the plan (w could reach its speed within a·dt): back on its time.
  const bool caught_up = !braking && (w_target >= v_plan * (1 - 1e-9) || w_ + current_.a * dt >= v_plan);
  w_ = w_target;
  if (caught_up) {
    scaled_ = false;
    w_ = v_plan;
    k_ = 1;
  } else {
    k_ = v_plan > 0 ? std::min(1.0, w_ / v_plan) : (w_ > 0 ? 1 : 0);
  }
  return evaluate(w_);
}

}  // namespace imess::planner
