// Wire words for the motion loop's enums, in one place.
#include "imess/net/wording.hpp"

#include "imess/protocol/messages.hpp"

namespace imess::net {

using core::CommandKind;
using core::FaultKind;
using core::Mode;
using core::Refusal;
using core::Warning;
using protocol::ErrorCode;

std::string_view mode_name(Mode m) {
  switch (m) {
    case Mode::Free: return "free";
    case Mode::Idle: return "idle";
    case Mode::Jog: return "jog";
    case Mode::Move: return "move";
    case Mode::Retract: return "retract";
    case Mode::Home: return "home";
    case Mode::Fault: return "fault";
    case Mode::Stopping: return "stopping";
    case Mode::Path: return "move";  // queued segments: the 1996 clients' word for a motor move
  }
  return "unknown";
}

std::string_view command_verb(CommandKind k) {
  switch (k) {
    case CommandKind::StartMv: return "StartMv";
    case CommandKind::ForcePt: return "ForcePt";
    case CommandKind::GoTo: return "GoTo";
    case CommandKind::Home: return "Home";
    case CommandKind::Free: return "Free";
    case CommandKind::Reset: return "Reset";
    case CommandKind::HandMv: return "HandMv";
    case CommandKind::Pause: return "Pause";
    case CommandKind::Resume: return "Resume";
    case CommandKind::JogAx: return "JogAx";
  }
  return "Unknown";
}

Wording warning_wording(Warning w) {
  switch (w) {
    case Warning::TipNotFree: return {"TipNotFree", "could not free the tip automatically; do it by hand"};
    case Warning::UnexpectedHit: return {"UnexpectedHit", "probe touched during a move; stopped, retracted, no point"};
    case Warning::HandHitNoTravel: return {"HandHitNoTravel", "hand hit ignored: travel HandTravel mm before touching"};
    case Warning::HandHitTooSoon: return {"HandHitTooSoon", "hand hit ignored: within HandInterval s of the last"};
    case Warning::HitIgnored: return {"HitIgnored", "probe touched while the machine stands; no point taken"};
    case Warning::HomingFailed: return {"HomingFailed", "reference search failed; the machine is not homed"};
    case Warning::MoveRefused: return {"MoveRefused", "the next move could not start (limit or tip touched)"};
    case Warning::HostStall:
      return {"HostStall", "ms stall beyond the card's lead: it braked; queue failed"};
  }
  return {"Unknown", ""};
}

Wording fault_wording(FaultKind f) {
  switch (f) {
    case FaultKind::CommLost: return {"CommLost", "the controller stopped answering; loops opened"};
    case FaultKind::FollowingError: return {"FollowingError", "an axis lagged beyond its limit (blocked?); loops open"};
    case FaultKind::Emergency: return {"Emergency", "E-stop or probe overtravel; free the probe, then Reset"};
    case FaultKind::DriveNotReady: return {"DriveNotReady", "a drive reports not ready; check power, then Reset"};
    case FaultKind::ConfigError: return {"ConfigError", "the controller reports a configuration or data error"};
    case FaultKind::StopInput: return {"StopInput", "STOP input: steps may be lost; release it, Reset, Home"};
    case FaultKind::SafetyInput1: return {"SafetyInput1", "safety input 1 opened; outputs off; close it, Reset"};
    case FaultKind::SafetyInput2: return {"SafetyInput2", "safety input 2 opened; outputs off; close it, Reset"};
    case FaultKind::SafetyInput3: return {"SafetyInput3", "safety input 3 opened; outputs off; close it, Reset"};
    case FaultKind::SafetyInput4: return {"SafetyInput4", "safety input 4 opened; outputs off; close it, Reset"};
    case FaultKind::LinkErrors: return {"LinkErrors", "the card's line lost or damaged frames; axes braked; Reset"};
  }
  return {"Unknown", ""};
}

Wording fail_wording(core::FailReason f) {
  switch (f) {
    case core::FailReason::Stopped: return {"Stopped", "a stop dropped the queue"};
    case core::FailReason::OutOfTravel: return {"OutOfTravel", "the segment leaves the travel"};
    case core::FailReason::IntoLimit: return {"IntoLimit", "a limit switch stopped the machine"};
    case core::FailReason::Faulted: return {"Faulted", "fault, or the backend cannot follow a path"};
    case core::FailReason::UnexpectedHit: return {"UnexpectedHit", "probe touched: stopped, retracted, no point"};
    case core::FailReason::TipTouched: return {"TipTouched", "probe deflected: the queue did not start"};
    case core::FailReason::OffPath: return {"OffPath", "the machine is not at the queue's start"};
    case core::FailReason::PartNotFound:
      return {"PartNotFound", "no edge up to SearchDist past the target"};
    case core::FailReason::Refused: return {"Refused", "not plannable from where the Probe ended"};
    case core::FailReason::ProbeOff: return {"ProbeOff", "the probe is switched off: SetOut <id> <its output> on first"};
    case core::FailReason::HostStall: return {"HostStall", "messd stalled beyond the card's lead; resend"};
    case core::FailReason::ScanLostContact: return {"ScanLostContact", "the probe left the surface mid-scan: stopped"};
    case core::FailReason::ScanOverRange: return {"ScanOverRange", "probe pressed to its range: stopped, backed off"};
    case core::FailReason::NoMeasuringProbe: return {"NoMeasuringProbe", "this probe measures no deflection: no scan"};
  }
  return {"Unknown", ""};
}

RefusalWording refusal_wording(Refusal r) {
  switch (r) {
    case Refusal::None: return {ErrorCode::Internal, ""};
    case Refusal::TipTouched: return {ErrorCode::TipTouched, "tip is touched, can't move - move the tip free by hand"};
    case Refusal::IntoLimit: return {ErrorCode::IntoLimit, "every requested axis points further into its limit; only moves away are allowed"};
    case Refusal::Busy: return {ErrorCode::Busy, "busy: homing, retract or a move is running; StopMv stops it"};
    case Refusal::NotSimulated:
      return {ErrorCode::NotSimulated,
              "HandMv needs a simulated machine that can be pushed by hand (the servo-card or drive-kit simulation; steppers hold their position)"};
    case Refusal::LoopsClosed: return {ErrorCode::LoopsClosed, "the position loops hold the machine; send Free (or wait IdleOpen s) first"};
    case Refusal::OutOfTravel: return {ErrorCode::OutOfTravel, "target outside the travel; Status and the configuration give the axis ranges"};
    case Refusal::Faulted: return {ErrorCode::Faulted, "machine fault; remove the cause, then send Reset"};
    case Refusal::Hardware: return {ErrorCode::Internal, "the controller did not accept the command; see the daemon log"};
    case Refusal::TooSlow: return {ErrorCode::BadValue, "speed below the minimum of 0.01 mm/s (per axis for StartMv)"};
  }
  return {ErrorCode::Internal, "unknown refusal"};
}

std::string failed_line(std::uint32_t id, core::FailReason why) {
  auto w = fail_wording(why);
  return protocol::format_event("Failed", std::to_string(id) + " " + std::string(w.name) + " " + std::string(w.text));
}

}  // namespace imess::net
