// The MRM arm (config/sim-mrm-arm.json: X Y linear, C U V rotary, drive kits on port map A)
// driven by the motion core over its simulated drive kits: one coordinated segment moves all
// five axes together within their own limits; jogs of a rotary and a linear axis; soft limits
// per axis.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "config_rig.hpp"
#include "imess/core/path_machine.hpp"

using namespace imess;
using namespace imess::test;

namespace {

const std::string kArm = std::string(IMESS_SOURCE_DIR) + "/config/sim-mrm-arm.json";

struct Recorder {
  std::vector<hal::AxisVec> positions;  // per cycle, encoder positions
  std::vector<core::Event> events;
};

void run(ConfigRig& rig, Recorder& r, int cycles) {
  for (int i = 0; i < cycles; ++i) {
    rig.step([&](const core::Event& e) { r.events.push_back(e); });
    r.positions.push_back(rig.core().snapshot().position);
  }
}

bool has(const Recorder& r, core::EventKind k, std::uint32_t id = 0) {
  return std::any_of(r.events.begin(), r.events.end(), [&](const core::Event& e) { return e.kind == k && e.id == id; });
}

// Queues one straight line to target through the planner the daemon builds from the core.
void queue_line(ConfigRig& rig, std::uint32_t id, const hal::AxisVec& target, double feed) {
  planner::Planner p(core::path_machine(rig.core().config()), core::path_options(rig.core().config()));
  planner::Pose here{};
  const auto& pos = rig.core().snapshot().position;
  for (int a = 0; a < 5; ++a) here[a] = pos[a];
  p.set_position(here);
  planner::Line l;
  l.id = id;
  l.feed = feed;
  l.target = here;
  for (int a = 0; a < 5; ++a) l.target[a] = target[a];
  REQUIRE(p.append(l).ok());
  p.flush();
  planner::PlannedSegment seg;
  while (p.take(seg)) REQUIRE(rig.core().submit_segment({seg, rig.core().stop_ticket(), 0}));
}

}  // namespace

TEST_CASE("the MRM arm config: five axes X Y C U V, C U V rotary, drive kits on port map A") {
  ConfigRig rig(kArm);
  const auto& l = rig.core().config().layout;
  CHECK(l.names() == "XYCUV");
  CHECK(l.kinds[0] == hal::AxisKind::Linear);
  CHECK(l.kinds[1] == hal::AxisKind::Linear);
  for (int a = 2; a < 5; ++a) CHECK(l.kinds[a] == hal::AxisKind::Rotary);
  const auto& d = rig.config().ports.drive;
  for (int a = 0; a < 5; ++a) {
    CHECK(d.axes[a].command_port == 0x301 + a);   // BRIEF §5 map A: command 0x301-0x305
    CHECK(d.axes[a].position_port == 0x306 + a);  // position 0x306-0x30A
  }
  CHECK(d.sync_port == 0x300);
  CHECK(rig.machine().backend().describe().find("drive kit") != std::string::npos);
  CHECK(rig.core().snapshot().position.head<5>().isApprox((hal::AxisVec() << 200, 150, 0, 0, 0, 0, 0, 0, 0).finished().head<5>()));
}

TEST_CASE("the MRM arm: one MoveTo segment moves all five axes together, each within its own limits") {
  ConfigRig rig(kArm);
  const auto& cfg = rig.core().config();
  Recorder r;
  run(rig, r, 20);
  const hal::AxisVec start = rig.core().snapshot().position;
  const hal::AxisVec target = (hal::AxisVec() << 320, 90, 120, -60, 75, 0, 0, 0, 0).finished();
  queue_line(rig, 7, target, 40);
  const std::size_t t0 = r.positions.size();
  for (int i = 0; i < 20000 && !has(r, core::EventKind::Done, 7); i += 10) run(rig, r, 10);
  REQUIRE(has(r, core::EventKind::Done, 7));
  CHECK_FALSE(has(r, core::EventKind::Failed, 7));
  run(rig, r, 300);  // settle
  const hal::AxisVec end = rig.core().snapshot().position;

  // Every axis reaches its target (0.02 in position, one count of 0.01).
  for (int a = 0; a < 5; ++a) {
    INFO("axis " << cfg.layout.letters[a]);
    CHECK(std::abs(end[a] - target[a]) <= 0.03);
  }
  // Start and end per axis: the first cycle 2 % of its way along, the first cycle within 2 %
  // of its end. All five within two periods of each other: one segment, one time base.
  std::array<long, 5> first{}, last{};
  for (int a = 0; a < 5; ++a) {
    const double span = target[a] - start[a];
    first[a] = last[a] = -1;
    for (std::size_t i = t0; i < r.positions.size(); ++i) {
      const double f = (r.positions[i][a] - start[a]) / span;
      if (first[a] < 0 && f > 0.02) first[a] = static_cast<long>(i);
      if (last[a] < 0 && f > 0.98) last[a] = static_cast<long>(i);
    }
    REQUIRE(first[a] > 0);
    REQUIRE(last[a] > 0);
  }
  const auto [fmin, fmax] = std::minmax_element(first.begin(), first.end());
  const auto [lmin, lmax] = std::minmax_element(last.begin(), last.end());
  CHECK(*fmax - *fmin <= 2);
  CHECK(*lmax - *lmin <= 2);
  WARN("arm segment: starts within " << (*fmax - *fmin) << " periods, ends within " << (*lmax - *lmin) << " periods, "
       << (*lmax - *fmin) << " ms along");

  // Speed and acceleration per axis, from the encoders over 10 ms windows (a count of 0.01
  // is 1 unit/s of speed there): within the axis' own limits.
  constexpr int w = 10;
  constexpr double dt = w * 1e-3;
  for (int a = 0; a < 5; ++a) {
    INFO("axis " << cfg.layout.letters[a]);
    double vmax = 0, amax = 0, vprev = 0;
    for (std::size_t i = t0 + w; i < r.positions.size(); i += w) {
      const double v = (r.positions[i][a] - r.positions[i - w][a]) / dt;
      vmax = std::max(vmax, std::abs(v));
      amax = std::max(amax, std::abs(v - vprev) / dt);
      vprev = v;
    }
    CHECK(vmax <= cfg.axes[a].max_velocity * 1.04 + 1.0);
    CHECK(amax <= cfg.axes[a].max_accel * 1.1 + 200.0);
    CHECK(vmax > 1.0);  // it did move
  }
}

TEST_CASE("the MRM arm: jog a rotary axis (C) and a linear one (Y) — soft limits per axis once homed") {
  ConfigRig rig(kArm);
  Recorder r;
  core::Command home{core::CommandKind::Home};
  rig.core().submit(home);
  for (int i = 0; i < 400 && !has(r, core::EventKind::Homed); ++i) run(rig, r, 250);
  REQUIRE(has(r, core::EventKind::Homed));
  run(rig, r, 200);
  const auto& cfg = rig.core().config();

  // C at 50 % of MaxSpeed (50): 25 deg/s, the other axes stand.
  hal::AxisVec before = rig.core().snapshot().position;
  core::Command jog{core::CommandKind::StartMv};
  jog.v[2] = 50;
  rig.core().submit(jog);
  run(rig, r, 1000);
  hal::AxisVec after = rig.core().snapshot().position;
  CHECK((after[2] - before[2]) == Approx(25.0).margin(1.5));  // 1 s at 25 deg/s, less the ramp
  for (int a : {0, 1, 3, 4}) CHECK(std::abs(after[a] - before[a]) < 0.05);

  // C on into its travel end: it stops at travel_max (170 deg), not beyond.
  jog.v[2] = 100;
  rig.core().submit(jog);
  run(rig, r, 12000);
  CHECK(rig.core().snapshot().position[2] <= cfg.axes[2].travel_max + 0.05);
  CHECK(rig.core().snapshot().position[2] >= cfg.axes[2].travel_max - 0.5);

  // Y back and forth: a linear axis jogs in mm/s.
  before = rig.core().snapshot().position;
  core::Command jy{core::CommandKind::StartMv};
  jy.v[1] = 40;  // 20 mm/s
  rig.core().submit(jy);
  run(rig, r, 500);
  after = rig.core().snapshot().position;
  CHECK((after[1] - before[1]) == Approx(10.0).margin(1.0));
  CHECK(std::abs(after[2] - before[2]) < 0.05);
  rig.core().request_stop();
  run(rig, r, 300);
  CHECK(rig.core().mode() == core::Mode::Idle);
}
