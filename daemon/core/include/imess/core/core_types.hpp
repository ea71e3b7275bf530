// Plain data crossing into and out of the motion loop: commands, events, parameters, the
// state snapshot. Trivially copyable, fixed size — they travel through lock-free rings.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>

#include "imess/core/core_params.hpp"
#include "imess/hal/types.hpp"

namespace imess::core {

using hal::AxisArray;
using hal::AxisLayout;
using hal::AxisVec;
using hal::kMaxAxes;
using hal::Nanos;
using hal::Vec3;

// Stopping: braking to rest after a stop (StopMv, a limit switch, a dropped owner); Idle
// follows only when every axis is at rest. Path: running queued planner segments (MoveTo,
// ArcTo, Dwell) through MotionBackend::follow; on the wire it is the 1996 word "move".
enum class Mode : std::uint8_t { Free, Idle, Jog, Move, Retract, Home, Fault, Stopping, Path };

// Why a queued segment did not complete (`Failed id <Reason>`). Never renumbered; the wire
// words are in net/wording.cpp (fail_wording).
enum class FailReason : std::uint8_t {
  Stopped,        // a stop (StopMv, Release, a dropped owner, the dead-man) dropped the queue
  OutOfTravel,    // held behind a Probe, it leaves the travel from the Probe's end (io side)
  IntoLimit,      // a limit switch stopped the machine
  Faulted,        // a fault, or the backend cannot follow a planned path
  UnexpectedHit,  // the probe touched during a queued segment: stopped, retracted, no point
  TipTouched,     // the queue could not start: the probe is deflected
  OffPath,        // the queue does not start where the machine stands (it was moved meanwhile)
  PartNotFound,   // a Probe's search ran SearchDist beyond the target without an edge
  Refused,        // held behind a Probe, the planner refused it from the Probe's end (io side)
  ProbeOff,       // a Probe cycle began while the probe's power output was off
  HostStall,      // the host stalled longer than the card's lead: the card braked on the path
  ScanLostContact,   // a scan's probe left the surface (no deflection) for longer than the loop allows
  ScanOverRange,     // a scan pressed the measuring probe to its range: stopped, backed off
  NoMeasuringProbe,  // a scan on a machine whose probe measures no deflection (a touch-trigger probe)
};

// Why the loop refused a command; net maps each to a protocol error code.
// TooSlow: the requested speed is below kMinSpeed (nothing would visibly move).
enum class Refusal : std::uint8_t { None, TipTouched, IntoLimit, Busy, NotSimulated, LoopsClosed, OutOfTravel, Faulted, Hardware, TooSlow };

// Slowest accepted motion, mm/s: a jog or GoTo slower than this is refused (TooSlow), and an
// axis whose share of a jog is slower than this does not move at all.
inline constexpr double kMinSpeed = 0.01;
// A GoTo moves an axis only when its target differs by at least this much, mm.
inline constexpr double kNegligibleTravel = 1e-4;

enum class Warning : std::uint8_t {
  TipNotFree,       // retract did not re-seat the probe in time; loops opened
  UnexpectedHit,    // probe triggered during a positioning move or homing
  HandHitNoTravel,  // hand hit without 1 mm of travel before it: no direction to compensate
  HandHitTooSoon,   // second hand hit within the minimum interval
  HitIgnored,       // probe edge while the loops hold the machine still
  HomingFailed,
  MoveRefused,      // a jog or GoTo queued behind a stop could not start (limit, tip)
  HostStall,        // the card ran out of setpoints (Event::value: the longest stall, ms)
};

enum class FaultKind : std::uint8_t {
  CommLost, FollowingError, Emergency, DriveNotReady, ConfigError,
  StopInput,                                             // STOP pressed: steps may be lost, reference run needed
  SafetyInput1, SafetyInput2, SafetyInput3, SafetyInput4,  // a normally-closed safety input opened
  LinkErrors,                                            // the card's link damaged or lost frames the stream needs
};

// Units: mm for a linear axis, degrees for a rotary one (speeds per second).
struct AxisSettings {
  double travel_min = 0, travel_max = 1000;  // soft limits once referenced
  int home_direction = -1;                   // side of the home switch
  double home_position = 0;                  // machine coordinate of the index found by Home
  // The axis' own limits. Every motion stays within them whatever a client sets, and every
  // stop brakes with max_accel. 0 = the machine-wide value (CoreConfig::max_velocity /
  // CoreParams::max_accel as configured); MotionCore resolves them at construction.
  double max_velocity = 0;                   // mm/s
  double max_accel = 0;                      // mm/s², acceleration and braking deceleration
};

struct HomingSettings {
  // The axes in the order homed: order[0 .. AxisLayout::count) (default_home_order).
  AxisArray<int> order{2, 0, 1};  // Z first: lift the probe clear before X and Y move
  double search_speed = 30, index_speed = 5, creep_speed = 0.1;  // mm/s
  double limit_escape = 180;      // mm moved out of a limit before the search
  double backoff = 100;           // mm backed off when the switch was found too soon
  double min_search_time = 2;     // s
  double phase_timeout = 120;     // s per phase before homing fails
};

// Z first (lift the probe clear), then the others in machine order: {2, 0, 1} on X Y Z.
AxisArray<int> default_home_order(const AxisLayout& layout) noexcept;

// A digital output of the machine (configuration "outputs"): its name on the wire (SetOut,
// Outputs), the backend's output number, how long the path holds after switching it, its
// state when messd starts, and whether it powers the probe. After the probe's power output
// switches, probe edges are ignored for its settle time (the power-on/-off edge is not a hit:
// Warn HitIgnored), and while it is off a Probe cycle fails (ProbeOff).
inline constexpr int kMaxOutputs = 8;
struct OutputSettings {
  std::array<char, 16> name{};  // NUL-terminated, letters, digits and '_'
  int number = 1;               // MotionBackend::set_output
  double settle_s = 0;          // the path's hold after a switch; the probe's arming time
  bool at_start = false;        // switched on when messd starts (else off)
  bool probe_power = false;
  std::string_view name_view() const noexcept { return std::string_view(name.data()); }
};

// The servo card's probe output: "probe", output 1, on at start, armed 100 ms after a switch.
inline OutputSettings default_probe_output() noexcept {
  OutputSettings o;
  o.name = {'p', 'r', 'o', 'b', 'e'};
  o.number = 1;
  o.settle_s = 0.1;
  o.at_start = o.probe_power = true;
  return o;
}

struct CoreConfig;
// The configured output of that name, or nullptr.
const OutputSettings* find_output(const CoreConfig& config, std::string_view name) noexcept;

struct CoreConfig {
  AxisLayout layout;  // the machine's axes: axes[0 .. layout.count)
  CoreParams params;
  AxisArray<AxisSettings> axes{AxisSettings{0, 1000, -1, 0}, AxisSettings{0, 1000, -1, 0}, AxisSettings{0, 600, 1, 600}};
  HomingSettings homing;
  double max_velocity = 150;  // mm/s: no speed level lifts a move above this
  double period_s = 0.001;    // the loop's period: the time step of queued segments
  bool referenced_at_start = false;  // absolute scales: soft limits valid without Home
  std::array<OutputSettings, kMaxOutputs> outputs{};  // outputs[0 .. output_count)
  int output_count = 0;
};

inline const OutputSettings* find_output(const CoreConfig& config, std::string_view name) noexcept {
  for (int i = 0; i < config.output_count; ++i)
    if (config.outputs[i].name_view() == name) return &config.outputs[i];
  return nullptr;
}

// Commands through the ring. Stops and parameter changes have lanes of their own
// (MotionCore::request_stop, MotionCore::set_param) and never wait behind these.
// Pause / Resume: feed hold of the queued segments (Sampler::hold / resume), on the path.
// JogAx: a StartMv of named axes (percent per machine axis in v), answered as JogAx.
enum class CommandKind : std::uint8_t { StartMv, ForcePt, GoTo, Home, Free, Reset, HandMv, Pause, Resume, JogAx };

struct Command {
  CommandKind kind = CommandKind::ForcePt;
  std::uint32_t client = 0;  // who asked (for the reply)
  std::uint32_t seq = 0;
  AxisVec v = AxisVec::Zero();  // StartMv: percent per axis; GoTo: target; HandMv: delta on X Y Z
  double speed = 0;          // GoTo, HandMv: mm/s; 0 = default
  unsigned axes = ~0u;       // GoTo: the axes given (bit per machine axis); the others stay
  std::uint64_t ticket = 0;  // set by MotionCore::submit: orders commands against stops
};

// Done / Failed: a queued segment (id) completed / did not. QueueDropped: the loop dropped
// every queued segment (drops: its new count, to stamp the segments sent after it).
// QueueLow: the loop holds no more than the segment it runs: the planner should flush.
// ScanPt: a scan's point (p the surface point, dir from the ball centre toward it, radius, id).
enum class EventKind : std::uint8_t { Reply, MeasPt, State, Limit, Warn, Fault, Homed, Done, Failed, QueueDropped, QueueLow, ScanPt };

struct Event {
  EventKind kind = EventKind::Reply;
  std::uint32_t client = 0, seq = 0;  // Reply
  CommandKind command = CommandKind::ForcePt;
  Refusal refusal = Refusal::None;    // Reply: None = Ok
  Mode mode = Mode::Free;             // State
  Warning warning = Warning::TipNotFree;
  FaultKind fault = FaultKind::CommLost;
  std::int8_t axis = -1, side = 0;    // Limit: axis index, -1 negative / +1 positive
  bool compensated = false;           // MeasPt: radius corrected (false: ForcePt)
  Vec3 p = Vec3::Zero();              // MeasPt / Warn / Fault position, Cartesian (X Y Z axes)
  Vec3 dir = Vec3::Zero();            // MeasPt: approach direction used
  const char* reason = nullptr;       // Warn: a static text saying why (HomingFailed), or none
  double radius = 0;                  // MeasPt: tip radius applied (0: ForcePt)
  std::uint32_t id = 0;               // Done, Failed: the segment's id; QueueDropped: drops;
                                      // MeasPt: the Probe's id (0: a jog or hand hit)
  bool probe_end = false;             // Done: closes a Probe cycle, p = where the machine stands
  AxisVec end = AxisVec::Zero();      // Done closing a Probe: every axis where the machine stands
  FailReason fail = FailReason::Stopped;  // Failed, QueueDropped
  std::uint32_t value = 0;            // Warn HostStall: the longest stall of the loop, ms
  Nanos time{0};
};

struct Snapshot {
  std::uint64_t cycle = 0;
  Nanos time{0};
  Mode mode = Mode::Free;
  AxisVec position = AxisVec::Zero();  // every axis, machine coordinates
  bool loops_closed = false, tip_touched = false, homed = false, referenced = false;
  AxisArray<std::int8_t> limit{};     // -1 negative switch, +1 positive, 0 none
  AxisArray<std::uint32_t> status{};  // raw axis status words
  AxisArray<std::uint8_t> inputs{};
  CoreParams params;
  bool simulated = false;
  std::uint64_t events_dropped = 0;
  std::uint64_t hardware_errors = 0;
  std::uint64_t link_errors = 0;      // MotionBackend::link_errors(): frames lost or damaged on the link
  bool path_running = false;          // a queued segment is in hand
  std::uint32_t path_id = 0;          // its id
  bool path_held = false;             // Pause is in effect
  std::uint32_t outputs = 0;          // bit i: CoreConfig::outputs[i] is on (as last switched)
  bool probe_armed = true;            // the probe is powered and past its arming time
  bool measuring_probe = false;       // the backend reads a measuring probe's deflection: it can scan
  std::uint64_t rest_departures = 0;  // times the position left a rest (RestWatch); each wakes the io side
};

}  // namespace imess::core
