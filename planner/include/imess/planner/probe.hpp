// A probing cycle as planner requests: a fast approach along the line start → target up to
// `prehit` before the target (none when the start is that close already), then the search
// at `probe_speed` up to `search` beyond the target, both with the cycle's id.
#pragma once
#include <optional>

#include "imess/planner/segment.hpp"

namespace imess::planner {

struct ProbeCycle {
  std::optional<Line> approach;
  Line search;
};

struct ProbeGeometry {
  double prehit = 2;       // mm before the target where the search speed starts
  double search = 10;      // mm beyond the target where the search ends
  double feed = 0;         // approach feed (the move feed)
  double probe_speed = 5;  // search feed
};

// The direction is unit(target − start) over the first three axes; nullopt when the target
// lies closer than kMinProbeTravel to the start (no direction).
inline constexpr double kMinProbeTravel = 1e-3;
std::optional<ProbeCycle> probe_cycle(std::uint32_t id, const Pose& start, const Pose& target, const ProbeGeometry& g);

}  // namespace imess::planner
