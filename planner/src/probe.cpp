#include "imess/planner/probe.hpp"

#include <algorithm>
#include <cmath>

namespace imess::planner {

std::optional<ProbeCycle> probe_cycle(std::uint32_t id, const Pose& start, const Pose& target, const ProbeGeometry& g) {
  double d[3], len2 = 0;
  for (int a = 0; a < 3; ++a) {
    d[a] = target[a] - start[a];
    len2 += d[a] * d[a];
  }
  const double len = std::sqrt(len2);
  if (!(len >= kMinProbeTravel)) return std::nullopt;
  for (double& x : d) x /= len;
  ProbeCycle c;
  c.search.id = id;
  c.search.probe = ProbePhase::Search;
  c.search.feed = g.probe_speed;
  c.search.target = target;
  for (int a = 0; a < 3; ++a) c.search.target[a] = target[a] + g.search * d[a];
  const double fast = len - g.prehit;  // the approach's length
  if (fast > 0) {
    Line l;
    l.id = id;
    l.probe = ProbePhase::Approach;
    l.feed = g.feed;
    l.target = target;
    for (int a = 0; a < 3; ++a) l.target[a] = start[a] + fast * d[a];
    c.approach = l;
  }
  return c;
}

}  // namespace imess::planner
