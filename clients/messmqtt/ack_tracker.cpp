// The PUBACK watermark (ack_tracker.hpp).
#include "ack_tracker.hpp"

namespace imess::mqtt {

bool AckTracker::acknowledged(int mid) {
  auto it = in_flight_.find(mid);
  if (it == in_flight_.end()) return false;  // a PUBACK of an earlier connection's message
  const auto seq = it->second;
  in_flight_.erase(it);
  if (seq <= acked_) return false;
  done_above_.insert(seq);
  return advance();
}

bool AckTracker::skip(std::uint64_t first, std::uint64_t last) {
  if (last <= acked_) return false;
  if (first <= acked_ + 1) {  // the usual case: the next ones are the lost ones
    acked_ = last;
    while (!done_above_.empty() && *done_above_.begin() <= acked_) done_above_.erase(done_above_.begin());
    advance();
    return true;
  }
  for (auto s = first; s <= last && done_above_.size() < 100000; ++s) done_above_.insert(s);
  return advance();
}

bool AckTracker::advance() {
  bool moved = false;
  while (!done_above_.empty() && *done_above_.begin() == acked_ + 1) {
    ++acked_;
    done_above_.erase(done_above_.begin());
    moved = true;
  }
  return moved;
}

}  // namespace imess::mqtt
