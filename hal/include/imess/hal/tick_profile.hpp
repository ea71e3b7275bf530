// TickProfile: the MRM manual's integer point-to-point profile (BRIEF §5), the increments a
// drive kit in mode 2 takes (its command port holds this period's increment in counts).
// Per tick it speeds up by a fixed step up to the feed, brakes when the distance left is no
// more than it needs to stop, and ends exactly on the target, at rest. Integer arithmetic
// only: speeds in thousandths of a count per tick; the fraction of a count not yet sent is
// carried to the next tick, so the increments add up to the distance exactly.
//
// messd does not run it: messd's drive kits follow the planner's segments. It reproduces the
// manual's point-to-point mode and its reference run (docs/hardware.md, "Drive kits").
#pragma once
#include <cstdint>

namespace imess::hal {

class TickProfile {
 public:
  static constexpr std::int64_t kMilli = 1000;  // speed units per count

  // distance: counts, signed, |distance| ≤ 10^12; feed: thousandths of a count per tick,
  // 1 … 10^9; accel: thousandths of a count per tick per tick, 1 … 10^9. Anything else
  // throws std::invalid_argument. A zero distance is done at once (no tick).
  TickProfile(std::int64_t distance, std::int64_t feed, std::int64_t accel);

  bool done() const noexcept { return left_ == 0; }
  // This tick's increment in counts, with the distance's sign; 0 once done.
  std::int64_t next() noexcept;

  std::int64_t ticks() const noexcept { return ticks_; }             // increments handed out
  std::int64_t speed() const noexcept { return speed_; }             // the last tick's, thousandths
  std::int64_t braking_from() const noexcept { return braking_from_; }  // 0-based tick; -1: not yet

 private:
  // u plus the distance the ticks after one at speed u need to come to rest, each slower by
  // accel: u + (u − a) + (u − 2a) + … while positive. Strictly increasing in u.
  std::int64_t stop_need(std::int64_t u) const noexcept;

  std::int64_t sign_, feed_, accel_;
  std::int64_t left_;      // thousandths of a count still to go
  std::int64_t done_ = 0;  // thousandths of a count gone
  std::int64_t speed_ = 0, ticks_ = 0, braking_from_ = -1;
};

}  // namespace imess::hal
