// The port backends follow a planned path (follow(), one setpoint per servo period): a
// planner path (corners, an arc, a dwell; 3 axes; limits from the driver configuration)
// sampled at 1 ms into the real drivers on the simulated machines. Stepper: no step lost,
// exact ends in steps, step rate and pulse timing kept, position within 1 step + speed ×
// base period of the sampled path. Drive kit: ends within 1 count, following error under
// the limit, no fault, modes 1 and 2. Both: stop() brakes within v²/2a, follow after stop,
// move after follow, seeded random paths.
#include <catch2/catch.hpp>

#include "follow_rig.hpp"

using namespace imess;
using namespace imess::test;

namespace {

StepperRigOptions stepper_follow_options() {
  auto o = stepper_options();
  o.sim.scene = sim::Scene();  // nothing to touch
  return o;
}

DriveRigOptions drive_follow_options(int mode) {
  auto o = drive_options(mode, mode == 1 ? "mrm-b" : "mrm-a");
  o.sim.scene = sim::Scene();
  return o;
}

// Every axis ended on round(target × steps/mm), the generator and the decoder agree, and
// the power stage never saw a timing violation.
void check_no_step_lost(StepperRig& rig, StepperFollowRun& run, const hal::Vec3& target) {
  for (int a = 0; a < 3; ++a) {
    INFO("axis " << a);
    CHECK(run.decoded(a) == rig.driver().steps_for(a, target[a]));
    CHECK(rig.driver().step_count(a) == run.decoded(a));
    CHECK(rig.stepper().lost_steps(a) == 0);
  }
  CHECK(rig.stepper().violations().total() == 0);
  CHECK(run.figures().min_step_interval >= rig.driver().timing().step_len + rig.driver().timing().step_space);
}

void check_stepper_figures(StepperFollowRun& run) {
  const auto& f = run.figures();
  INFO("max error " << f.max_error_steps << " steps, worst over the bound " << f.max_error_over_bound
                    << ", late periods " << f.late_periods << " of " << f.periods << ", shortest step interval "
                    << f.min_step_interval << " base periods; worst in period " << f.worst_period << " axis "
                    << f.worst_axis);
  CHECK(f.max_error_over_bound <= 1e-9);
  WARN("stepper: max |decoded - sampled path| " << f.max_error_steps << " steps; late periods " << f.late_periods
                                                << "/" << f.periods << "; shortest step interval "
                                                << f.min_step_interval << " base periods");
}

}  // namespace

TEST_CASE("stepper follows a planned path with corners, an arc and a dwell: no step lost, within 1 step + v x base period") {
  StepperRig rig(stepper_follow_options());
  StepperFollowRun run(rig);
  const hal::Vec3 start = xyz(run.state().position);
  PathFeed feed(follow_machine(rig.options().sim.mechanics, rig.options().driver.axes), start);
  feed.plan(corner_arc_dwell_path(start, 90));
  run.follow(feed);
  check_no_step_lost(rig, run, feed.end());
  check_stepper_figures(run);
  // Settled on the path's end: profile end and in position on every axis.
  CHECK(run.state().motion_done());
  CHECK(run.state().all(hal::status::kInPosition));
  CHECK_FALSE(run.state().faulted());
}

TEST_CASE("stepper following: in-position only on axes the path holds at rest") {
  StepperRig rig(stepper_follow_options());
  StepperFollowRun run(rig);
  const hal::Vec3 start = xyz(run.state().position);
  PathFeed feed(follow_machine(rig.options().sim.mechanics, rig.options().driver.axes), start);
  feed.plan({planner::Line{1, pose3(start + hal::Vec3(20, 0, 0)), 50}});
  for (int i = 0; i < 100; ++i) {
    const hal::Setpoint sp = feed.next();
    run.cycle(&sp);
  }
  const auto& st = run.state();
  CHECK((st.status[0] & hal::status::kProfileEnd) == 0);  // X is moving
  CHECK((st.status[0] & hal::status::kInPosition) == 0);
  CHECK((st.status[1] & hal::status::kProfileEnd) != 0);  // Y and Z stand still on the path
  CHECK((st.status[2] & hal::status::kInPosition) != 0);
  run.follow(feed);
  CHECK(run.state().motion_done());
  CHECK(run.state().all(hal::status::kInPosition));
}

TEST_CASE("stepper: stop() mid-path brakes within v^2/2a without losing a step — follow after stop and move after follow work") {
  StepperRig rig(stepper_follow_options());
  StepperFollowRun run(rig);
  const hal::Vec3 start = xyz(run.state().position);
  const auto machine = follow_machine(rig.options().sim.mechanics, rig.options().driver.axes);
  PathFeed feed(machine, start);
  feed.plan({planner::Line{1, pose3(start + hal::Vec3(60, -45, 20)), 90}});
  hal::Setpoint sp;
  for (int i = 0; i < 500; ++i) {  // well into the cruise
    sp = feed.next();
    run.cycle(&sp);
  }
  REQUIRE(sp.velocity.norm() > 50);
  CHECK_FALSE(run.state().any(hal::status::kProfileEnd));
  CHECK_FALSE(run.state().any(hal::status::kInPosition));
  const hal::Vec3 decel(2000, 2000, 2000);
  REQUIRE(run.stop(decel));
  REQUIRE(run.settle());
  const hal::Vec3 rest = xyz(run.state().position);
  for (int a = 0; a < 3; ++a) {
    INFO("axis " << a << " v " << sp.velocity[a]);
    const double brake = sp.velocity[a] * sp.velocity[a] / (2 * decel[a]);
    const double travelled = std::abs(rest[a] - sp.position[a]);
    CHECK(travelled <= brake + 1.0 / 1000 + 1e-9);  // + one step
    CHECK(travelled >= brake - 1.0 / 1000 - 1e-9);
    CHECK((rest[a] - sp.position[a]) * sp.velocity[a] >= 0);  // on, not back
    CHECK(run.decoded(a) == rig.driver().step_count(a));
  }
  CHECK(rig.stepper().violations().total() == 0);
  WARN("stepper stop from " << sp.velocity.norm() << " mm/s: rest " << (rest - xyz(sp.position)).transpose() << " mm past the last setpoint");

  SECTION("follow after stop") {
    feed.restart(rest);
    feed.plan(corner_arc_dwell_path(rest, 80));
    run.follow(feed);
    check_no_step_lost(rig, run, feed.end());
    check_stepper_figures(run);
  }
  SECTION("move after follow") {
    feed.restart(rest);
    feed.plan({planner::Line{1, pose3(rest + hal::Vec3(-5, 5, 5)), 40}});
    run.follow(feed);
    const hal::Vec3 goal = rest + hal::Vec3(12.3456, -7.0004, 3.3333);
    hal::AxisArray<hal::AxisMove> moves;
    for (int a = 0; a < 3; ++a) moves[a] = {goal[a], 60, 3000};
    REQUIRE(rig.backend().move(moves, 7));
    run.cycle();
    CHECK_FALSE(run.state().motion_done());
    REQUIRE(run.settle());
    check_no_step_lost(rig, run, goal);
  }
}

TEST_CASE("stepper following into a closed limit switch: that axis brakes as a move would, the others go on") {
  auto o = stepper_follow_options();
  o.sim.mechanics.start = axes3(hal::Vec3(20, 330, 100));
  o.driver.initial_position = xyz(o.sim.mechanics.start);
  StepperRig rig(o);
  StepperFollowRun run(rig);
  auto machine = follow_machine(o.sim.mechanics, o.driver.axes);
  machine.axes[0].travel_min = -100;  // a path the planner lets past X's end/ref switch (at -2)
  PathFeed feed(machine, xyz(run.state().position));
  feed.plan({planner::Line{1, pose3(hal::Vec3(-15, 360, 100)), 30}});
  run.follow(feed);
  REQUIRE(run.settle());
  const double x = xyz(run.state().position).x();
  CHECK((run.state().status[0] & hal::status::kHardLimitNeg) != 0);
  CHECK(x < -2);         // into the switch
  CHECK(x > -2 - 0.25);  // braked at 4000 mm/s² from 30·|u_x| mm/s within a period of the edge
  CHECK(run.decoded(1) == rig.driver().steps_for(1, 360));  // Y went on to the end of the path
  CHECK(run.decoded(0) == rig.driver().step_count(0));
  CHECK(rig.stepper().lost_steps(0) == 0);  // stopped well before the hard stop at -20
  CHECK(rig.stepper().violations().total() == 0);
}

TEST_CASE("stepper follows seeded random paths: no step lost, within 1 step + v x base period") {
  for (std::uint32_t seed : {1u, 7u, 2024u}) {
    DYNAMIC_SECTION("seed " << seed) {
      StepperRig rig(stepper_follow_options());
      StepperFollowRun run(rig);
      const hal::Vec3 start = xyz(run.state().position);
      PathFeed feed(follow_machine(rig.options().sim.mechanics, rig.options().driver.axes), start);
      feed.plan(random_path(start, 40, 90, seed));
      run.follow(feed);
      check_no_step_lost(rig, run, feed.end());
      check_stepper_figures(run);
      CHECK(run.state().motion_done());
    }
  }
}

// ------------------------------------------------------------------ drive kit

namespace {
void check_drive_end(DriveRig& rig, DriveFollowRun& run, const hal::Vec3& target, double count_mm) {
  for (int a = 0; a < 3; ++a) {
    INFO("axis " << a);
    CHECK(std::abs(run.state().position[a] - target[a]) <= count_mm + 1e-9);
    CHECK(rig.driver().max_following_error_seen(a) < 1.0);  // the configured limit
  }
  CHECK_FALSE(run.figures().faulted);
  CHECK(run.state().motion_done());
  CHECK(run.state().all(hal::status::kInPosition));
  WARN("drive kit: max following error " << rig.driver().max_following_error_seen(0) << " / "
                                         << rig.driver().max_following_error_seen(1) << " / "
                                         << rig.driver().max_following_error_seen(2) << " mm; max |encoder - setpoint| "
                                         << run.figures().max_path_error << " mm");
}
}  // namespace

TEST_CASE("drive kit follows a planned path with corners, an arc and a dwell, modes 1 and 2") {
  for (int mode : {1, 2}) {
    DYNAMIC_SECTION("mode " << mode) {
      auto o = drive_follow_options(mode);
      DriveRig rig(o);
      DriveFollowRun run(rig);
      const hal::Vec3 start = xyz(run.state().position);
      PathFeed feed(follow_machine(o.sim.mechanics, o.driver.axes), start);
      feed.plan(corner_arc_dwell_path(start, 120));
      run.follow(feed, 2000);
      check_drive_end(rig, run, feed.end(), o.driver.axes[0].position_unit_mm);
      CHECK(rig.driver().handshake_misses() == 0);
    }
  }
}

TEST_CASE("drive kit: stop() mid-path brakes within v^2/2a — follow after stop and move after follow work") {
  for (int mode : {1, 2}) {
    DYNAMIC_SECTION("mode " << mode) {
      auto o = drive_follow_options(mode);
      DriveRig rig(o);
      DriveFollowRun run(rig);
      const hal::Vec3 start = xyz(run.state().position);
      const auto machine = follow_machine(o.sim.mechanics, o.driver.axes);
      PathFeed feed(machine, start);
      feed.plan({planner::Line{1, pose3(start + hal::Vec3(80, -60, 30)), 140}});
      hal::Setpoint sp;
      for (int i = 0; i < 500; ++i) {
        sp = feed.next();
        run.cycle(&sp);
      }
      REQUIRE(sp.velocity.norm() > 100);
      // All three axes move: none claims the end of its profile or in position.
      CHECK_FALSE(run.state().any(hal::status::kProfileEnd));
      CHECK_FALSE(run.state().any(hal::status::kInPosition));
      const hal::Vec3 decel(2000, 2000, 2000);
      REQUIRE(rig.backend().stop(axes3(decel)));
      REQUIRE(run.settle());
      const hal::Vec3 rest = xyz(run.state().position);
      for (int a = 0; a < 3; ++a) {
        INFO("axis " << a << " v " << sp.velocity[a]);
        const double brake = sp.velocity[a] * sp.velocity[a] / (2 * decel[a]);
        CHECK(std::abs(rest[a] - sp.position[a]) <= brake + o.driver.axes[a].in_position_mm);
        CHECK(std::abs(rest[a] - sp.position[a]) >= brake - o.driver.axes[a].in_position_mm);
      }
      CHECK_FALSE(run.figures().faulted);

      feed.restart(rest);
      feed.plan(corner_arc_dwell_path(rest, 100));
      run.follow(feed, 2000);
      check_drive_end(rig, run, feed.end(), o.driver.axes[0].position_unit_mm);

      const hal::Vec3 goal = xyz(run.state().position) + hal::Vec3(-12.345, 6.789, -3.21);
      hal::AxisArray<hal::AxisMove> moves;
      for (int a = 0; a < 3; ++a) moves[a] = {goal[a], 100, 3000};
      REQUIRE(rig.backend().move(moves, 7));
      run.cycle();
      CHECK_FALSE(run.state().motion_done());
      REQUIRE(run.settle());
      for (int a = 0; a < 3; ++a) CHECK(std::abs(run.state().position[a] - goal[a]) < o.driver.axes[a].in_position_mm);
      CHECK_FALSE(run.figures().faulted);
    }
  }
}

TEST_CASE("drive kit follows seeded random paths: within the following-error limit, ends within 1 count") {
  for (std::uint32_t seed : {3u, 11u, 99u}) {
    for (int mode : {1, 2}) {
      DYNAMIC_SECTION("seed " << seed << " mode " << mode) {
        auto o = drive_follow_options(mode);
        DriveRig rig(o);
        DriveFollowRun run(rig);
        const hal::Vec3 start = xyz(run.state().position);
        PathFeed feed(follow_machine(o.sim.mechanics, o.driver.axes), start);
        feed.plan(random_path(start, 40, 150, seed));
        run.follow(feed, 2000);
        check_drive_end(rig, run, feed.end(), o.driver.axes[0].position_unit_mm);
      }
    }
  }
}
