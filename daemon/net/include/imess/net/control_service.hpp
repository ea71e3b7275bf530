// ControlService: who may move the machine, for every front end — the one owner (a MESSD
// client or the I++ DME session), claims, take-overs and releases, each announced through the
// observer fan-out (MESSD's `Control` event, the warning to whoever lost it). The rules
// themselves are Control's (pure logic); stops go through the MotionGateway. An idle owner
// (the machine at rest, nothing queued, no command for control.handover_s) hands over to the
// next client that asks.
#pragma once
#include <chrono>
#include <optional>
#include <string>
#include <string_view>

#include "imess/net/control.hpp"
#include "imess/net/log_limiter.hpp"
#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/program_runner.hpp"

namespace imess::net {

class ControlService {
 public:
  using Clock = std::chrono::steady_clock;
  ControlService(MotionGateway& gateway, const ProgramRunner& programs, Observers& observers, LogLimiter& log,
                 double handover_s = 0)
      : gateway_(gateway), programs_(programs), observers_(observers), log_(log), control_(handover_s) {}

  const std::optional<Controller>& owner() const { return control_.owner(); }
  bool owns(std::uint32_t session) const { return control_.owns(session); }
  // A command that needs control from `who`: kept, taken when free or handed over by an idle
  // owner (announced).
  ControlOutcome claim(const Controller& who, bool may_control);
  // Take [force]: as claim; a forced take-over stops the machine first and warns who lost it.
  ControlOutcome take(const Controller& who, bool may_control, bool force, bool may_force);
  // A command line from `session` (blank lines are none): the owner's silence starts anew.
  void heard(std::uint32_t session);
  // What the machine and the owner do now (whether an idle owner would hand over).
  Activity activity() const;
  double handover_s() const { return control_.handover_s(); }
  // Taken over without asking (the I++ DME session at StartSession, or back from its operator).
  void take_over(const Controller& who);
  bool release(std::uint32_t session);  // true when it held control (free now; not announced)
  // release + stop + announce; `gone`: the client left (disconnected, dropped), so a program
  // it ran detached goes on. The dead-man: what a client started must not outlive its control.
  void lose(std::uint32_t session, std::string_view why, bool gone);
  void rename(std::uint32_t session, const std::string& name);
  void announce();  // the owner to the log and every observer

 private:
  void handed_over();  // logged and announced
  MotionGateway& gateway_;
  const ProgramRunner& programs_;
  Observers& observers_;
  LogLimiter& log_;
  Control control_;
  Clock::time_point owner_heard_{};  // the owner's last command, or when it took control
};

}  // namespace imess::net
