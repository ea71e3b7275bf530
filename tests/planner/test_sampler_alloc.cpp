// Real-time discipline: sampling (segment changes, completions, hold, resume, rest at the
// end) allocates nothing — counted by replacing the global allocator.
#include <catch2/catch.hpp>

#include "planner_rig.hpp"

#include "allocation_counter.hpp"

using namespace imess::test;

TEST_CASE("sampler: advance allocates nothing, through segments, arcs in any plane, hold, resume and rest") {
  Planner p(make_machine("XYZ", -500, 500, 100, 1000));
  static SegmentBuffer<1024> ring;  // planned before counting: planning is the non-RT side
  Arc a;
  a.id = 1000;
  a.target = pose_of({0, 0, 0});
  a.centre = {10, 0, 0};
  a.feed = 50;
  REQUIRE(p.append(a).ok());
  for (std::uint32_t i = 1; i <= 500; ++i)
    REQUIRE(p.append(Line{i, pose_of({0.5 * i, (i % 2) * 0.3, 0}), 100}).ok());
  // from (250, 0, 0): a helix in the ZX plane with an extra turn, then a half circle in the
  // plane normal to (1, 1, 1)
  Arc zx;
  zx.id = 1001;
  zx.target = pose_of({270, 5, 0});
  zx.centre = {260, 0, 0};
  zx.normal = {0, 1, 0};
  zx.turns = 1;
  zx.feed = 50;
  REQUIRE(p.append(zx).ok());
  Arc tilted;
  tilted.id = 1002;
  const double d = 3 / std::sqrt(2.0);
  tilted.centre = {270 - d, 5 + d, 0};
  tilted.target = pose_of({270 - 2 * d, 5 + 2 * d, 0});
  tilted.normal = {1, 1, 1};
  tilted.planar = true;
  tilted.feed = 50;
  REQUIRE(p.append(tilted).ok());
  p.append(Dwell{2000, 0.01});
  p.append(SetOutput{2001, 3, 1});
  p.flush();
  PlannedSegment s;
  while (p.take(s)) REQUIRE(ring.push(s));
  Sampler sampler;
  auto pop = [](PlannedSegment& out) noexcept { return ring.pop(out); };
  int done = 0;
  g_allocations = 0;
  g_counting = true;
  for (int t = 0; t < 40000; ++t) {
    if (t == 500) sampler.hold();
    if (t == 900) sampler.resume();
    done += sampler.advance(0.001, pop).done_count;
  }
  g_counting = false;
  CHECK(g_allocations.load() == 0);
  CHECK(done == 505);
  CHECK(sampler.idle());
  static_assert(noexcept(sampler.advance(0.001, pop)));
}
