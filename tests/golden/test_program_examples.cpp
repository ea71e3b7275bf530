// The example programs (examples/programs/) run by messd on the simulated machines of their
// configurations, end to end over the wire: Take, Load from the configured programs folder,
// Run, then what the machine did. messd's own parts (Server, motion core, backend, simulator)
// run in virtual time through the golden harness, so a 130 s program takes seconds of CPU;
// every time below is virtual.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "config_rig.hpp"
#include "golden_harness.hpp"
#include "imess/metrology/fit.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/sim/stepper_machine.hpp"

using namespace imess;
using namespace imess::golden;

namespace {

struct Run {
  std::vector<std::string> lines;  // what client 1 received, in order

  std::vector<std::string> starting(const std::string& prefix) const {
    std::vector<std::string> out;
    for (const auto& l : lines)
      if (l.rfind(prefix, 0) == 0) out.push_back(l);
    return out;
  }
  std::string last(const std::string& prefix) const {
    const auto all = starting(prefix);
    return all.empty() ? std::string() : all.back();
  }
  // The numbers after "Pos" in the last Status reply: every axis in the machine's order.
  std::vector<double> position() const {
    std::istringstream in(last("Ok Status").substr(last("Ok Status").find(" Pos ") + 5));
    std::vector<double> pos;
    double v;
    while (in >> v) pos.push_back(v);
    return pos;
  }
};

// Loads `program` from the configuration's programs folder, runs it for `ms` of virtual time,
// then asks Status, Outputs and Program.
Run run_example(const std::string& config, const std::string& program, long ms,
                const std::function<void(test::ConfigRig&)>& inspect = {}) {
  const std::string script = "@ config/" + config + "\n> Take\n> Load " + program + "\n> Run\n= " + std::to_string(ms) +
                             " ms\n> Status\n> Outputs\n> Program\n";
  const auto out = replay(parse_transcript(script, program), program, inspect);
  Run r;
  for (const auto& e : out)
    if (e.kind == EntryKind::Receive && e.client == 1) r.lines.push_back(e.text);
  INFO(format_transcript(out));
  REQUIRE(r.starting("Ok Load " + program).size() == 1);
  REQUIRE(r.starting("Ok Run " + program).size() == 1);
  return r;
}

// Block events name lines that never go back (a program has no jumps) and the last one
// comes before ProgEnd.
void check_blocks(const Run& r, const std::string& program) {
  const auto blocks = r.starting("Block " + program + " ");
  REQUIRE(blocks.size() >= 2);
  int previous = 0;
  for (const auto& b : blocks) {
    const int line = std::stoi(b.substr(b.find(' ', 6) + 1));
    CHECK(line >= previous);
    previous = line;
  }
}

}  // namespace

TEST_CASE("program examples: mrm-manual.mrm on the MRM arm ends where it began, the part turned, gripper off") {
  const auto r = run_example("sim-mrm-arm.json", "mrm-manual.mrm", 150000);
  INFO(r.last("ProgEnd"));
  CHECK(r.last("ProgEnd") == "ProgEnd mrm-manual.mrm ok 12 end");
  check_blocks(r, "mrm-manual.mrm");
  const auto pos = r.position();  // X Y C U V
  REQUIRE(pos.size() == 5);
  // sim.start [200, 150, 0, 0, 0]; a count is 0.01 mm / 0.01°
  CHECK(std::abs(pos[0] - 200) <= 0.01);
  CHECK(std::abs(pos[1] - 150) <= 0.01);
  CHECK(std::abs(pos[3] - 0) <= 0.01);
  CHECK(std::abs(pos[4] - 0) <= 0.01);
  CHECK(std::abs(pos[2] - 180) <= 0.01);  // the half turn A1800 gave the part (docs/programs.md)
  CHECK_THAT(r.last("Ok Outputs"), Catch::StartsWith("Ok Outputs gripper off"));
}

TEST_CASE("program examples: shd-drawing.plt on the SHD steppers, no step lost, back on the start's step") {
  std::int64_t steps[3] = {-1, -1, -1};
  unsigned long lost = 1, violations = 1;
  const auto r = run_example("sim-parport-shd.json", "shd-drawing.plt", 80000, [&](test::ConfigRig& rig) {
    auto* sim = rig.machine().stepper_sim();
    REQUIRE(sim);
    lost = 0;
    for (int a = 0; a < 3; ++a) {
      steps[a] = sim->steps(a);
      lost += sim->lost_steps(a);
    }
    violations = sim->violations().total();
  });
  INFO(r.last("ProgEnd"));
  CHECK_THAT(r.last("ProgEnd"), Catch::StartsWith("ProgEnd shd-drawing.plt ok "));
  check_blocks(r, "shd-drawing.plt");
  CHECK(lost == 0);
  CHECK(violations == 0);
  // The carriage's own step counts (the simulated machine's, not the controller's) are where
  // they were at power-on: back at the start within a step.
  for (int a = 0; a < 3; ++a) CHECK(std::llabs(steps[a]) <= 1);
  const auto pos = r.position();
  REQUIRE(pos.size() == 3);
  CHECK(pos[0] == Approx(430).margin(0.005));
  CHECK(pos[1] == Approx(330).margin(0.005));
  CHECK(pos[2] == Approx(100).margin(0.005));
}

TEST_CASE("program examples: pocket-helix.ngc on the 3D-Step machine: arcs and a helix, no step lost") {
  unsigned long lost = 1, violations = 1;
  std::int64_t steps[3] = {-1, -1, -1};
  const auto r = run_example("sim-parport-3dstep.json", "pocket-helix.ngc", 50000, [&](test::ConfigRig& rig) {
    auto* sim = rig.machine().stepper_sim();
    REQUIRE(sim);
    lost = 0;
    for (int a = 0; a < 3; ++a) {
      lost += sim->lost_steps(a);
      steps[a] = sim->steps(a);
    }
    violations = sim->violations().total();
  });
  INFO(r.last("ProgEnd"));
  CHECK_THAT(r.last("ProgEnd"), Catch::StartsWith("ProgEnd pocket-helix.ngc ok "));
  check_blocks(r, "pocket-helix.ngc");
  CHECK(lost == 0);
  CHECK(violations == 0);
  for (int a = 0; a < 3; ++a) CHECK(std::llabs(steps[a]) <= 1);
}

TEST_CASE("program examples: bore-inspection.ngc on the CMM: eight G38.2 hits fit the bore within 1 um") {
  const auto r = run_example("sim-servo-card.json", "bore-inspection.ngc", 40000);
  INFO(r.last("ProgEnd"));
  CHECK_THAT(r.last("ProgEnd"), Catch::StartsWith("ProgEnd bore-inspection.ngc ok "));
  std::vector<Eigen::Vector2d> points;
  for (const auto& line : r.starting("Hit ")) {
    const auto msg = protocol::parse_message(line);
    const auto* hit = std::get_if<protocol::HitMsg>(&msg);
    REQUIRE(hit);
    CHECK(hit->p.z == Approx(40).margin(1e-3));  // at half height, where the program probes
    points.emplace_back(hit->p.x, hit->p.y);
  }
  REQUIRE(points.size() == 8);
  CHECK(r.starting("MeasPt ").size() == 8);
  const auto fit = metrology::fit_circle2d(points);
  REQUIRE(fit.ok());
  const auto& c = fit.value();
  INFO("centre " << c.center.transpose() << " diameter " << c.diameter << " form " << c.stats.form());
  // The scene's bore: diameter 30 at X460 Y350 (config/sim-servo-card.json)
  CHECK(std::abs(c.center.x() - 460) <= 0.001);
  CHECK(std::abs(c.center.y() - 350) <= 0.001);
  CHECK(std::abs(c.diameter - 30) <= 0.002);  // the radius within 1 um
  const auto pos = r.position();
  REQUIRE(pos.size() == 3);
  CHECK(pos[0] == Approx(430).margin(0.005));  // the program's last move: back to the start
  CHECK(pos[1] == Approx(330).margin(0.005));
}
