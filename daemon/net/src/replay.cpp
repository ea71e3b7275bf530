// Replay <from-seq>: journaled hits to the asking client only, as Hit lines exactly as sent
// live, then `Ok Replay <count> <newest>`. At most kMaxReplayHits per request, so one reply
// stays small against the session's write queue and the io thread is busy only briefly.
#include <spdlog/spdlog.h>

#include "imess/net/server.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

void Server::on_replay(Session& s, std::uint32_t slot, std::uint64_t from) {
  journal::ReadResult r;
  try {
    r = journal_.read(from, protocol::kMaxReplayHits);
  } catch (const journal::JournalError& e) {
    spdlog::error("Replay {} for client {}: {}", from, s.id(), e.what());
    reply(s, slot, protocol::format_err(protocol::ErrorCode::Internal, "the journal could not be read; see the daemon's log"));
    return;
  }
  if (r.rotated_away) {
    reply(s, slot, protocol::format_err(protocol::ErrorCode::NotInJournal,
                                        "hit " + std::to_string(from) + " is no longer in the journal; the oldest kept is " +
                                            std::to_string(r.oldest)));
    return;
  }
  std::string lines;
  for (const auto& l : r.lines) lines += l;
  reply(s, slot, lines + protocol::format_ok("Replay", std::to_string(r.lines.size()) + " " + std::to_string(r.newest)));
}

}  // namespace imess::net
