// MotionBackend: what the motion core needs from a machine — read axes and inputs, run
// per-axis trapezoid moves, stop, open/close the position loops, read the probe latch.
// Real-time calls are noexcept and allocate nothing; set-up calls may throw.
#pragma once
#include <string>

#include "imess/hal/types.hpp"

namespace imess::hal {

// Axis status word bits (the MCU-style card's layout; every backend reports in it).
namespace status {
inline constexpr std::uint32_t kCommTimeout = 1u << 0, kEmergency = 1u << 1, kDriveNotReady = 1u << 2,
                               kHardLimitNeg = 1u << 3, kHardLimitPos = 1u << 4, kSoftLimitNeg = 1u << 5,
                               kSoftLimitPos = 1u << 6, kFollowingError = 1u << 7, kDataError = 1u << 8,
                               kConfigError = 1u << 9, kProfileEnd = 1u << 12, kClosedLoop = 1u << 13,
                               kInPosition = 1u << 14, kUserInput = 1u << 15, kLatchValid = 1u << 16;
// Bits the MCU card leaves unused, set by the port backends: the STOP input of a stepper
// machine (stopped at once, steps may be lost: a reference run is needed) and the
// normally-closed safety inputs of a drive-kit machine (one bit per input, 1..4).
inline constexpr std::uint32_t kStopInput = 1u << 10, kSafetyInput1 = 1u << 17, kSafetyInput2 = 1u << 18,
                               kSafetyInput3 = 1u << 19, kSafetyInput4 = 1u << 20;
// The card's setpoints ran out with the path still moving (the host stalled longer than the
// lead, docs/servo-card-link.md): it braked along the path to rest and holds there, loops
// closed. Not a fault: the next motion command clears it.
inline constexpr std::uint32_t kHostStarved = 1u << 11;
inline constexpr std::uint32_t kSafetyInputs = kSafetyInput1 | kSafetyInput2 | kSafetyInput3 | kSafetyInput4;
// Set by the servo card's stream driver: the link damaged or lost frames the stream cannot do
// without (the card saw a damaged host frame; a frame was never acknowledged).
inline constexpr std::uint32_t kLinkErrors = 1u << 21;
inline constexpr std::uint32_t kFaultMask = kCommTimeout | kEmergency | kDriveNotReady | kFollowingError | kDataError |
                                            kConfigError | kStopInput | kSafetyInputs | kLinkErrors;
}  // namespace status

// Module input bits per axis. 0x2/0x4/0x8 as on the 1996 card; home and index are ours.
namespace input {
inline constexpr std::uint8_t kLimitPos = 0x2, kLimitNeg = 0x4, kTip = 0x8, kHome = 0x10, kIndex = 0x20;
}

struct MachineState {
  int count = 3;                         // the machine's axes (AxisLayout::count); the backend sets it
  AxisVec position = AxisVec::Zero();    // mm or degrees, actual (encoder), in machine coordinates
  AxisArray<std::uint32_t> status{};     // status word per axis
  AxisArray<std::uint8_t> inputs{};      // module inputs per axis (raw)
  bool tip_touched = false;              // probe deflected, switch polarity already applied
  // A measuring (analog) probe: its deflection vector, sampled at the same card tick as the
  // positions (mm, machine X Y Z: the ball centre pushed off its rest position by the
  // surface). deflection_valid: this backend reads a measuring probe (false on the port
  // backends and with a touch-trigger probe: scanning is refused there); probe_over_range:
  // the deflection reached the probe's range (the reading is clamped).
  Vec3 deflection = Vec3::Zero();
  bool deflection_valid = false;
  bool probe_over_range = false;

  // Every / any of the machine's axes (the unused entries never count).
  bool all(std::uint32_t bit) const {
    std::uint32_t w = bit;
    for (int a = 0; a < count; ++a) w &= status[a];
    return w != 0;
  }
  bool any(std::uint32_t bit) const {
    std::uint32_t w = 0;
    for (int a = 0; a < count; ++a) w |= status[a];
    return (w & bit) != 0;
  }
  bool input(int axis, std::uint8_t bit) const { return (inputs[axis] & bit) != 0; }
  // The limit switch an axis is in: -1 negative, +1 positive, 0 none.
  std::int8_t limit_side(int axis) const {
    return static_cast<std::int8_t>(input(axis, input::kLimitNeg) ? -1 : input(axis, input::kLimitPos) ? 1 : 0);
  }
  bool loops_closed() const { return all(status::kClosedLoop); }
  bool motion_done() const { return all(status::kProfileEnd); }
  bool latch_valid() const { return any(status::kLatchValid); }
  bool faulted() const { return any(status::kFaultMask); }
};

// One servo period of a planned path (the motion core samples the planner's segments every
// cycle): where every axis must be at the end of this period, mm, and how fast it moves
// there, mm/s (the feed-forward). Consecutive setpoints are continuous and within the axes'
// speed and acceleration limits: the planner made them so.
struct Setpoint {
  AxisVec position = AxisVec::Zero();
  AxisVec velocity = AxisVec::Zero();
  double time = -1;  // s, the path's time of this setpoint (monotonic within a path); < 0: not given
};

struct AxisMove {
  double target = 0;    // mm (degrees for a rotary axis), absolute
  double velocity = 0;  // mm/s (deg/s), > 0
  double accel = 0;     // mm/s² (deg/s²), > 0
};

class MotionBackend {
 public:
  virtual ~MotionBackend() = default;

  // ---- set-up (not real-time; may throw std::runtime_error naming the problem) ----
  // Brings the hardware to a known state: firmware, parameters, loops open.
  virtual void initialise(bool force_reboot) = 0;
  virtual std::string describe() const = 0;

  // ---- real-time (noexcept, no allocation); false = the hardware did not answer properly ----
  virtual bool read_state(MachineState& out) noexcept = 0;
  // Positions latched at the probe edge; reading clears the latch-valid bit.
  virtual bool read_latch(AxisVec& latched) noexcept = 0;
  virtual bool set_loops(bool closed) noexcept = 0;
  // Starts a trapezoid move on the axes whose bit is set in axis_mask; others keep going.
  virtual bool move(const AxisArray<AxisMove>& moves, unsigned axis_mask) noexcept = 0;
  // Follows a planned path: called once per cycle while the core runs queued segments, each
  // call the next servo period's setpoint for every axis (a per-axis trapezoid started by
  // move() is replaced). stop() ends following and brakes as always. Backends that cannot
  // follow a path keep this default and return false (the core refuses queued motion).
  virtual bool follow(const Setpoint& sp) noexcept {
    (void)sp;
    return false;
  }
  // How the core advances a path's time from one cycle to the next (after a late cycle: a
  // stalled host).
  enum class PathTime {
    // One period a cycle (the default): given a setpoint late, the machine waits or brakes.
    PerCycle,
    // The time that really passed, at least a period: the hardware goes on along the path at
    // the last setpoint's velocity until the next comes (the servo card over request/reply, up
    // to its watchdog), so the next setpoint continues where the machine went.
    Bridged,
    // Exactly the time that passed: the backend runs setpoints sent ahead on its own clock
    // (a streamed card, stamped by Setpoint::time), so the setpoints after a stall meet the
    // card where it went on.
    OwnClock,
  };
  virtual PathTime path_time() const noexcept { return PathTime::PerCycle; }
  // How long after it is sent the backend runs a setpoint, s (a streamed card's lead; 0 for
  // the others): the delay a feedback loop through the path (a scan's contact control) sees.
  virtual double path_lead_s() const noexcept { return 0; }
  // False while the link to the controller still carries earlier commands (a streamed serial
  // line: a flood of GoTo lines outruns 115 200 baud): the core then leaves the next command in
  // its ring for a later cycle, so the line's backlog stays short and a stop never waits
  // behind it. Real-time: noexcept.
  virtual bool ready_for_command() const noexcept { return true; }
  // Digital outputs, numbered 1..output_count() as the backend documents them (docs/hardware.md:
  // the card's output 1 powers the probe; drive-kit and parallel-port outputs per map).
  // set_output switches one; false: no such output, or the hardware did not take it. A
  // safety trip or fault switches every output off on the backends whose hardware does so.
  virtual int output_count() const noexcept { return 0; }
  virtual bool set_output(int number, bool on) noexcept {
    (void)number;
    (void)on;
    return false;
  }
  // The output's state as the backend holds it (a trip may have switched it off).
  virtual bool output_on(int number) const noexcept {
    (void)number;
    return false;
  }
  // Decelerates every axis to rest with the given per-axis deceleration (mm/s², deg/s²).
  virtual bool stop(const AxisVec& decel) noexcept = 0;
  // Redefines the current position of one axis (homing: the index becomes value).
  virtual bool set_position(int axis, double value) noexcept = 0;
  // Clears latched fault bits (after the cause is gone); leaves the loops open.
  virtual bool reset_faults() noexcept = 0;
  // Frames lost or damaged on the link to the hardware (and link requests refused) since
  // start; 0 for a backend without a link. Read on the motion thread (the core publishes it).
  virtual unsigned long link_errors() const noexcept { return 0; }
};

// Simulator-only hooks (hand pushes); a real machine has none, and the core refuses them.
class SimHooks {
 public:
  virtual ~SimHooks() = default;
  // Moves the carriage by hand by delta at speed (mm/s); only while the loops are open.
  virtual void push_by_hand(const Vec3& delta, double speed) noexcept = 0;
};

}  // namespace imess::hal
