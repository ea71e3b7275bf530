// Wire words for the motion loop's enums, in one place.
#include "imess/net/wording.hpp"

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
  }
  return "unknown";
}

std::string_view command_verb(CommandKind k) {
  switch (k) {
    case CommandKind::StartMv: return "StartMv";
    case CommandKind::StopMv: return "StopMv";
    case CommandKind::ForcePt: return "ForcePt";
    case CommandKind::GoTo: return "GoTo";
    case CommandKind::Home: return "Home";
    case CommandKind::Free: return "Free";
    case CommandKind::Reset: return "Reset";
    case CommandKind::HandMv: return "HandMv";
    case CommandKind::SetParam: return "Set";
  }
  return "Unknown";
}

Wording warning_wording(Warning w) {
  switch (w) {
    case Warning::TipNotFree: return {"TipNotFree", "could not free the tip automatically, do it by hand; loops are open"};
    case Warning::UnexpectedHit: return {"UnexpectedHit", "probe touched during a positioning move; stopped and retracted, no point taken"};
    case Warning::HandHitNoTravel: return {"HandHitNoTravel", "hand hit ignored: move at least HandTravel mm toward the surface before touching"};
    case Warning::HandHitTooSoon: return {"HandHitTooSoon", "hand hit ignored: less than HandInterval s after the previous one"};
    case Warning::HitIgnored: return {"HitIgnored", "probe touched while the loops hold the machine still; no point taken"};
    case Warning::HomingFailed: return {"HomingFailed", "reference search failed; the machine is not homed"};
    case Warning::MoveRefused: return {"MoveRefused", "the queued move could not start after stopping (limit or tip touched)"};
  }
  return {"Unknown", ""};
}

Wording fault_wording(FaultKind f) {
  switch (f) {
    case FaultKind::CommLost: return {"CommLost", "the controller stopped answering; loops opened"};
    case FaultKind::FollowingError: return {"FollowingError", "an axis lagged beyond its following-error limit (blocked or overloaded); loops opened"};
    case FaultKind::Emergency: return {"Emergency", "emergency stop or probe overtravel; free the probe by hand, then Reset"};
    case FaultKind::DriveNotReady: return {"DriveNotReady", "a drive reports not ready; check power, then Reset"};
    case FaultKind::ConfigError: return {"ConfigError", "the controller reports a configuration or data error"};
    case FaultKind::StopInput: return {"StopInput", "the STOP input stopped all axes at once; steps may be lost: release STOP, Reset, then Home (a reference run is needed)"};
    case FaultKind::SafetyInput1: return {"SafetyInput1", "safety input 1 opened (normally closed: power-off button in the shipped maps); all motion stopped, outputs off; close it, then Reset"};
    case FaultKind::SafetyInput2: return {"SafetyInput2", "safety input 2 opened (normally closed: emergency limit switch in the shipped maps); all motion stopped, outputs off; close it, then Reset"};
    case FaultKind::SafetyInput3: return {"SafetyInput3", "safety input 3 opened (normally closed: E-stop 1 in the shipped maps); all motion stopped, outputs off; close it, then Reset"};
    case FaultKind::SafetyInput4: return {"SafetyInput4", "safety input 4 opened (normally closed: E-stop 2 in the shipped maps); all motion stopped, outputs off; close it, then Reset"};
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
  }
  return {ErrorCode::Internal, "unknown refusal"};
}

}  // namespace imess::net
