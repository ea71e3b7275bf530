// LoopContext: what every mode of the motion loop shares — the backend, the loop's copy of
// the configuration, this cycle's machine state, the mode, the direction of travel — and
// what every mode writes through: events, mode changes, braking, straight-line axis moves.
// Owned by MotionCore; the mode units (StraightMoves, ProbeCycle, PathFollower, HandMode,
// Outputs) hold a reference to it. Everything here is real-time: noexcept, no allocation.
#pragma once
#include <cstdint>

#include "imess/core/core_types.hpp"
#include "imess/core/queues.hpp"
#include "imess/hal/motion_backend.hpp"

namespace imess::core {

// -1, 0 or +1: the side of zero v lies on (a direction's sense along one axis).
constexpr int sign(double v) noexcept { return (v > 0) - (v < 0); }

struct LoopContext {
  LoopContext(hal::MotionBackend& hardware, const CoreConfig& configured, hal::SimHooks* sim_hooks) noexcept
      : hw(hardware),
        sim(sim_hooks),
        config(configured),
        n(configured.layout.count),
        referenced(configured.referenced_at_start) {}
  LoopContext(const LoopContext&) = delete;
  LoopContext& operator=(const LoopContext&) = delete;

  // ---- events (the ring to the io thread)
  void emit(const Event& e) noexcept;
  void reply(const Command& c, Refusal r) noexcept;
  void measured(const Vec3& point, const Vec3& dir, bool compensated, Nanos now, std::uint32_t id = 0) noexcept;
  void warn(Warning w, const AxisVec& where, Nanos now, const char* reason = nullptr) noexcept;
  void segment_event(EventKind k, std::uint32_t id, FailReason why, Nanos now) noexcept;

  // ---- modes
  // A new mode (a State event when it changes); the next cycle judges it on fresh state.
  void enter(Mode m, Nanos now) noexcept;
  // Brakes every axis with its configured deceleration (never the runtime MaxAccel), along
  // the current direction of travel so a line stays a line.
  void stop_motion() noexcept;
  // stop_motion, then Mode::Stopping remembering what braked (a hit while braking belongs to it).
  void brake_to_rest(Mode from, Nanos now) noexcept;
  double seconds_in_mode(Nanos now) const noexcept { return hal::seconds(now - mode_since); }

  // ---- straight lines
  // Per-axis speeds and accelerations for a straight path along unit direction u at the
  // requested path speed, within max_velocity, every axis' speed limit and the runtime
  // acceleration (itself within every axis' limit; configured_accel: the axes' configured
  // values, for moves that begin by braking another). Axes with u = 0 are not in the mask.
  AxisArray<hal::AxisMove> straight_moves(const AxisVec& target, const AxisVec& u, double speed,
                                          bool configured_accel = false) const noexcept;
  unsigned moving_axes(const AxisVec& u) const noexcept;

  // The Cartesian part (X Y Z axes) of a machine position, and of a direction as a unit vector.
  Vec3 cartesian(const AxisVec& p) const noexcept { return config.layout.cartesian(p); }
  Vec3 cartesian_dir(const AxisVec& d) const noexcept;

  hal::MotionBackend& hw;
  hal::SimHooks* sim;       // the simulator's hooks, or nullptr on real hardware
  CoreConfig config;        // params: the loop's copy, refreshed from the parameter lane
  int n = 3;                // the machine's axes (config.layout.count)
  hal::MachineState ms;     // this cycle's state
  Mode mode = Mode::Free;
  Nanos mode_since{0};
  std::uint32_t free_entries = 0;  // times the loop entered Free (HandMode forgets the travel then)
  bool state_stale = false;        // a motion started after this cycle's state was read
  bool homed = false, referenced = false;
  AxisVec motion_dir = AxisVec::Zero();        // unit direction of the current jog / move
  AxisVec approach_dir = AxisVec::Zero();      // direction of the last hit (zero: unknown)
  AxisArray<std::int8_t> started_in_limit{};   // side of a limit an axis sat in when motion began
  Mode stopped_from = Mode::Idle;              // what was braking in Mode::Stopping
  std::uint64_t stop_taken = 0;                // the newest stop acted on
  double since_last_s = 0;                     // s since the previous cycle, the period at the first
  std::uint64_t hardware_errors = 0, events_dropped = 0;
  bool pushed = false;                         // this cycle pushed an event: notify at its end
  EventQueue events;
};

}  // namespace imess::core
