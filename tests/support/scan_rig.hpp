// Scans in virtual time: the motion core on the simulated CMM whose probe measures its
// deflection (either card link), a planner feeding it scan segments as the io side does, and
// what a scan leaves — its points, the deflection on every cycle, its end. Shared by the scan
// tests (tests/core/test_scan.cpp, test_scan_contour.cpp) and the allocation test.
#pragma once
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core_rig.hpp"
#include "imess/planner/planner.hpp"
#include "imess/planner/scan.hpp"

namespace imess::test {

// The default simulated CMM with a measuring probe (ball 2 mm, range 1 mm, no noise) at start.
inline RigOptions analog_options(const Vec3& start, bool streamed) {
  RigOptions o = default_options();
  o.sim.mechanics.probe.ball_radius = 2.0;
  o.sim.mechanics.probe.type = sim::ProbeType::Analog;
  o.sim.mechanics.probe.analog.range = 1.0;
  o.sim.mechanics.probe.analog.noise = 0;
  o.sim.mechanics.start = axes3(start);
  o.sim.streamed = streamed;
  return o;
}

// The planner's machine: the simulated CMM's travel (1000 × 1000 × 600 mm).
inline planner::Machine scan_machine() {
  planner::Machine m = planner::make_machine("XYZ", 0, 1000, 150, 1000);
  m.axes[2].travel_max = 600;
  return m;
}

// Plans a scan from where the machine stands and hands every segment to the core (the ring
// holds a scan's few segments); the shape's refusal fails the test. The number of requests.
inline std::size_t queue_scan(MotionRig& rig, std::uint32_t id, const planner::ScanShape& shape,
                              const planner::ScanSettings& s) {
  planner::Planner plan(scan_machine());
  planner::Pose here{};
  for (int a = 0; a < 3; ++a) here[a] = rig.position()[a];
  plan.set_position(here);
  const auto requests = planner::scan_requests(id, here, shape, s);
  if (const auto* why = std::get_if<std::string>(&requests)) FAIL(*why);
  const auto& list = std::get<std::vector<planner::Request>>(requests);
  for (const auto& r : list) {
    const auto res = plan.append(r);
    INFO(planner::describe(res, plan.machine()));
    REQUIRE(res.ok());
  }
  plan.flush();
  planner::PlannedSegment seg;
  while (plan.take(seg)) REQUIRE(rig.core().submit_segment({seg, rig.core().stop_ticket(), 0}));
  return list.size();
}

class ScanRig {
 public:
  ScanRig(const Vec3& start, bool streamed) : rig_(analog_options(start, streamed)) { rig_.run(0.2); }

  // The scan queued from where the machine stands; the number of its requests.
  std::size_t plan(std::uint32_t id, const planner::ScanShape& shape, const planner::ScanSettings& s) {
    return queue_scan(rig_, id, shape, s);
  }

  // Runs until the scan's id ends (Done or Failed) or max_s passes, recording every cycle's
  // deflection and the points so far.
  void run(std::uint32_t id, double max_s) {
    for (long i = 0; i < static_cast<long>(max_s * 1000); ++i) {
      rig_.step();
      const auto& ms = rig_.core().machine();
      for (const auto& e : rig_.events()) {
        if (e.kind == EventKind::ScanPt) points.push_back(e);
        if ((e.kind == EventKind::Done || e.kind == EventKind::Failed) && e.id == id) end = e;
      }
      deflections.push_back(ms.deflection.norm());
      point_counts.push_back(points.size());
      over_range = over_range || ms.probe_over_range;
      rig_.clear_events();
      if (end) break;
    }
    rig_.run(0.05);
  }

  // The deflection on every cycle from the first point (less `skip` cycles of settling after
  // the approach's corner) to the last.
  std::vector<double> following(std::size_t skip) const {
    std::vector<double> out;
    std::size_t first = 0, last = 0;
    for (std::size_t i = 0; i < point_counts.size(); ++i) {
      if (point_counts[i] == 0) first = i + 1;
      if (point_counts[i] < points.size()) last = i;
    }
    for (std::size_t i = first + skip; i <= last && i < deflections.size(); ++i) out.push_back(deflections[i]);
    return out;
  }

  // The largest distance of the points from the true surface, mm.
  double worst_surface_error() {
    double worst = 0;
    for (const auto& p : points) worst = std::max(worst, std::fabs(scene().distance(p.p)));
    return worst;
  }
  const sim::Scene& scene() { return rig_.mechanics().scene(); }
  CoreRig& core_rig() { return rig_; }

  std::vector<Event> points;
  std::vector<double> deflections;
  std::vector<std::size_t> point_counts;
  std::optional<Event> end;
  bool over_range = false;

 private:
  CoreRig rig_;
};

}  // namespace imess::test
