// AckTracker: which journaled hits the broker has acknowledged. Each hit is published with QoS 1
// and gets a message id (mid); the broker's PUBACK for that mid acknowledges its seq. `acked()`
// is the watermark: every seq up to it is acknowledged (or was lost in messd's journal and
// skipped), so after any break the bridge republishes from acked() + 1 and loses nothing.
#pragma once
#include <cstdint>
#include <map>
#include <set>

namespace imess::mqtt {

class AckTracker {
 public:
  explicit AckTracker(std::uint64_t acked = 0) : acked_(acked) {}

  // A hit published as message `mid`.
  void published(int mid, std::uint64_t seq) { in_flight_[mid] = seq; }
  // The broker's PUBACK for `mid`; true when the watermark moved.
  bool acknowledged(int mid);
  // Seqs first … last will never be published (damaged in the journal, rotated out): they
  // count as done so the watermark can pass them. True when it moved.
  bool skip(std::uint64_t first, std::uint64_t last);
  // The broker connection ended: what was in flight is unacknowledged and will be sent again.
  void connection_lost() { in_flight_.clear(); done_above_.clear(); }
  // Start again at `acked` (messd's journal is not the one the watermark was of).
  void restart_at(std::uint64_t acked) { connection_lost(); acked_ = acked; }

  std::uint64_t acked() const { return acked_; }
  std::size_t in_flight() const { return in_flight_.size(); }

 private:
  bool advance();

  std::uint64_t acked_;
  std::map<int, std::uint64_t> in_flight_;  // mid -> seq
  std::set<std::uint64_t> done_above_;      // acknowledged or skipped, above the watermark
};

}  // namespace imess::mqtt
