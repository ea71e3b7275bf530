// The example programs (examples/programs/) against the machines of their configurations:
// each translates and passes messd's dry run (travel, axis limits, arcs) from the
// configuration's simulated start, and does what examples/README.md says it does. The bore
// inspection is in test_example_bore.cpp.
#include <catch2/catch.hpp>

#include <cmath>

#include "example_bench.hpp"

using namespace imess;
using namespace imess::test;

namespace {

// Every segment keeps the probe's ball clear of the simulated part (no unexpected touch).
void check_clear_of_the_scene(const ExampleBench& b) {
  double closest = INFINITY;
  const auto c = b.check([&](const planner::PlannedSegment& seg, const programs::Item&) {
    each_point(seg, true, [&](const planner::Pose& p) { closest = std::min(closest, b.scene().distance(xyz(p))); });
  });
  REQUIRE(c.ok);
  INFO("closest approach of the ball's centre to the part: " << closest);
  CHECK(closest > b.ball_radius() + 1.0);
}

}  // namespace

TEST_CASE("examples: mrm-manual.mrm on the MRM arm — X Y and the tilts back at the start, the part turned, gripper off") {
  ExampleBench b("sim-mrm-arm.json", "mrm-manual.mrm");
  const auto& m = b.setup.machine;
  REQUIRE(m.count == 5);
  // MrmOptions as they come: A = C (rotation about Z), B = U (U1), C = V (U2); the gripper by
  // name, from the configuration's programs section.
  const int gripper = b.output_number("gripper");
  REQUIRE(gripper > 0);
  REQUIRE(b.setup.mrm.gripper_output == gripper);

  const auto [c, t] = b.passed();
  const planner::Pose start = b.setup.start;
  const planner::Pose end = programs::end_pose(t.items, start);
  // Back at the start within a count (0.01 mm, 0.01°) on X, Y and both tilt joints.
  for (int a : {0, 1, 3, 4}) {
    INFO("axis " << m.axes[a].letter);
    CHECK(std::abs(end[a] - start[a]) <= 0.01);
  }
  // The A word's joint, the rotation about Z, ends half a turn on: the part was turned.
  CHECK(end[2] == Approx(start[2] + 180).margin(1e-9));
  // The manual's reach: X +500 mm, Y +300 mm, U1 +90°; every axis within its travel.
  CHECK(c.high[0] == Approx(start[0] + 500));
  CHECK(c.high[1] == Approx(start[1] + 300));
  CHECK(c.high[3] == Approx(start[3] + 90));
  for (int a = 0; a < m.count; ++a) {
    CHECK(c.low[a] >= m.axes[a].travel_min);
    CHECK(c.high[a] <= m.axes[a].travel_max);
  }
  // The gripper closes before the half turn and opens after it, and ends off; the turn is the
  // only move of C, and nothing else moves while the gripper is closed.
  bool closed = false;
  int switches = 0, turns_closed = 0, other_moves_closed = 0;
  planner::Pose here = start;
  for (const auto& item : t.items) {
    if (const auto* out = std::get_if<planner::SetOutput>(&item.step)) {
      CHECK(out->output == gripper);
      closed = out->value != 0;
      ++switches;
    } else if (const auto* l = std::get_if<planner::Line>(&item.step)) {
      const bool turns = l->target[2] != here[2];
      if (turns) CHECK(closed);
      if (closed) (turns ? turns_closed : other_moves_closed) += 1;
      here = l->target;
    }
  }
  CHECK(switches == 2);
  CHECK_FALSE(closed);
  CHECK(turns_closed == 1);
  CHECK(other_moves_closed == 0);
  CHECK(std::holds_alternative<programs::End>(t.items.back().step));
}

TEST_CASE("examples: shd-drawing.plt on the SHD stepper machine — a frame with IMESS in it, back at plotter 0,0") {
  ExampleBench b("sim-parport-shd.json", "shd-drawing.plt");
  const planner::Pose start = b.setup.start;
  // The configuration's programs.hpgl: plotter 0,0 where the machine stands, the pen up at
  // the start's Z and down 10 mm lower.
  REQUIRE(b.setup.hpgl.origin_x == start[0]);
  REQUIRE(b.setup.hpgl.origin_y == start[1]);
  REQUIRE(b.setup.hpgl.pen == programs::HpglOptions::Pen::ZMove);
  REQUIRE(b.setup.hpgl.pen_up_z == start[2]);
  REQUIRE(b.setup.hpgl.pen_down_z == start[2] - 10);

  const auto [c, t] = b.passed();
  CHECK(programs::end_pose(t.items, start) == start);
  // Everything inside the frame, 160 x 60 mm from plotter 0,0; the pen between its heights.
  check_box(c, xyz(start) - hal::Vec3(0, 0, 10), xyz(start) + hal::Vec3(160, 60, 0));
  // Drawn moves at the pen-down height only, travel moves at the pen-up height only.
  int drawn = 0;
  planner::Pose here = start;
  for (const auto& item : t.items) {
    const auto* l = std::get_if<planner::Line>(&item.step);
    if (!l) continue;
    const bool flat = l->target[2] == here[2];
    if (flat && l->target != here) {
      CHECK(l->target[2] == (item.rapid ? start[2] : start[2] - 10));
      drawn += item.rapid ? 0 : 1;
    }
    here = l->target;
  }
  CHECK(drawn >= 20);  // the frame's 4 sides and the letters' strokes
  check_clear_of_the_scene(b);
}

TEST_CASE("examples: pocket-helix.ngc on the 3D-Step machine — helical entry, rounded pocket, back at the start") {
  ExampleBench b("sim-parport-3dstep.json", "pocket-helix.ngc");
  const planner::Pose start = b.setup.start;
  const auto [c, t] = b.passed();
  CHECK(programs::end_pose(t.items, start) == start);
  // The pocket 40 x 30 mm about X450 Y350, floor Z91, and the way from and to the start.
  check_box(c, {430, start[1], 91}, {470, 365, start[2]});
  // One helix (an arc that goes down, with a whole extra turn) and eight 5 mm corners in the XY plane.
  int helices = 0, corners = 0;
  planner::Pose here = start;
  for (const auto& item : t.items) {
    if (const auto* a = std::get_if<planner::Arc>(&item.step)) {
      CHECK(a->normal == (std::array<double, 3>{0, 0, 1}));
      const double r = std::hypot(here[0] - a->centre[0], here[1] - a->centre[1]);
      if (a->target[2] < here[2]) {
        ++helices;
        CHECK(a->turns >= 1);
      } else {
        ++corners;
        CHECK(r == Approx(5));
      }
      here = a->target;
    } else if (const auto* l = std::get_if<planner::Line>(&item.step)) {
      here = l->target;
    }
  }
  CHECK(helices == 1);
  CHECK(corners == 8);
  CHECK(std::holds_alternative<programs::End>(t.items.back().step));
  check_clear_of_the_scene(b);
}
