// Per tick the fastest speed that is at most one accel step above the last, at most the
// feed, and from which the rest can still be stopped in accel steps (stop_need ≤ left):
// while that is the feed or the last speed plus a step it accelerates or cruises; the first
// tick it is less, braking begins, and from then on each tick is one accel step slower
// except the first, which takes the part of a step that makes the end exact. The last tick
// is at most one step, so the axis ends at rest. No division by the distance anywhere.
#include "imess/hal/tick_profile.hpp"

#include <algorithm>
#include <stdexcept>

namespace imess::hal {

TickProfile::TickProfile(std::int64_t distance, std::int64_t feed, std::int64_t accel)
    : sign_(distance < 0 ? -1 : 1), feed_(feed), accel_(accel) {
  constexpr std::int64_t kMaxDistance = 1'000'000'000'000, kMaxRate = 1'000'000'000;
  if (distance > kMaxDistance || distance < -kMaxDistance)
    throw std::invalid_argument("tick profile: distance beyond 10^12 counts");
  if (feed < 1 || feed > kMaxRate) throw std::invalid_argument("tick profile: feed outside 1 ... 10^9 thousandths of a count per tick");
  if (accel < 1 || accel > kMaxRate) throw std::invalid_argument("tick profile: accel outside 1 ... 10^9 thousandths of a count per tick²");
  left_ = (distance < 0 ? -distance : distance) * kMilli;
}

std::int64_t TickProfile::stop_need(std::int64_t u) const noexcept {
  if (u <= 0) return 0;
  const std::int64_t m = (u - 1) / accel_;  // ticks after this one still moving: u − k·a > 0
  return (m + 1) * u - accel_ * m * (m + 1) / 2;  // ≤ about feed²/accel: within 10^18
}

std::int64_t TickProfile::next() noexcept {
  if (left_ == 0) return 0;
  const std::int64_t up = std::min(speed_ + accel_, feed_);
  std::int64_t u = up;
  if (stop_need(up) > left_) {
    // The fastest u with stop_need(u) ≤ left: the last tick was possible, so u ≥ speed − accel.
    std::int64_t lo = std::max<std::int64_t>(speed_ - accel_, 0), hi = up;  // stop_need(lo) ≤ left < stop_need(hi)
    while (hi - lo > 1) {
      const std::int64_t mid = lo + (hi - lo) / 2;
      (stop_need(mid) <= left_ ? lo : hi) = mid;
    }
    u = lo;
    if (braking_from_ < 0) braking_from_ = ticks_;
  }
  const std::int64_t sent = done_ / kMilli;
  done_ += u;
  left_ -= u;
  speed_ = u;
  ++ticks_;
  return sign_ * (done_ / kMilli - sent);
}

}  // namespace imess::hal
