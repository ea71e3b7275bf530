// ExampleBench: an example program (examples/programs/) and the machine of the configuration
// it is written for, loaded as messd loads it: the planner's machine with the configured
// travel and axis limits, the simulated start, the scene and the probe's ball. The program
// is dry-run through programs::check_program as messd checks it before Run.
#pragma once
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "config_rig.hpp"
#include "imess/core/path_machine.hpp"
#include "imess/net/program_run.hpp"
#include "imess/programs/check.hpp"
#include "imess/sim/scene.hpp"

namespace imess::test {

class ExampleBench {
 public:
  ExampleBench(const std::string& config, const std::string& program)
      : rig_(std::string(IMESS_SOURCE_DIR) + "/config/" + config), name_(program) {
    std::ifstream in(std::string(IMESS_SOURCE_DIR) + "/examples/programs/" + program);
    REQUIRE(in);
    std::stringstream s;
    s << in.rdbuf();
    text_ = s.str();
    // The set-up messd's runner makes from the configuration's "programs" section.
    planner::Pose start{};
    for (int a = 0; a < rig_.core().config().layout.count; ++a) start[a] = rig_.config().sim.mechanics.start[a];
    setup = net::program_setup(rig_.config().server.programs, rig_.core().config(), core::path_machine(rig_.core().config()), start);
    options = core::path_options(rig_.core().config());
  }

  programs::Language language() const {
    const auto lang = programs::language_of(name_);
    REQUIRE(lang);
    return *lang;
  }
  const std::string& text() const { return text_; }
  programs::Translation translation() const { return programs::translate(language(), text_, setup); }
  programs::Check check(const programs::SegmentVisitor& visit = {}) const {
    return programs::check_program(language(), text_, setup, options, visit);
  }
  // What messd's Load will say of it (the dry run's figures), in the test's output.
  void report(const programs::Check& c) const {
    WARN(name_ << ": " << c.lines << " lines, " << c.blocks << " blocks, " << c.segments << " segments, length "
               << c.length << " (feed " << c.feed_length << ", rapid " << c.rapid_length << ", probe "
               << c.probe_length << "), time " << c.time << " s");
  }

  // The dry run, which must pass (its figures in the test's output), and the translation.
  struct Passed {
    programs::Check check;
    programs::Translation translation;
  };
  Passed passed() const {
    Passed p{check(), translation()};
    INFO(p.check.error);
    REQUIRE(p.check.ok);
    REQUIRE(p.translation.ok);
    report(p.check);
    return p;
  }

  const app::DaemonConfig& config() const { return rig_.config(); }
  const sim::Scene& scene() const { return rig_.config().sim.scene; }
  double ball_radius() const { return rig_.config().sim.mechanics.probe.ball_radius; }
  double tip_radius() const { return rig_.config().core.params.tip_radius; }
  // The number of the configured output with this name (0: none).
  int output_number(std::string_view name) const {
    const auto& c = rig_.config().core;
    for (int i = 0; i < c.output_count; ++i)
      if (c.outputs[i].name_view() == name) return c.outputs[i].number;
    return 0;
  }

  programs::Setup setup;
  planner::PlannerOptions options;

 private:
  ConfigRig rig_;
  std::string name_, text_;
};

inline hal::Vec3 xyz(const planner::Pose& p) { return {p[0], p[1], p[2]}; }

// The dry run's bounding box on X Y Z.
inline void check_box(const programs::Check& c, const hal::Vec3& low, const hal::Vec3& high) {
  for (int a = 0; a < 3; ++a) {
    INFO("axis " << "XYZ"[a]);
    CHECK(c.low[a] == Approx(low[a]));
    CHECK(c.high[a] == Approx(high[a]));
  }
}

// Every point of a planned segment that moves, about every 0.2 mm (and at least 8 along an
// arc), from its start (first = true) or just after it.
inline void each_point(const planner::PlannedSegment& seg, bool first, const std::function<void(const planner::Pose&)>& f) {
  if (seg.length <= 0) return;
  const int n = std::max(8, static_cast<int>(std::ceil(seg.length / 0.2)));
  planner::Pose p{}, d{};
  for (int k = first ? 0 : 1; k <= n; ++k) {
    planner::pose_at(seg, seg.length * k / n, p, d);
    f(p);
  }
}

}  // namespace imess::test
