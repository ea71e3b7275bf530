// HitSequencer: turns Hit lines — live, replayed, repeated after a reconnect, out of order
// around a Replay — into the gap-free, duplicate-free sequence to write, and says when to ask
// messd for a Replay (after a reconnect, on a gap, when a capped Replay has more to give).
// Pure logic, no I/O: capture_command.cpp feeds it lines and sends what it asks for.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "imess/protocol/messages.hpp"

namespace imess::messcap {

class HitSequencer {
 public:
  // last_kept: the last hit number already in the output file (--append); none: a new capture,
  // which takes every hit journaled after it connected — the first Replay request is then a
  // probe (`Replay <max>`, answered `Ok Replay 0 <newest>`) that tells where that is.
  explicit HitSequencer(std::optional<std::uint64_t> last_kept = std::nullopt);

  // A Hit line arrived. Returns the hits now due to be written, in sequence order.
  std::vector<protocol::HitMsg> on_hit(const protocol::HitMsg& hit);

  // A new connection: what a Replay asked on the old one will not be answered.
  void on_connected();
  // The answers to a Replay; each returns the hits that became due (when missing ones are
  // given up, those that came after them).
  // `Ok Replay count newest`.
  std::vector<protocol::HitMsg> on_replay_ok(std::uint64_t count, std::uint64_t newest);
  // `Err 212 ... the oldest kept is N`: the hits before N are gone; carry on from N.
  std::vector<protocol::HitMsg> on_replay_gone(std::uint64_t oldest);
  // Any other Err to a Replay (an older messd without a journal): no more Replay requests.
  std::vector<protocol::HitMsg> on_replay_refused();
  // `Replay Lost first last`: messd journaled those numbers but cannot give them (damaged
  // records); they are skipped, with a note, when the capture reaches them.
  std::vector<protocol::HitMsg> on_replay_lost(std::uint64_t first, std::uint64_t last);

  // The number to send `Replay` from now, if one is needed and none is outstanding.
  std::optional<std::uint64_t> take_replay_request();

  std::optional<std::uint64_t> next() const { return next_; }  // the number expected next
  std::uint64_t skipped() const { return skipped_; }            // hits that could not be had
  // Their numbers for the user, "5, 11 to 49" (at most 5 ranges, then "..."); empty when none.
  std::string lost_text() const;
  // Notes for the user (hits skipped, a journal that starts again); taken once.
  std::vector<std::string> take_notes();

 private:
  std::vector<protocol::HitMsg> drain();
  void skip_to(std::uint64_t seq, const std::string& why);
  bool skip_lost();  // next_ is in a range messd named lost: skip past it
  std::optional<std::uint64_t> next_;
  std::map<std::uint64_t, protocol::HitMsg> ahead_;  // arrived before the ones missing in between
  bool want_replay_ = false, outstanding_ = false, refused_ = false, probe_sent_ = false;
  std::uint64_t skipped_ = 0;
  std::map<std::uint64_t, std::uint64_t> lost_;  // first -> last, named by Replay Lost, not yet reached
  std::vector<std::pair<std::uint64_t, std::uint64_t>> skipped_ranges_;
  std::vector<std::string> notes_;
};

}  // namespace imess::messcap
