// The control service: claims, take-overs and releases of the one machine, announced to all.
#include "imess/net/control_service.hpp"

#include <spdlog/fmt/fmt.h>

namespace imess::net {

// Idle: every axis stands (free, idle or faulted) and nothing waits to move it — no queued,
// held or planned move, no program (running or paused at an M0).
Activity ControlService::activity() const {
  const auto& snap = gateway_.snapshot();
  Activity a;
  a.machine_moves = !(snap.mode == core::Mode::Idle || snap.mode == core::Mode::Free || snap.mode == core::Mode::Fault);
  a.queue = gateway_.ids_pending() > 0 || gateway_.planner_holds() || gateway_.open_probe().has_value() || snap.path_running ||
            snap.path_held || programs_.running();
  a.owner_silent_s = std::chrono::duration<double>(Clock::now() - owner_heard_).count();
  return a;
}

void ControlService::heard(std::uint32_t session) {
  if (control_.owns(session)) owner_heard_ = Clock::now();
}

ControlOutcome ControlService::claim(const Controller& who, bool may_control) {
  const auto outcome = control_.claim(who, may_control, activity());
  if (outcome == ControlOutcome::Taken) {
    owner_heard_ = Clock::now();
    announce();
  }
  if (outcome == ControlOutcome::HandedOver) handed_over();
  return outcome;
}

void ControlService::handed_over() {
  owner_heard_ = Clock::now();
  log_limited(log_, spdlog::level::info, "control-handover",
              describe(*control_.owner()) + " took control from " + describe(*control_.previous()) + ", idle for " +
                  fmt::format("{:g}", control_.handover_s()) + " s or more with the machine at rest");
  announce();
}

ControlOutcome ControlService::take(const Controller& who, bool may_control, bool force, bool may_force) {
  const auto outcome = control_.take(who, may_control, force, may_force, activity());
  if (outcome == ControlOutcome::Taken || outcome == ControlOutcome::TakenOver) owner_heard_ = Clock::now();
  switch (outcome) {
    case ControlOutcome::Taken: announce(); break;
    case ControlOutcome::HandedOver: handed_over(); break;
    case ControlOutcome::TakenOver: {
      // The operator at the machine takes over: stop first (with a move queue, the previous
      // owner's moves would be paused and kept for it, as DirectCMM did; there is none yet).
      gateway_.stop("Take force");
      const auto& was = *control_.previous();
      observers_.each("ControlTaken", [&](MotionObserver& o) { o.control_taken(was, *control_.owner()); });
      log_limited(log_, spdlog::level::warn, "control-force", describe(*control_.owner()) + " took control over from " + describe(was));
      announce();
      break;
    }
    default: break;
  }
  return outcome;
}

void ControlService::take_over(const Controller& who) {
  const Controller was = *control_.owner();
  control_.take(who, true, true, true);
  owner_heard_ = Clock::now();
  observers_.each("ControlTaken", [&](MotionObserver& o) { o.control_taken(was, who); });
  announce();
}

bool ControlService::release(std::uint32_t session) { return control_.release(session); }

void ControlService::lose(std::uint32_t session, std::string_view why, bool gone) {
  // A program started detached by this client goes on without it (anyone may stop it, the
  // next controller may Pause, Resume or Abort it).
  if (gone && programs_.running() && programs_.detached() && control_.owns(session)) {
    control_.release(session);
    log_limited(log_, spdlog::level::info, "control-lost", "client " + std::to_string(session) + " " + std::string(why) +
                                                               ": program " + programs_.name() + " runs on detached");
    announce();
    return;
  }
  if (!control_.release(session)) return;
  gateway_.stop(why);  // the dead-man: whatever this client started must not outlive its control
  log_limited(log_, spdlog::level::info, "control-lost", "client " + std::to_string(session) + " " + std::string(why) + ": machine stopped");
  announce();
}

void ControlService::rename(std::uint32_t session, const std::string& name) { control_.rename(session, name); }

void ControlService::announce() {
  const auto& owner = control_.owner();
  log_limited(log_, spdlog::level::info, "control", owner ? "control: " + describe(*owner) : std::string("control: none"));
  observers_.each("Control", [&](MotionObserver& o) { o.control_changed(owner); });
}

}  // namespace imess::net
