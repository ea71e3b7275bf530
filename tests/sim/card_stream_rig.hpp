// StreamRig: the motion core on the simulated servo-card CMM whose card is streamed over a
// 115 200 baud serial line (sim::TimedCardLink, virtual time), with a planner feeding the
// core's segment ring as the io thread does; per cycle it records what the tests measure.
#pragma once
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core_rig.hpp"
#include "imess/core/path_machine.hpp"
#include "imess/planner/planner.hpp"

namespace imess::test {

inline RigOptions streamed_options() {
  RigOptions o = default_options();
  o.sim.streamed = true;
  return o;
}

inline planner::Pose pose_of(const Vec3& v) {
  planner::Pose p{};
  for (int a = 0; a < 3; ++a) p[a] = v[a];
  return p;
}

// Lines of at most chord mm along `turns` circles of radius r in the XY plane, starting (and
// ending) at start, the centre r to +X of it, counter-clockwise; ids from 1.
inline std::vector<planner::Request> chord_circle(const Vec3& start, double r, double chord, int turns, double feed) {
  const Vec3 centre = start + Vec3(r, 0, 0);
  const int n = static_cast<int>(std::ceil(M_PI / std::asin(chord / (2 * r))));
  std::vector<planner::Request> out;
  for (int i = 1; i <= n * turns; ++i) {
    const double phi = M_PI + 2 * M_PI * i / n;
    planner::Line l;
    l.id = static_cast<std::uint32_t>(i);
    l.target = pose_of(centre + r * Vec3(std::cos(phi), std::sin(phi), 0));
    l.feed = feed;
    out.push_back(l);
  }
  return out;
}

class StreamRig {
 public:
  explicit StreamRig(RigOptions o = streamed_options())
      : rig(o), planner_(core::path_machine(rig.core().config()), core::path_options(rig.core().config())) {
    planner_.set_position(pose_of(rig.position()));
  }

  void queue(const std::vector<planner::Request>& requests) {
    for (const auto& r : requests) {
      const auto res = planner_.append(r);
      INFO(planner::describe(res, planner_.machine()));
      REQUIRE(res.ok());
    }
    planner_.flush();
  }
  // After the loop dropped the queue (a fault, a host stall): plans from where the machine stands.
  void queue_from_here(const std::vector<planner::Request>& requests) {
    planner_.set_position(pose_of(rig.position()));
    queue(requests);
  }
  // One motion period: the ring topped up (stamped with the loop's drop count, as the io side
  // does), the core's cycle. A drop discards what the planner still holds, as the io side does.
  void step() {
    planner::PlannedSegment s;
    while (rig.core().segment_room() > 0 && planner_.take(s)) REQUIRE(rig.core().submit_segment({s, rig.core().stop_ticket(), drops_}));
    rig.step();
    for (const auto& e : rig.events())
      if (e.kind == EventKind::QueueDropped && e.id > drops_) {
        drops_ = e.id;
        while (planner_.take(s)) {
        }
      }
  }
  bool run_until(const std::function<bool()>& pred, double max_seconds) {
    for (long i = 0, n = static_cast<long>(max_seconds * 1000); i < n; ++i) {
      if (pred()) return true;
      step();
    }
    return pred();
  }
  bool comm_lost() const { return faulted(core::FaultKind::CommLost); }
  bool faulted(core::FaultKind kind) const {
    for (const auto& e : rig.events())
      if (e.kind == EventKind::Fault && e.fault == kind) return true;
    return false;
  }

  sim::TimedCardLink& line() { return rig.cmm().line(); }
  sim::EmulatedCard& card() { return rig.cmm().card(); }
  const hal::CardStreamSession& session() { return *rig.driver().stream(); }

  CoreRig rig;

 private:
  planner::Planner planner_;
  std::uint32_t drops_ = 0;  // the loop's queue drops seen (QueueDropped)
};

}  // namespace imess::test
