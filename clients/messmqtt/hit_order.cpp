// Publishing in seq order (hit_order.hpp).
#include "hit_order.hpp"

#include <algorithm>

namespace imess::mqtt {

HitOrder::Offer HitOrder::offer(std::uint64_t seq) {
  if (!newest_ || seq > *newest_) newest_ = seq;
  if (seq < next_) return Offer::Already;
  if (seq > next_) return Offer::Gap;
  ++next_;
  return Offer::Publish;
}

bool HitOrder::pass_lost(std::uint64_t first, std::uint64_t last) {
  if (first > next_ || last < next_) return false;
  next_ = last + 1;
  return true;
}

void HitOrder::rotated_out(std::uint64_t oldest) { next_ = std::max(next_, oldest); }

void HitOrder::replay_answered(std::uint64_t from, std::uint64_t count, std::uint64_t newest) {
  replay_in_flight_ = false;
  if (!newest_ || newest > *newest_) newest_ = newest;
  // Every hit of the answer came as a Hit line and was offered (or passed as lost): next_ is
  // from + count already, unless the broker session changed meanwhile (start_at), in which case
  // the next catch-up starts from the new session's next_. Nothing is skipped on an answer.
  (void)from;
  (void)count;
}

void HitOrder::journal_restarted(std::uint64_t newest) {
  next_ = newest + 1;
  newest_ = newest;
}

}  // namespace imess::mqtt
