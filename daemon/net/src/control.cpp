// The control rules: who may move the machine, implicit take, Take force, release.
#include "imess/net/control.hpp"

#include <algorithm>
#include <type_traits>

#include "imess/protocol/verbs.hpp"

namespace imess::net {

// Declared with each verb (protocol/src/verb_table.cpp); an undeclared command needs control.
CommandNeed command_need(const protocol::Command& cmd) {
  const protocol::VerbSpec* verb = protocol::declaration_of(cmd);
  if (!verb) return CommandNeed::Controlling;
  switch (verb->access) {
    case protocol::Access::Open: return CommandNeed::Open;
    case protocol::Access::Controlling: return CommandNeed::Controlling;
    case protocol::Access::Moving: return CommandNeed::Controlling;  // ForcePt too: a point in everyone's capture
    case protocol::Access::Stop: return CommandNeed::Stop;
    case protocol::Access::Own: return CommandNeed::Own;
    case protocol::Access::Operator: return CommandNeed::Operator;
  }
  return CommandNeed::Controlling;
}

bool Control::hands_over(const Activity& now) const {
  return owner_ && owner_->session != kIppSession && handover_s_ > 0 && !now.machine_moves && !now.queue &&
         now.owner_silent_s >= handover_s_;
}

ControlOutcome Control::claim(const Controller& who, bool may_control, const Activity& now) {
  if (owns(who.session)) return ControlOutcome::Kept;
  if (!may_control) return ControlOutcome::HostNotAllowed;
  if (owner_) {
    if (!hands_over(now)) return ControlOutcome::HeldByOther;
    previous_ = owner_;
    owner_ = who;
    return ControlOutcome::HandedOver;
  }
  owner_ = who;
  return ControlOutcome::Taken;
}

ControlOutcome Control::take(const Controller& who, bool may_control, bool force, bool may_force, const Activity& now) {
  if (owns(who.session)) return ControlOutcome::Kept;
  if (!may_control) return ControlOutcome::HostNotAllowed;
  if (!owner_) {
    owner_ = who;
    return ControlOutcome::Taken;
  }
  if (!force || (!may_force && hands_over(now))) return claim(who, may_control, now);  // HandedOver when idle
  if (!may_force) return ControlOutcome::ForceNotAllowed;
  previous_ = owner_;
  owner_ = who;
  return ControlOutcome::TakenOver;
}

bool Control::release(std::uint32_t session) {
  if (!owns(session)) return false;
  owner_.reset();
  return true;
}

void Control::rename(std::uint32_t session, const std::string& name) {
  if (owns(session)) owner_->name = name;
}

std::string controller_name(std::uint32_t session, const std::string& hello_name) {
  if (hello_name.empty()) return "client" + std::to_string(session);
  return hello_name.substr(0, kMaxControlName);
}

namespace {
// "<name> <host>" in at most `room` characters: a long (scoped IPv6) host shortens the name
// first (to one letter at least), then the host.
std::string name_and_host(std::string name, std::string host, std::size_t room) {
  if (name.size() + 1 + host.size() > room) {
    name = name.substr(0, std::max<std::size_t>(1, room - 1 - std::min(host.size(), room - 2)));
    host = host.substr(0, room - 1 - name.size());
  }
  return name + " " + host;
}
}  // namespace

std::string control_event(const std::optional<Controller>& owner) {
  if (!owner) return "Control none\n";
  const std::string verb = "Control ";
  return verb + name_and_host(owner->name, owner->host, kMaxEventLine - verb.size()) + "\n";
}

std::string control_taken_warning(const Controller& by) {
  const std::string head = "Warn ControlTaken ", tail = " took over; machine stopped";
  std::string who = name_and_host(by.name, by.host, kMaxEventLine - head.size());
  if (head.size() + who.size() + tail.size() > kMaxEventLine) return head + who + "\n";  // the names matter more
  return head + who + tail + "\n";
}

std::string describe(const Controller& c) {
  if (c.session == kIppSession) return c.name + " at " + c.host + " (the I++ DME session)";
  return c.name + " at " + c.host + " (client " + std::to_string(c.session) + ")";
}

std::string status_value(const std::optional<Controller>& owner) {
  return owner ? owner->name + "@" + owner->host : "none";
}

}  // namespace imess::net
