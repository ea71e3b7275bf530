// IdealFollower: a MotionBackend test double that follows a planned path perfectly — follow()
// puts every axis exactly at the setpoint — and brakes, moves and latches in a simple 1 ms
// model of its own (read_state advances it one period). It counts follow() calls, can refuse
// the call number N, can be told it cannot follow at all, and has a probe and limit inputs
// the test sets. FollowerRig: the motion core on it in virtual time, with a Planner built
// from the core's resolved configuration as the io side builds it.
#pragma once
#include <array>
#include <cmath>
#include <vector>

#include "core_rig.hpp"
#include "imess/core/path_machine.hpp"
#include "imess/planner/planner.hpp"
#include "imess/planner/probe.hpp"

namespace imess::test {

class IdealFollower final : public hal::MotionBackend {
 public:
  static constexpr double kDt = 0.001;

  void initialise(bool) override {}
  std::string describe() const override { return "ideal follower (test double)"; }

  bool read_state(hal::MachineState& out) noexcept override {
    tick();
    out.position = pos_;
    for (int a = 0; a < 3; ++a) {
      std::uint32_t st = loops_ ? hal::status::kClosedLoop : 0;
      if (kind_ == Kind::Rest) st |= hal::status::kProfileEnd;
      if (kind_ == Kind::Rest && lag_left_ == 0) st |= hal::status::kInPosition;
      if (latch_valid_) st |= hal::status::kLatchValid;
      out.status[a] = st;
      out.inputs[a] = static_cast<std::uint8_t>((tip ? hal::input::kTip : 0) | inputs[a]);
    }
    out.tip_touched = tip;
    return true;
  }
  bool read_latch(hal::AxisVec& latched) noexcept override {
    latched = latch_;
    latch_valid_ = false;
    return true;
  }
  bool set_loops(bool closed) noexcept override {
    loops_ = closed;
    return true;
  }
  bool move(const hal::AxisArray<hal::AxisMove>& moves, unsigned mask) noexcept override {
    for (int a = 0; a < 3; ++a)
      if (mask & (1u << a)) target_[a] = moves[a].target, speed_[a] = moves[a].velocity;
      else target_[a] = pos_[a], speed_[a] = 0;
    kind_ = Kind::Move;
    return true;
  }
  bool follow(const hal::Setpoint& sp) noexcept override {
    ++follow_calls;
    if (!can_follow || follow_calls == fail_at_call) return false;
    pos_ = sp.position;
    vel_ = sp.velocity;
    kind_ = Kind::Follow;
    fresh_ = true;
    if (record) setpoints.push_back(sp);
    return true;
  }
  bool stop(const hal::AxisVec& decel) noexcept override {
    ++stops;
    decel_ = decel;
    if (kind_ == Kind::Move) vel_.setZero();
    if (kind_ == Kind::Follow || kind_ == Kind::Move) kind_ = Kind::Brake;
    return true;
  }
  bool set_position(int axis, double value) noexcept override {
    pos_[axis] = value;
    return true;
  }
  bool reset_faults() noexcept override { return true; }
  int output_count() const noexcept override { return static_cast<int>(outputs.size()); }
  bool output_on(int number) const noexcept override { return number >= 1 && number <= output_count() && outputs[number - 1]; }
  // Records every switch with how many setpoints came before it (the next one is the
  // setpoint of the switching cycle); a probe power output makes the probe's power edge.
  bool set_output(int number, bool on) noexcept override {
    if (number < 1 || number > output_count() || refuse_outputs) return false;
    if (record) switches.push_back({number, on, setpoints.size()});
    const bool changed = outputs[number - 1] != on;
    outputs[number - 1] = on;
    if (changed && number == probe_power_output) touch(), tip = false;
    return true;
  }

  // The probe edge: latched where the axes are now.
  void touch() {
    tip = true;
    latch_ = pos_;
    latch_valid_ = true;
  }
  // The probe edge at a given point (a scene's surface crossed between two cycles).
  void touch_at(const hal::Vec3& where) {
    tip = true;
    latch_.setZero();
    latch_.head<3>() = where;
    latch_valid_ = true;
  }
  const hal::AxisVec& velocity() const { return vel_; }
  hal::Vec3 where() const { return pos_.head<3>(); }  // where the X Y Z axes are now

  struct Switch {
    int number = 0;
    bool on = false;
    std::size_t setpoints_before = 0;
  };
  std::array<bool, 4> outputs{};
  std::vector<Switch> switches;
  bool refuse_outputs = false;
  int probe_power_output = 0;  // 0: no output makes a power edge
  bool can_follow = true;
  long fail_at_call = -1;  // follow() call number (1-based) that returns false
  long follow_calls = 0;
  int stops = 0;
  bool tip = false;
  hal::AxisArray<std::uint8_t> inputs{};
  bool record = true;
  std::vector<hal::Setpoint> setpoints;
  // Cycles from the end of a followed path until the axes report in position (a servo's
  // following error dying out); negative: never.
  int lag_cycles = 0;

 private:
  enum class Kind { Rest, Follow, Brake, Move };
  // One period of the backend's own motion: a followed setpoint holds until the next
  // follow(); braking lowers every axis' speed by its deceleration; a move runs at its speed.
  void tick() {
    if (kind_ == Kind::Rest && lag_left_ > 0) --lag_left_;
    if (kind_ == Kind::Follow && fresh_) {  // the setpoint of the last cycle holds
      fresh_ = false;
      return;
    }
    if (kind_ == Kind::Follow) {  // no new setpoint came last cycle: the path ended
      if (vel_.isZero()) kind_ = Kind::Rest, lag_left_ = lag_cycles;
      else kind_ = Kind::Brake;  // a backend left without setpoints brakes (never happens on a planned path)
      return;
    }
    if (kind_ == Kind::Brake) {
      bool moving = false;
      for (int a = 0; a < 3; ++a) {
        const double v0 = vel_[a];
        double v1 = v0 > 0 ? std::max(0.0, v0 - decel_[a] * kDt) : std::min(0.0, v0 + decel_[a] * kDt);
        pos_[a] += 0.5 * (v0 + v1) * kDt;
        vel_[a] = v1;
        moving = moving || v1 != 0;
      }
      if (!moving) kind_ = Kind::Rest;
      return;
    }
    if (kind_ == Kind::Move) {
      bool there = true;
      for (int a = 0; a < 3; ++a) {
        const double d = target_[a] - pos_[a], step = speed_[a] * kDt;
        if (std::abs(d) <= step) pos_[a] = target_[a];
        else pos_[a] += d > 0 ? step : -step, there = false;
      }
      if (there) kind_ = Kind::Rest;
    }
  }
  // Follow holds between calls: tick() runs before the core's follow() of the same cycle.
  Kind kind_ = Kind::Rest;
  hal::AxisVec pos_ = (hal::AxisVec() << 100, 100, 100, 0, 0, 0, 0, 0, 0).finished(), vel_ = hal::AxisVec::Zero(),
               decel_ = hal::AxisVec::Zero();
  hal::AxisVec target_ = hal::AxisVec::Zero(), speed_ = hal::AxisVec::Zero(), latch_ = hal::AxisVec::Zero();
  bool loops_ = true, latch_valid_ = false, fresh_ = false;
  int lag_left_ = 0;
};

class FollowerRig final : public MotionRig {
 public:
  explicit FollowerRig(core::CoreConfig config = default_config()) {
    start_core(config);
    planner_.emplace(core::path_machine(core_->config()), core::path_options(core_->config()));
    planner::Pose here{};
    for (int a = 0; a < 3; ++a) here[a] = core_->machine().position[a];
    planner_->set_position(here);
  }
  static core::CoreConfig default_config() {
    core::CoreConfig c;
    for (auto& a : c.axes) a.travel_min = 0, a.travel_max = 500, a.max_velocity = 0, a.max_accel = 0;
    c.axes[0].max_velocity = 80, c.axes[0].max_accel = 800;
    c.axes[1].max_velocity = 60, c.axes[1].max_accel = 600;
    c.axes[2].max_velocity = 40, c.axes[2].max_accel = 400;
    c.referenced_at_start = true;
    return c;
  }
  hal::MotionBackend& backend() override { return hw; }

  planner::Planner& planner() { return *planner_; }
  // Appends (throws on refusal), then moves every final segment into the core's ring as far
  // as it has room; returns how many went in.
  void append(const planner::Request& r) {
    auto res = planner_->append(r);
    if (!res.ok()) throw std::runtime_error(planner::describe(res, planner_->machine()));
  }
  int feed(bool flush = false) {
    if (flush) planner_->flush();
    int n = 0;
    planner::PlannedSegment s;
    while (core_->segment_room() > 0 && planner_->take(s)) {
      core::QueuedSegment q{s, core_->stop_ticket(), drops};
      if (!core_->submit_segment(q)) break;
      ++n;
    }
    return n;
  }
  planner::Line line(std::uint32_t id, double x, double y, double z, double f) const {
    planner::Line l;
    l.id = id;
    l.target = {x, y, z};
    l.feed = f;
    return l;
  }
  // The reasons of the Failed events, in order.
  std::vector<core::FailReason> fail_reasons() const {
    std::vector<core::FailReason> out;
    for (auto& e : events_)
      if (e.kind == EventKind::Failed) out.push_back(e.fail);
    return out;
  }
  std::vector<std::uint32_t> ids(EventKind k) const {
    std::vector<std::uint32_t> out;
    for (auto& e : events_)
      if (e.kind == k) out.push_back(e.id);
    return out;
  }

  IdealFollower hw;
  std::uint32_t drops = 0;

 private:
  std::optional<planner::Planner> planner_;
};

// Queues Probe `id` toward `target` (X Y Z) from where the planner stands, as the io side
// does: the approach at `feed` (when the target is beyond the prehit distance), then the search.
inline void queue_probe(FollowerRig& rig, std::uint32_t id, hal::Vec3 target, double feed = 50) {
  const auto& p = rig.core().params();
  planner::Pose t = rig.planner().position();
  for (int a = 0; a < 3; ++a) t[a] = target[a];
  auto c = planner::probe_cycle(id, rig.planner().position(), t, {p.prehit_distance, p.search_distance, feed, p.probe_speed});
  REQUIRE(c);
  if (c->approach) rig.append(*c->approach);
  rig.append(c->search);
}

}  // namespace imess::test
