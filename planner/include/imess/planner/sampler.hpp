// Sampler: the real-time side. Holds the current PlannedSegment and the time into it;
// advance(dt) gives the pose and velocity at the new time, moves on to the next segment
// carrying the leftover time (junctions are continuous), reports the ids that completed,
// and comes to rest at the end of the queue. Feed hold brakes along the path (sampler.cpp).
// Everything here is noexcept and allocation-free; sizes are fixed at compile time.
// Measured cost: see bench/bench_planner.cpp and docs/architecture.md ("Planner").
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "imess/planner/segment.hpp"

namespace imess::planner {

// A segment that ended this tick: the daemon answers `Done id`.
struct Completion {
  std::uint32_t id = 0;
  SegmentKind kind = SegmentKind::Line;
  ProbePhase probe = ProbePhase::None;
  ScanPhase scan = ScanPhase::None;
};

// A SetOutput segment that began this tick (the path before it has come to rest): the
// daemon switches the output now; the segment completes after its hold.
struct OutputSwitch {
  std::uint32_t id = 0;
  std::uint16_t output = 0;
  double value = 0;
};

inline constexpr int kMaxCompletionsPerTick = 16;

struct Sample {
  Pose pose{};      // where every axis is commanded to be now
  Pose velocity{};  // axis units per second
  std::array<Completion, kMaxCompletionsPerTick> done{};
  int done_count = 0;
  // In the order they began; a tick begins at most one segment more than it completes.
  std::array<OutputSwitch, kMaxCompletionsPerTick + 1> switches{};
  int switch_count = 0;
  bool busy = false;     // a segment is in progress
  bool held = false;     // a feed hold (or a starved queue) brought the path to rest
  bool starved = false;  // the segments ran out while the last one ended above rest: the
                         // sampler braked on the path (auto hold); it goes on when more arrive
};

// A fixed-size FIFO of segments for a single thread (tests, a feeder that fills one slot
// at a time). Across threads use an SPSC ring (core/queues.hpp) and pass its pop.
template <std::size_t N>
class SegmentBuffer {
 public:
  bool push(const PlannedSegment& s) noexcept {
    if (size_ == N) return false;
    items_[(head_ + size_++) % N] = s;
    return true;
  }
  bool pop(PlannedSegment& s) noexcept {
    if (size_ == 0) return false;
    s = items_[head_];
    head_ = (head_ + 1) % N;
    --size_;
    return true;
  }
  std::size_t size() const noexcept { return size_; }
  bool full() const noexcept { return size_ == N; }

 private:
  std::array<PlannedSegment, N> items_{};
  std::size_t head_ = 0, size_ = 0;
};

class Sampler {
 public:
  explicit Sampler(const Pose& position = {}) noexcept { set_position(position); }

  // Where the machine is; drops the current and the buffered segment (after a stop).
  void set_position(const Pose& position) noexcept;

  // Advances by dt seconds. `pop(PlannedSegment&) -> bool` gives the next final segment in
  // order, or false when none is there yet. It is called at most a few times per tick.
  template <class Pop>
  const Sample& advance(double dt, Pop&& pop) noexcept {
    begin_tick();
    return advance_tick(dt, pop);
  }

  // Feed hold: decelerate along the path (at the segment's path acceleration) to rest;
  // resume() accelerates back to the planned speed. The path and its end points do not change.
  void hold() noexcept { holding_ = true; }
  void resume() noexcept { holding_ = false; }
  bool holding() const noexcept { return holding_; }
  double time_scale() const noexcept { return k_; }
  bool idle() const noexcept { return !has_current_ && !has_next_; }
  const Sample& last() const noexcept { return sample_; }
  // The segment the last sample lies on (nullptr at rest after the queue), and how far into
  // it, 0 … 1 of its time.
  const PlannedSegment* current() const noexcept { return has_current_ ? &current_ : nullptr; }
  double current_fraction() const noexcept {
    return has_current_ && current_.duration() > 0 ? std::clamp(tau_ / current_.duration(), 0.0, 1.0) : 0.0;
  }

 private:
  void begin_tick() noexcept;
  // A feed hold keeps an output from switching: the path waits at rest before a SetOutput
  // until resume() (a segment braking to its planned stop reaches it while holding).
  bool may_promote() const noexcept { return !(holding_ && next_.kind == SegmentKind::SetOutput); }
  void promote() noexcept;
  void complete() noexcept;
  const Sample& rest() noexcept;
  const Sample& evaluate(double path_speed) noexcept;
  // Starts braking (hold, or a starving queue) and reports whether it is braking.
  bool update_braking(double dt) noexcept;
  // Profile time at which the current segment reaches path length s (≥ tau_), by bisection.
  double time_at_length(double s) const noexcept;
  // Resuming: w + a·dt, but never above the planned speed where the tick ends (the plan
  // may be braking toward a junction there).
  double resume_speed(double dw, double dt) const noexcept;
  // After the distance of a scaled tick: the new speed, and back to the plan when reached.
  const Sample& finish_scaled(double w_target, bool braking, double dt) noexcept;

  // The tick after begin_tick(): what advance() does (advance_scaled comes back here when the
  // plan is at rest, within the same tick: its completions and switches are kept).
  template <class Pop>
  const Sample& advance_tick(double dt, Pop&& pop) noexcept {
    if (!has_next_) has_next_ = pop(next_);
    if (!has_current_ && has_next_ && may_promote()) promote(), has_next_ = pop(next_);
    if (!has_current_) return rest();
    const bool braking = update_braking(dt);
    if (scaled_) return advance_scaled(dt, braking, pop);
    double dtau = dt + carry_;
    carry_ = 0;
    while (tau_ + dtau >= current_.duration()) {
      dtau -= current_.duration() - tau_;
      complete();
      if (!has_next_ || !may_promote()) return rest();
      promote();
      has_next_ = pop(next_);
      if (sample_.done_count == kMaxCompletionsPerTick) {  // zero-time segments pile up: later
        carry_ = dtau;
        dtau = 0;
        break;
      }
    }
    tau_ += dtau;
    return evaluate(current_.profile.at(tau_).v);
  }

  // A scaled tick: the path speed w changes by the path acceleration a·dt (down while
  // braking, up while resuming), the tick covers ½(w + w_new)·dt of path, and τ is found
  // where the profile has covered that length. Resuming rejoins the plan (k = 1) once w
  // reaches the planned speed there.
  template <class Pop>
  const Sample& advance_scaled(double dt, bool braking, Pop&& pop) noexcept {
    if (!braking && current_.length <= 0) {  // the plan itself is at rest here: follow it
      scaled_ = false;
      k_ = 1;
      return advance_tick(dt, pop);
    }
    const double a = current_.a;
    const double w_target = braking ? std::max(0.0, w_ - a * dt) : resume_speed(a * dt, dt);
    double d = 0.5 * (w_ + w_target) * dt;
    while (true) {
      if (current_.length <= 0) {
        if (current_.duration() > 0) break;  // a dwell: held where it is
      } else {
        const double s_now = current_.profile.at(tau_).s;
        if (d < current_.length - s_now) {
          if (d > 0) tau_ = time_at_length(s_now + d);
          break;
        }
        d -= current_.length - s_now;
      }
      complete();
      if (!has_next_ || !may_promote()) return rest();
      promote();
      has_next_ = pop(next_);
      if (braking && current_.v0 <= 0) d = 0;  // never past a planned stop while braking
      if (sample_.done_count == kMaxCompletionsPerTick) break;
    }
    return finish_scaled(w_target, braking, dt);
  }

  PlannedSegment current_{}, next_{};
  bool has_current_ = false, has_next_ = false;
  double tau_ = 0;    // profile time into current_
  double carry_ = 0;  // profile time left over from a tick that completed too many segments
  double k_ = 1;    // time scale: planned speed / actual speed (1: on the plan's time)
  double w_ = 0;    // path speed while scaled
  bool scaled_ = false;  // braking or resuming: off the plan's time, on its path
  bool holding_ = false, starving_ = false;
  Pose position_{};
  Sample sample_{};
};

}  // namespace imess::planner
