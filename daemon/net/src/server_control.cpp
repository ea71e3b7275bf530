// The server's side of control: implicit take, Take / Release, announcing the owner, and the
// one stop helper every control-related stop goes through.
#include <spdlog/spdlog.h>

#include "imess/net/server.hpp"
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
  return "host " + s.host() + " may observe but not control the machine (control.hosts in the daemon's configuration); StopMv is open to all";
}
}  // namespace

Controller Server::controller(Session& s) const { return {s.id(), controller_name(s.id(), s.info().name), s.host()}; }

// The stop lane (read first in every motion cycle); the queued moves the loop has not
// received fail here, those it has fail there (their ids were stamped before this stop).
void Server::stop_machine(std::string_view who) {
  core_.request_stop();
  drop_planned(core::FailReason::Stopped);
  if (program_.running()) end_program(ProgramOutcome::Aborted, program_.shown_block > 0 ? program_.items[program_.shown_block - 1].line : 0, std::string(who));
}

void Server::announce_control() {
  const auto& owner = control_.owner();
  log_limited(spdlog::level::info, "control", owner ? "control: " + describe(*owner) : std::string("control: none"));
  broadcast(control_event(owner));
}

void Server::lose_control(Session& s, std::string_view why, bool gone) {
  // A program started detached by this client goes on without it (anyone may stop it, the
  // next controller may Pause, Resume or Abort it).
  if (gone && program_.running() && program_.detached && control_.owns(s.id())) {
    control_.release(s.id());
    log_limited(spdlog::level::info, "control-lost", "client " + std::to_string(s.id()) + " " + std::string(why) +
                                                         ": program " + program_.loaded->name + " runs on detached");
    announce_control();
    return;
  }
  if (!control_.release(s.id())) return;
  stop_machine(why);  // the dead-man: whatever this client started must not outlive its control
  log_limited(spdlog::level::info, "control-lost", "client " + std::to_string(s.id()) + " " + std::string(why) + ": machine stopped");
  announce_control();
}

// Returns false (and answers the slot) when cmd may not run for this session.
bool Server::allowed(Session& s, const protocol::Command& cmd, std::uint32_t slot) {
  if (command_need(cmd) != CommandNeed::Controlling) return true;
  switch (control_.claim(controller(s), s.info().may_control)) {
    case ControlOutcome::Kept: return true;
    case ControlOutcome::Taken: announce_control(); return true;
    case ControlOutcome::HostNotAllowed:
      log_limited(spdlog::level::info, "refused-control", "client " + std::to_string(s.id()) + ": " + host_text(s));
      reply(s, slot, format_err(ErrorCode::HostNotAllowed, host_text(s)));
      return false;
    default:
      reply(s, slot, format_err(ErrorCode::NotInControl, held_text(*control_.owner())));
      return false;
  }
}

void Server::take(Session& s, std::uint32_t slot, const protocol::Take& t) {
  auto outcome = control_.take(controller(s), s.info().may_control, t.force, s.info().may_force);
  switch (outcome) {
    case ControlOutcome::Kept: reply(s, slot, format_ok("Take")); return;
    case ControlOutcome::Taken:
      announce_control();
      reply(s, slot, format_ok("Take"));
      return;
    case ControlOutcome::TakenOver: {
      // The operator at the machine takes over: stop first (with a move queue, the previous
      // owner's moves would be paused and kept for it, as DirectCMM did; there is none yet).
      stop_machine("Take force");
      const auto& was = *control_.previous();
      if (auto it = sessions_.find(was.session); it != sessions_.end())
        send(*it->second, control_taken_warning(*control_.owner()));
      log_limited(spdlog::level::warn, "control-force", describe(*control_.owner()) + " took control over from " + describe(was));
      announce_control();
      reply(s, slot, format_ok("Take"));
      return;
    }
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

void Server::release(Session& s, std::uint32_t slot) {
  const auto& owner = control_.owner();
  if (owner && owner->session != s.id()) {
    reply(s, slot, format_err(ErrorCode::NotInControl, held_text(*owner) + "; only the owner can release it"));
    return;
  }
  lose_control(s, "released control", false);
  reply(s, slot, format_ok("Release"));
}

}  // namespace imess::net
