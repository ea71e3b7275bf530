// A measured point leaves the daemon: numbered and written to the journal first, then
// `Hit` and the 1996 `MeasPt` to every client. A client can never hold a hit the journal lacks.
#include <spdlog/spdlog.h>

#include "imess/net/server.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"

namespace imess::net {

void Server::send_hit(const core::Event& e) {
  protocol::HitMsg hit{0, e.id, {e.p.x(), e.p.y(), e.p.z()}, {e.dir.x(), e.dir.y(), e.dir.z()}, e.radius,
                       hal::seconds(e.time)};
  std::string line;
  try {
    line = journal_.append(hit);
  } catch (const journal::JournalError& err) {
    // The point is still sent (losing it would be worse); only Replay cannot give it again.
    spdlog::error("{}; the hit is sent to the clients anyway, but Replay cannot give it again", err.what());
    line = protocol::format_hit(hit);
  }
  broadcast(line);
  broadcast(protocol::format_meas_pt(hit.p));
  send_part_point(hit);
  arm_housekeeping();  // the journal's fdatasync when it falls due
}

// Qualify radius form dx dy dz: TipRadius through the parameter lane (as Set does, so the
// next hit already uses it) and the probe offset here, then the Qualified event to everyone.
void Server::qualify(Session& s, std::uint32_t slot, const protocol::Qualify& c) {
  core_.set_param(core::ParamId::TipRadius, c.radius);
  config_.probe_offset = {c.offset.x, c.offset.y, c.offset.z};
  reply(s, slot, protocol::format_ok("Qualify"));
  std::string text = "TipRadius ";
  protocol::append_fixed(text, c.radius, 4);
  text += " Offset";
  for (double v : config_.probe_offset) {
    text += ' ';
    protocol::append_fixed(text, v, 4);
  }
  text += " Form ";
  protocol::append_fixed(text, c.form, 4);
  broadcast(protocol::format_event("Qualified", text));
}

}  // namespace imess::net
