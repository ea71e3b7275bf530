// HitSequencer: the expected number, the hits that came early, and when to ask for a Replay.
#include "hit_sequencer.hpp"

#include <algorithm>
#include <utility>

#include "imess/protocol/numbers.hpp"

namespace imess::messcap {

HitSequencer::HitSequencer(std::optional<std::uint64_t> last_kept) {
  if (last_kept) {
    next_ = *last_kept + 1;
    want_replay_ = true;  // whatever came after the file's last hit
  }
}

std::vector<protocol::HitMsg> HitSequencer::on_hit(const protocol::HitMsg& hit) {
  if (!next_) {
    if (probe_sent_ && outstanding_) {  // where to start is in the probe's answer
      ahead_.emplace(hit.seq, hit);
      return {};
    }
    next_ = hit.seq;  // no probe possible (a messd without Replay): start with this one
  }
  if (hit.seq < *next_) return {};  // held already (a Replay overlapping the live stream)
  ahead_.emplace(hit.seq, hit);
  return drain();
}

std::vector<protocol::HitMsg> HitSequencer::drain() {
  std::vector<protocol::HitMsg> due;
  for (;;) {
    while (skip_lost()) {
    }
    if (ahead_.empty()) break;
    auto first = ahead_.begin();
    if (first->first < *next_) {
      ahead_.erase(first);
    } else if (first->first == *next_) {
      due.push_back(first->second);
      ahead_.erase(first);
      ++*next_;
    } else {
      break;  // a gap: take_replay_request() asks for it
    }
  }
  return due;
}

void HitSequencer::on_connected() {
  outstanding_ = false;
  if (next_) want_replay_ = true;  // whatever was measured while we were away
  else probe_sent_ = false;        // the probe is asked again on the new link
}

void HitSequencer::skip_to(std::uint64_t seq, const std::string& why) {
  skipped_ += seq - *next_;
  skipped_ranges_.emplace_back(*next_, seq - 1);
  notes_.push_back((seq - 1 == *next_ ? "hit " + std::to_string(*next_) + " is"
                                      : "hits " + std::to_string(*next_) + " to " + std::to_string(seq - 1) + " are") +
                   " missing: " + why);
  next_ = seq;
}

bool HitSequencer::skip_lost() {
  if (!next_) return false;
  while (!lost_.empty() && lost_.begin()->second < *next_) lost_.erase(lost_.begin());  // passed already
  if (lost_.empty() || lost_.begin()->first > *next_) return false;
  const std::uint64_t to = lost_.begin()->second + 1;
  lost_.erase(lost_.begin());
  skip_to(to, to - *next_ == 1 ? "its record in messd's journal is damaged or missing"
                               : "their records in messd's journal are damaged or missing");
  return true;
}

std::vector<protocol::HitMsg> HitSequencer::on_replay_lost(std::uint64_t first, std::uint64_t last) {
  if (next_ && last < *next_) return {};
  auto [it, added] = lost_.emplace(first, last);
  if (!added) it->second = std::max(it->second, last);
  if (!next_) return {};
  return drain();
}

std::string HitSequencer::lost_text() const {
  std::string text;
  for (std::size_t i = 0; i < skipped_ranges_.size() && i <= 5; ++i) {
    const auto [a, b] = skipped_ranges_[i];
    text += (i ? ", " : "") + (i == 5 ? std::string("...")
                                      : a == b ? std::to_string(a) : std::to_string(a) + " to " + std::to_string(b));
  }
  return text;
}

std::vector<protocol::HitMsg> HitSequencer::on_replay_ok(std::uint64_t count, std::uint64_t newest) {
  outstanding_ = false;
  if (!next_) {  // the probe's answer: start after the newest hit, or with an earlier live one
    next_ = newest + 1;
    if (!ahead_.empty()) next_ = std::min(*next_, ahead_.begin()->first);
    return drain();
  }
  if (newest + 1 < *next_) {
    // The journal is behind what we hold: another journal (a new directory, another machine).
    notes_.push_back("messd's journal ends at hit " + std::to_string(newest) + " but this capture holds up to " +
                     std::to_string(*next_ - 1) + "; another journal? continuing with its numbers");
    next_ = newest + 1;
    ahead_.clear();
    return {};
  }
  if (*next_ <= newest) {
    if (count > 0) {
      want_replay_ = true;  // capped: more to fetch
    } else {
      // Journaled numbers it could not read back (a failed write): do not ask forever.
      std::uint64_t to = ahead_.empty() ? newest + 1 : ahead_.begin()->first;
      skip_to(to, "messd's journal could not give them");
      return drain();
    }
  }
  return {};
}

std::vector<protocol::HitMsg> HitSequencer::on_replay_gone(std::uint64_t oldest) {
  outstanding_ = false;
  if (!next_ || oldest <= *next_) return {};
  skip_to(oldest, "rotated out of messd's journal before they could be fetched");
  want_replay_ = true;
  return drain();
}

std::vector<protocol::HitMsg> HitSequencer::on_replay_refused() {
  outstanding_ = false;
  refused_ = true;
  want_replay_ = false;
  if (ahead_.empty()) return {};
  if (!next_) next_ = ahead_.begin()->first;
  if (ahead_.begin()->first > *next_) skip_to(ahead_.begin()->first, "this messd has no Replay");
  return drain();
}

std::optional<std::uint64_t> HitSequencer::take_replay_request() {
  if (refused_ || outstanding_) return std::nullopt;
  if (!next_) {
    if (probe_sent_) return std::nullopt;
    probe_sent_ = outstanding_ = true;
    return protocol::kMaxSequenceNumber;
  }
  if (!want_replay_ && ahead_.empty()) return std::nullopt;
  want_replay_ = false;
  outstanding_ = true;
  return *next_;
}

std::vector<std::string> HitSequencer::take_notes() { return std::exchange(notes_, {}); }

}  // namespace imess::messcap
