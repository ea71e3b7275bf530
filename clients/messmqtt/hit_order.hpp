// HitOrder: the bridge publishes each broker session's hits in strictly rising seq order,
// starting after the broker's watermark. A Hit line from messd — live or replayed, they look
// alike — is published when it is the next one, dropped when it was already published, and a
// gap when it is further on: then the bridge asks messd to `Replay` from the next one. So a
// subscriber sees every seq, in order, with repeats only after a break (dedup by seq).
#pragma once
#include <cstdint>
#include <optional>

namespace imess::mqtt {

class HitOrder {
 public:
  enum class Offer { Publish, Already, Gap };

  // A new broker session, or messd came back: publish from `next` on; what messd holds is
  // unknown until a Replay answers.
  void start_at(std::uint64_t next) {
    next_ = next;
    newest_.reset();
  }
  void messd_reconnected() { newest_.reset(); }

  Offer offer(std::uint64_t seq);
  // Seqs first … last cannot be published (damaged in the journal): pass them when next.
  bool pass_lost(std::uint64_t first, std::uint64_t last);
  // Hits before `oldest` were rotated out of messd's journal: continue there.
  void rotated_out(std::uint64_t oldest);
  // `Ok Replay count newest` of a catch-up from `from`.
  void replay_answered(std::uint64_t from, std::uint64_t count, std::uint64_t newest);

  // messd's journal ends before next() - 1 (its numbers are given again after a power cut, or
  // the journal is new): publish from newest + 1.
  void journal_restarted(std::uint64_t newest);

  // Whether a catch-up `Replay next()` is due (none is in flight, and messd holds more than was
  // published, or what it holds is unknown).
  bool catch_up_due() const { return !replay_in_flight_ && (!newest_ || *newest_ >= next_); }
  void catch_up_sent() { replay_in_flight_ = true; }
  void catch_up_dropped() { replay_in_flight_ = false; }  // messd's link broke before the answer

  std::uint64_t next() const { return next_; }
  std::optional<std::uint64_t> newest() const { return newest_; }

 private:
  std::uint64_t next_ = 1;
  std::optional<std::uint64_t> newest_;
  bool replay_in_flight_ = false;
};

}  // namespace imess::mqtt
