// HandMode: HandMv, the travel while free, and hand hits.
#include "imess/core/hand_mode.hpp"

#include <algorithm>

namespace imess::core {

// Entering Free forgets the travel. Done here, before each use, rather than as the loop
// enters Free: nothing touches the travel in between, so the two are the same.
void HandMode::forget_if_free_again() noexcept {
  if (free_entries_ == loop_.free_entries) return;
  free_entries_ = loop_.free_entries;
  travel_.clear();
}

Refusal HandMode::push(const Command& c) noexcept {
  if (!loop_.sim) return Refusal::NotSimulated;
  if (loop_.ms.loops_closed()) return Refusal::LoopsClosed;
  loop_.sim->push_by_hand(loop_.cartesian(c.v), std::min(c.speed > 0 ? c.speed : 10.0, loop_.config.max_velocity));
  return Refusal::None;
}

void HandMode::track() noexcept {
  forget_if_free_again();
  travel_.update(loop_.cartesian(loop_.ms.position));
}

void HandMode::hit(const AxisVec& latched, Nanos now) noexcept {
  const auto& p = loop_.config.params;
  if (hal::seconds(now - last_hit_) < p.hand_min_interval) {
    loop_.warn(Warning::HandHitTooSoon, latched, now);
    return;
  }
  forget_if_free_again();
  auto dir = travel_.direction_to(loop_.cartesian(latched), p.hand_min_travel);
  if (!dir) {
    loop_.warn(Warning::HandHitNoTravel, latched, now);
    return;
  }
  last_hit_ = now;
  loop_.approach_dir = loop_.config.layout.machine(*dir);
  loop_.measured(loop_.cartesian(latched) + p.tip_radius * *dir, *dir, true, now);
}

}  // namespace imess::core
