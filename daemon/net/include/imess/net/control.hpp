// Control: which session may move or change the machine — one at a time; everyone else
// observes (and may always stop). Pure logic, no sockets or clock, so it is tested directly.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "imess/protocol/commands.hpp"

namespace imess::net {

// Who holds (or asks for) control: the session, its Hello name ("client<N>" without one)
// and its host address.
struct Controller {
  std::uint32_t session = 0;
  std::string name;
  std::string host;
  friend bool operator==(const Controller&, const Controller&) = default;
};

// What a command needs: Open (anyone: Hello, Status, Get, Watch ...), Stop (anyone, never
// takes control: StopMv), Controlling (moves or changes the machine: takes control when it
// is free, refused from observers), Own (Take / Release: decided by Control itself),
// Operator (a client on a host that may control, whoever holds control: Key).
enum class CommandNeed { Open, Stop, Controlling, Own, Operator };
CommandNeed command_need(const protocol::Command& cmd);

enum class ControlOutcome {
  Kept,            // the session already held control
  Taken,           // control was free and is now the session's
  TakenOver,       // Take force: the previous owner lost it (stop the machine first)
  HandedOver,      // the owner was idle: control passed to the session that asked
  HeldByOther,     // another session holds control: NotInControl
  HostNotAllowed,  // the session's host is not in control.hosts
  ForceNotAllowed, // Take force from a host not in control.force_hosts
};

// What the machine and its owner are doing when another session asks for control
// (ControlService gathers it). The default is a busy owner: nothing is handed over.
struct Activity {
  bool machine_moves = true;   // a state but idle, free (loops open) or fault: jog, move, path, retract, home, stopping
  bool queue = true;           // queued moves (held ones and a paused queue too) or a program running
  double owner_silent_s = 0;   // since the owner's last command (blank lines are none)
};

class Control {
 public:
  // handover_s: an owner silent this long, with the machine at rest and nothing queued, hands
  // control to the next session that asks (control.handover_s); 0: never.
  explicit Control(double handover_s = 0) : handover_s_(handover_s) {}

  // A Controlling command from `who`; may_control: its host is in control.hosts.
  ControlOutcome claim(const Controller& who, bool may_control, const Activity& now = {});
  // Take [force]; on TakenOver and HandedOver, previous() names who lost control.
  ControlOutcome take(const Controller& who, bool may_control, bool force, bool may_force, const Activity& now = {});
  // Whether the owner would hand over now: it is idle (the I++ DME session never is: it
  // holds the machine from StartSession to EndSession).
  bool hands_over(const Activity& now) const;
  double handover_s() const { return handover_s_; }
  // Release or disconnect: true when the session held control (it is free now).
  bool release(std::uint32_t session);
  // Hello after taking control renames the owner.
  void rename(std::uint32_t session, const std::string& name);

  bool owns(std::uint32_t session) const { return owner_ && owner_->session == session; }
  const std::optional<Controller>& owner() const { return owner_; }
  const std::optional<Controller>& previous() const { return previous_; }

 private:
  std::optional<Controller> owner_, previous_;
  double handover_s_ = 0;
};

// The I++ DME session's number as a controller (never a MESSD client's: those count from 1).
inline constexpr std::uint32_t kIppSession = 0xFFFFFF00u;

inline constexpr std::size_t kMaxEventLine = 79;  // characters, without "\n" (1996: 80 with it)
inline constexpr std::size_t kMaxControlName = 24;

// "client<N>" or the Hello name, cut to kMaxControlName printable characters.
std::string controller_name(std::uint32_t session, const std::string& hello_name);
// "Control <name> <host>\n" or "Control none\n", never longer than kMaxEventLine.
std::string control_event(const std::optional<Controller>& owner);
// To the client that lost control to Take force: "Warn ControlTaken <name> <host> took over;
// machine stopped\n" (the tail left out when a long host needs the room), at most 79 characters.
std::string control_taken_warning(const Controller& by);
// For people: "messjog at 127.0.0.1 (client 3)".
std::string describe(const Controller& c);
// The Status value: "<name>@<host>" or "none".
std::string status_value(const std::optional<Controller>& owner);

}  // namespace imess::net
