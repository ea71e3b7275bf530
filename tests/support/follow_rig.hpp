// Path following on the port backends in virtual time: a planner::Planner plans a path
// (limits from the driver's configuration), a planner::Sampler samples it every servo
// period, and each sample goes to the real driver's follow() (simulated port space,
// StepperMachine / DriveKitSim behind it). The stepper run pumps the base routine tick by
// tick so the decoded step count can be compared with the sampled path between samples.
#pragma once
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "imess/planner/planner.hpp"
#include "imess/planner/sampler.hpp"
#include "port_rigs.hpp"
#include "poses.hpp"

namespace imess::test {


// The planner's machine: travel from the simulated mechanics, speed and acceleration per
// axis from the driver's configuration.
template <class AxisConfigs>
planner::Machine follow_machine(const sim::MechanicsConfig& mech, const AxisConfigs& axes) {
  planner::Machine m = planner::make_machine("XYZ", 0, 1000, 10, 100);
  for (int a = 0; a < 3; ++a) {
    m.axes[a].travel_min = mech.axes[a].travel_min;
    m.axes[a].travel_max = mech.axes[a].travel_max;
    m.axes[a].max_velocity = axes[a].max_speed;
    m.axes[a].max_accel = axes[a].max_accel;
  }
  return m;
}

// Planner + sampler: plan() appends and flushes a whole path; next() is one servo period's
// setpoint (the sample at the period's end).
class PathFeed {
 public:
  PathFeed(const planner::Machine& m, const hal::Vec3& start)
      : planner_(m), sampler_(pose3(start)), ring_(std::make_unique<planner::SegmentBuffer<1024>>()) {
    planner_.set_position(pose3(start));
  }
  void restart(const hal::Vec3& at) {
    planner_.set_position(pose3(at));
    sampler_.set_position(pose3(at));
  }
  void plan(const std::vector<planner::Request>& requests) {
    for (const auto& r : requests) {
      const auto res = planner_.append(r);
      INFO(planner::describe(res, planner_.machine()));
      REQUIRE(res.ok());
    }
    planner_.flush();
    planner::PlannedSegment s;
    while (planner_.take(s)) REQUIRE(ring_->push(s));
  }
  hal::Setpoint next() noexcept {
    const planner::Sample& smp = sampler_.advance(0.001, [this](planner::PlannedSegment& s) { return ring_->pop(s); });
    busy_ = smp.busy;
    return {axes3(vec3(smp.pose)), axes3(vec3(smp.velocity))};
  }
  bool done() const noexcept { return !busy_ && sampler_.idle(); }
  hal::Vec3 end() const { return vec3(planner_.position()); }

 private:
  planner::Planner planner_;
  planner::Sampler sampler_;
  std::unique_ptr<planner::SegmentBuffer<1024>> ring_;
  bool busy_ = true;
};

// Lines with corners, an XY arc, a dwell and a three-axis diagonal, around start.
inline std::vector<planner::Request> corner_arc_dwell_path(const hal::Vec3& s, double feed) {
  using namespace planner;
  std::vector<Request> r;
  r.push_back(Line{1, pose3(s + hal::Vec3(40, 0, 0)), feed});
  r.push_back(Line{2, pose3(s + hal::Vec3(40, 30, -20)), feed * 0.75});
  Arc arc;
  arc.id = 3;
  arc.target = pose3(s + hal::Vec3(40, 60, -20));
  arc.centre = {s.x() + 40, s.y() + 45, s.z() - 20};
  arc.ccw = true;  // the half circle on the +X side
  arc.feed = feed;
  r.push_back(arc);
  r.push_back(Dwell{4, 0.05});
  r.push_back(Line{5, pose3(s + hal::Vec3(-10, 60, -20)), feed});
  r.push_back(Line{6, pose3(s), feed});
  return r;
}

// Seeded random path inside ±box of start: lines (some tiny), arcs in XY, dwells.
inline std::vector<planner::Request> random_path(const hal::Vec3& s, double box, double vmax, std::uint32_t seed,
                                                 int count = 25) {
  using namespace planner;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), feed(0.05, 1.0), unit(0, 1);
  std::vector<Request> r;
  hal::Vec3 p = s;
  for (int i = 0; i < count; ++i) {
    const auto id = static_cast<std::uint32_t>(i + 1);
    const double pick = unit(rng);
    if (pick < 0.1) {
      r.push_back(Dwell{id, 0.002 + 0.03 * unit(rng)});
    } else if (pick < 0.3) {  // an arc about a centre r away, swept up to 3/4 turn
      const double radius = 2 + 10 * unit(rng);
      const double a0 = 6.2831853 * unit(rng);
      hal::Vec3 c = p - radius * hal::Vec3(std::cos(a0), std::sin(a0), 0);
      bool inside = true;
      for (int a = 0; a < 2; ++a) inside = inside && std::abs(c[a] - s[a]) + radius < box;
      if (!inside) continue;
      const bool ccw = unit(rng) < 0.5;
      const double sweep = (ccw ? 1 : -1) * 4.712 * unit(rng) + (ccw ? 0.3 : -0.3);
      hal::Vec3 end = c + radius * hal::Vec3(std::cos(a0 + sweep), std::sin(a0 + sweep), 0);
      end.z() = std::clamp(p.z() + 5 * u(rng), s.z() - box, s.z() + box);  // a helix now and then
      Arc arc;
      arc.id = id;
      arc.target = pose3(end);
      arc.centre = {c.x(), c.y(), p.z()};
      arc.ccw = ccw;
      arc.feed = vmax * feed(rng);
      r.push_back(arc);
      p = end;
    } else {
      const double reach = unit(rng) < 0.2 ? 0.05 : box;  // short moves test the rounding
      hal::Vec3 q = p + reach * hal::Vec3(u(rng), u(rng), u(rng));
      for (int a = 0; a < 3; ++a) q[a] = std::clamp(q[a], s[a] - box, s[a] + box);
      r.push_back(Line{id, pose3(q), vmax * feed(rng)});
      p = q;
    }
  }
  return r;
}

// ------------------------------------------------------------------ stepper

struct StepperFigures {
  double max_error_steps = 0;      // |decoded − sampled path (interpolated)| while moving
  double max_error_over_bound = -1e9;  // the worst (error − (1 step + speed × base period))
  std::uint64_t min_step_interval = std::numeric_limits<std::uint64_t>::max();  // base periods
  long late_periods = 0;           // servo periods that ended before all their steps were out
  long periods = 0;
  long worst_period = -1;          // where the worst error was (periods since the run began)
  int worst_axis = -1;
};

// Drives a StepperRig's backend period by period, the base routine tick by tick.
class StepperFollowRun {
 public:
  explicit StepperFollowRun(StepperRig& rig) : rig_(rig) {
    const auto& d = rig.options().driver;
    base_ns_ = static_cast<std::int64_t>(d.base_period_ns);
    ticks_per_period_ = static_cast<int>(MotionRig::kPeriod.count() / base_ns_);
    for (int a = 0; a < 3; ++a) {
      spm_[a] = d.axes[a].steps_per_mm;
      last_[a] = rig.stepper().steps(a);
    }
    cycle();
    REQUIRE(rig.backend().set_loops(true));
    prev_ = cur_ = ref(xyz(state_.position));
  }

  // One servo period: base ticks up to its end (measured), read_state, then follow(sp).
  void cycle(const hal::Setpoint* sp = nullptr) {
    for (int i = 1; i <= ticks_per_period_; ++i) {
      rig_.clock().advance(hal::Nanos(base_ns_));
      rig_.pump().advance_to(rig_.clock().now());
      ++tick_;
      for (int a = 0; a < 3; ++a) {
        const std::int64_t c = rig_.stepper().steps(a);
        if (c != last_[a]) {
          if (have_step_[a]) f_.min_step_interval = std::min<std::uint64_t>(f_.min_step_interval, tick_ - last_tick_[a]);
          have_step_[a] = true;
          last_tick_[a] = tick_;
          last_[a] = c;
        }
        if (measuring_) {
          const double r = prev_[a] + (cur_[a] - prev_[a]) * i / ticks_per_period_;
          const double err = std::abs(static_cast<double>(c) - r);
          const double bound = 1 + speed_[a] * static_cast<double>(base_ns_) * 1e-9;
          if (err > f_.max_error_steps) {
            f_.max_error_steps = err;
            f_.worst_period = period_;
            f_.worst_axis = a;
          }
          f_.max_error_over_bound = std::max(f_.max_error_over_bound, err - bound);
        }
      }
    }
    if (measuring_) {
      ++f_.periods;
      for (int a = 0; a < 3; ++a)
        if (rig_.stepper().steps(a) != target_[a]) {
          ++f_.late_periods;
          break;
        }
    }
    REQUIRE(rig_.backend().read_state(state_));
    ++period_;
    measuring_ = false;
    if (!sp)  // not following: the next path starts where the axes are
      for (int a = 0; a < 3; ++a) cur_[a] = static_cast<double>(rig_.stepper().steps(a));
    if (sp) {
      REQUIRE(rig_.backend().follow(*sp));
      prev_ = cur_;
      cur_ = ref(xyz(sp->position));
      for (int a = 0; a < 3; ++a) {
        speed_[a] = std::max(std::abs(last_velocity_[a]), std::abs(sp->velocity[a])) * spm_[a];
        target_[a] = rig_.driver().steps_for(a, sp->position[a]);
      }
      last_velocity_ = xyz(sp->velocity);
      measuring_ = true;
    }
  }
  // stop() instead of the next setpoint: the period after it is braking, not the path.
  bool stop(const hal::Vec3& decel) {
    measuring_ = false;
    return rig_.backend().stop(axes3(decel));
  }
  // Follows the whole path, then as many periods as the sampler holds still.
  void follow(PathFeed& feed, int settle_periods = 20) {
    while (!feed.done()) {
      const hal::Setpoint sp = feed.next();
      last_sp_ = sp;
      cycle(&sp);
    }
    for (int i = 0; i < settle_periods; ++i) {
      const hal::Setpoint sp = feed.next();
      last_sp_ = sp;
      cycle(&sp);
    }
  }
  // Periods without follow() until every axis reports the end of its profile.
  bool settle(int max_periods = 5000) {
    for (int i = 0; i < max_periods; ++i) {
      if (state_.motion_done() && state_.all(hal::status::kInPosition)) return true;
      cycle();
    }
    return false;
  }
  // The step count of the stepper machine (decoded edges) per axis.
  std::int64_t decoded(int a) const { return rig_.stepper().steps(a); }
  const hal::MachineState& state() const { return state_; }
  const StepperFigures& figures() const { return f_; }
  const hal::Setpoint& last_setpoint() const { return last_sp_; }

 private:
  hal::Vec3 ref(const hal::Vec3& mm) const {
    hal::Vec3 r;
    for (int a = 0; a < 3; ++a) r[a] = mm[a] * spm_[a] + static_cast<double>(rig_.driver().steps_for(a, 0));
    return r;
  }
  StepperRig& rig_;
  std::int64_t base_ns_ = 0;
  int ticks_per_period_ = 0;
  std::uint64_t tick_ = 0;
  long period_ = 0;
  hal::Vec3 spm_ = hal::Vec3::Zero(), prev_ = hal::Vec3::Zero(), cur_ = hal::Vec3::Zero(), speed_ = hal::Vec3::Zero();
  hal::Vec3 last_velocity_ = hal::Vec3::Zero();
  hal::AxisArray<std::int64_t> last_{}, target_{};
  hal::AxisArray<std::uint64_t> last_tick_{};
  hal::AxisArray<bool> have_step_{};
  bool measuring_ = false;
  hal::MachineState state_{};
  hal::Setpoint last_sp_{};
  StepperFigures f_;
};

// ------------------------------------------------------------------ drive kit

struct DriveFigures {
  double max_path_error = 0;  // |encoder − setpoint| at the servo instants, mm
  bool faulted = false;
};

class DriveFollowRun {
 public:
  explicit DriveFollowRun(DriveRig& rig) : rig_(rig) {
    cycle();
    REQUIRE(rig.backend().set_loops(true));
  }
  void cycle(const hal::Setpoint* sp = nullptr) {
    rig_.clock().advance(MotionRig::kPeriod);
    REQUIRE(rig_.backend().read_state(state_));
    f_.faulted = f_.faulted || state_.faulted();
    if (measuring_)
      for (int a = 0; a < 3; ++a) f_.max_path_error = std::max(f_.max_path_error, std::abs(state_.position[a] - last_sp_.position[a]));
    measuring_ = false;
    if (sp) {
      REQUIRE(rig_.backend().follow(*sp));
      last_sp_ = *sp;
      measuring_ = true;
    }
  }
  void follow(PathFeed& feed, int settle_periods = 200) {
    while (!feed.done()) {
      const hal::Setpoint sp = feed.next();
      cycle(&sp);
    }
    for (int i = 0; i < settle_periods; ++i) {
      const hal::Setpoint sp = feed.next();
      cycle(&sp);
    }
  }
  bool settle(int max_periods = 5000) {
    for (int i = 0; i < max_periods; ++i) {
      if (state_.motion_done() && state_.all(hal::status::kInPosition)) return true;
      cycle();
    }
    return false;
  }
  const hal::MachineState& state() const { return state_; }
  const DriveFigures& figures() const { return f_; }
  const hal::Setpoint& last_setpoint() const { return last_sp_; }

 private:
  DriveRig& rig_;
  hal::MachineState state_{};
  hal::Setpoint last_sp_{};
  bool measuring_ = false;
  DriveFigures f_;
};

}  // namespace imess::test
