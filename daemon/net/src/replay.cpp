// Replay <from-seq>: journaled hits to the asking client only, as Hit lines exactly as sent live,
// `Replay Lost a b` in the place of numbers the journal cannot give, then `Ok Replay <count>
// <newest>`. At most kMaxReplayHits hits per request: one reply stays small and quick.
#include <spdlog/spdlog.h>

#include "imess/net/hit_service.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

std::string HitService::replay(std::uint32_t client, std::uint64_t from) const {
  journal::ReadResult r;
  try {
    r = journal_.read(from, protocol::kMaxReplayHits);
  } catch (const journal::JournalError& e) {
    spdlog::error("Replay {} for client {}: {}", from, client, e.what());
    return protocol::format_err(protocol::ErrorCode::Internal, "the journal could not be read; see the daemon's log");
  }
  if (r.rotated_away) {
    return protocol::format_err(protocol::ErrorCode::NotInJournal,
                                "hit " + std::to_string(from) + " is no longer in the journal; the oldest kept is " +
                                    std::to_string(r.oldest));
  }
  std::string lines;
  auto lost = r.lost.begin();
  for (std::size_t i = 0; i <= r.lines.size(); ++i) {
    for (; lost != r.lost.end() && lost->before == i; ++lost) lines += protocol::format_replay_lost(lost->first, lost->last);
    if (i < r.lines.size()) lines += r.lines[i];
  }
  // count: the numbers from from-seq on that this answer covers, given or named lost.
  return lines + protocol::format_ok("Replay", std::to_string(r.covered) + " " + std::to_string(r.newest));
}

}  // namespace imess::net
