// Seeded random property tests: random machines (3–6 axes, linear and rotary, each with its
// own limits) and random request streams (lines, arcs/helices, dwells, outputs, zero-length
// moves) fed while sampling at 1 ms. Every run: continuity, per-axis limits by finite
// differences, exact end, every id completed once and in order, deterministic output.
#include <catch2/catch.hpp>

#include "planner_rig.hpp"

using namespace imess::test;

namespace {

struct Scenario {
  Machine machine;
  std::vector<Request> requests;
  Pose start{}, end{};
};

Scenario make_scenario(unsigned seed) {
  std::mt19937 rng(seed);
  auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  const char* sets[] = {"XYZ", "XYZA", "XYZC", "XYZAB", "XYZBCU", "XYA"};
  Scenario sc;
  sc.machine = make_machine(sets[seed % 6], 0, 400, 100, 1000);
  Machine& m = sc.machine;
  for (int i = 0; i < m.count; ++i) {
    Axis& a = m.axes[i];
    a.max_velocity = uni(20, 200);
    a.max_accel = uni(200, 3000);
    if (a.kind == AxisKind::Rotary) a.travel_min = -720, a.travel_max = 720;
  }
  Pose pos{};
  for (int i = 0; i < m.count; ++i) pos[i] = m.axes[i].kind == AxisKind::Rotary ? 0 : 200;
  sc.start = pos;
  std::uint32_t id = 1;
  for (int n = 0; n < 60; ++n) {
    const double pick = uni(0, 1);
    if (pick < 0.55) {  // a line: short or long, some axes only
      Pose t = pos;
      const double reach = uni(0, 1) < 0.5 ? 2 : 60;
      for (int i = 0; i < m.count; ++i)
        if (uni(0, 1) < 0.6) t[i] = std::clamp(pos[i] + uni(-reach, reach), m.axes[i].travel_min, m.axes[i].travel_max);
      sc.requests.push_back(Line{id++, t, uni(5, 250)});
      pos = t;
    } else if (pick < 0.8 && m.count >= 3 && m.axes[2].letter == 'Z') {  // an XY arc, maybe a helix with Z and a rotary
      const double cx = pos[0] + uni(-30, 30), cy = pos[1] + uni(-30, 30);
      const double r = std::hypot(pos[0] - cx, pos[1] - cy);
      if (r < 1 || cx - r < 5 || cx + r > 395 || cy - r < 5 || cy + r > 395) continue;
      const double ang = uni(0, 2 * 3.14159265358979);
      Pose t = pos;
      t[0] = cx + r * std::cos(ang);
      t[1] = cy + r * std::sin(ang);
      if (uni(0, 1) < 0.5) t[2] = std::clamp(pos[2] + uni(-10, 10), 0.0, 400.0);
      if (m.count > 3 && uni(0, 1) < 0.5) t[3] = std::clamp(pos[3] + uni(-90, 90), m.axes[3].travel_min, m.axes[3].travel_max);
      Arc a;
      a.id = id++;
      a.target = t;
      a.centre = {cx, cy, 0};
      a.ccw = uni(0, 1) < 0.5;
      a.feed = uni(5, 150);
      sc.requests.push_back(a);
      pos = t;
    } else if (pick < 0.88) {
      sc.requests.push_back(Line{id++, pos, uni(1, 100)});  // zero length
    } else if (pick < 0.94) {
      sc.requests.push_back(Dwell{id++, uni(0, 0.02)});
    } else {
      sc.requests.push_back(SetOutput{id++, 1, uni(0, 1)});
    }
  }
  sc.end = pos;
  return sc;
}

}  // namespace

TEST_CASE("properties: random machines and paths stay within every limit and end exactly") {
  for (unsigned seed = 1; seed <= 24; ++seed) {
    INFO("seed " << seed);
    const Scenario sc = make_scenario(seed);
    Planner p(sc.machine);
    p.set_position(sc.start);
    RunOptions o;
    o.requests_per_tick = 1 + seed % 3;
    const auto r = run(p, sc.requests, o);
    check_continuity(r);
    check_limits(sc.machine, r);
    CHECK(r.ticks.back().pose == sc.end);  // bit for bit
    CHECK(r.ticks.back().velocity == Pose{});
    std::vector<std::uint32_t> want;
    for (std::uint32_t i = 1; i <= sc.requests.size(); ++i) want.push_back(i);
    CHECK(r.done == want);
    CHECK_FALSE(r.starved);
  }
}

TEST_CASE("properties: the same input gives the identical sample stream") {
  for (unsigned seed : {3u, 11u, 17u}) {
    const Scenario sc = make_scenario(seed);
    Planner a(sc.machine), b(sc.machine);
    a.set_position(sc.start);
    b.set_position(sc.start);
    const auto ra = run(a, sc.requests);
    const auto rb = run(b, sc.requests);
    REQUIRE(ra.ticks.size() == rb.ticks.size());
    bool same = true;
    for (std::size_t k = 0; k < ra.ticks.size(); ++k)
      same = same && ra.ticks[k].pose == rb.ticks[k].pose && ra.ticks[k].velocity == rb.ticks[k].velocity;
    CHECK(same);
  }
}

TEST_CASE("properties: batching input differently changes speeds, never limits or end points") {
  const Scenario sc = make_scenario(5);
  for (int per_tick : {1, 7, 1000}) {
    Planner p(sc.machine);
    p.set_position(sc.start);
    RunOptions o;
    o.requests_per_tick = per_tick;
    const auto r = run(p, sc.requests, o);
    check_limits(sc.machine, r);
    CHECK(r.ticks.back().pose == sc.end);
  }
}

TEST_CASE("properties: random feed holds and resumes keep every limit and the same end") {
  for (unsigned seed = 30; seed < 42; ++seed) {
    INFO("seed " << seed);
    const Scenario sc = make_scenario(seed);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> gap(1, 400);
    int next_toggle = gap(rng);
    bool held = false;
    RunOptions o;
    o.on_tick = [&](int t, Sampler& s) {
      if (t < next_toggle) return;
      held = !held;
      held ? s.hold() : s.resume();
      next_toggle = t + gap(rng);
    };
    o.max_ticks = 5'000'000;
    Planner p(sc.machine);
    p.set_position(sc.start);
    const auto r = run(p, sc.requests, o);
    check_continuity(r);
    check_limits(sc.machine, r);
    std::vector<std::uint32_t> want;
    for (std::uint32_t i = 1; i <= sc.requests.size(); ++i) want.push_back(i);
    CHECK(r.done == want);
    CHECK(r.ticks.back().pose == sc.end);
  }
}
