// The MESSD side of control: the implicit take of a command that needs it, Take and Release
// (the rules and announcements are ControlService's).
#include <spdlog/spdlog.h>

#include "imess/net/messd_dispatch.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

using protocol::ErrorCode;
using protocol::format_err;
using protocol::format_ok;

namespace {
std::string held_text(const Controller& owner) {
  return "the machine is controlled by " + describe(owner) + "; StopMv is open to all, Status shows the owner";
}
std::string host_text(const Session& s) {
  if (!s.info().observe_reason.empty()) return s.info().observe_reason + "; StopMv is open to all";
  return "host " + s.host() + " may observe but not control the machine (control.hosts in the daemon's configuration); StopMv is open to all";
}
}  // namespace

Controller MessdDispatch::controller(Session& s) const { return {s.id(), controller_name(s.id(), s.info().name), s.host()}; }

// Returns false (and answers the slot) when cmd may not run for this session.
bool MessdDispatch::allowed(Session& s, const protocol::Command& cmd, std::uint32_t slot) {
  const CommandNeed need = command_need(cmd);
  if (need == CommandNeed::Operator && !s.info().may_control) {  // the operator's keys: from a control host
    reply(s, slot, format_err(ErrorCode::HostNotAllowed, host_text(s)));
    return false;
  }
  if (need != CommandNeed::Controlling) return true;
  switch (control_.claim(controller(s), s.info().may_control)) {
    case ControlOutcome::Kept: return true;
    case ControlOutcome::Taken: return true;       // announced
    case ControlOutcome::HandedOver: return true;  // from an idle owner; announced
    case ControlOutcome::HostNotAllowed:
      log_limited(log_, spdlog::level::info, "refused-control", "client " + std::to_string(s.id()) + ": " + host_text(s));
      reply(s, slot, format_err(ErrorCode::HostNotAllowed, host_text(s)));
      return false;
    default:
      reply(s, slot, format_err(ErrorCode::NotInControl, held_text(*control_.owner())));
      return false;
  }
}

void MessdDispatch::take(Session& s, std::uint32_t slot, const protocol::Take& t) {
  auto outcome = control_.take(controller(s), s.info().may_control, t.force, s.info().may_force);
  switch (outcome) {
    case ControlOutcome::Kept: reply(s, slot, format_ok("Take")); return;
    case ControlOutcome::Taken:       // announced
    case ControlOutcome::HandedOver:  // from an idle owner; announced
    case ControlOutcome::TakenOver:   // the machine stopped, who lost it warned, announced
      reply(s, slot, format_ok("Take"));
      return;
    case ControlOutcome::HeldByOther:
      reply(s, slot, format_err(ErrorCode::NotInControl, held_text(*control_.owner()) +
                                                             (s.info().may_force ? "; Take force takes over" : "")));
      return;
    case ControlOutcome::HostNotAllowed: reply(s, slot, format_err(ErrorCode::HostNotAllowed, host_text(s))); return;
    case ControlOutcome::ForceNotAllowed:
      reply(s, slot, format_err(ErrorCode::HostNotAllowed,
                                "host " + s.host() + " may not force a take-over (control.force_hosts; by default the machine's own host)"));
      return;
  }
}

void MessdDispatch::release(Session& s, std::uint32_t slot) {
  const auto& owner = control_.owner();
  if (owner && owner->session != s.id()) {
    reply(s, slot, format_err(ErrorCode::NotInControl, held_text(*owner) + "; only the owner can release it"));
    return;
  }
  control_.lose(s.id(), "released control", false);
  reply(s, slot, format_ok("Release"));
}

}  // namespace imess::net
