// MotionCore: the machine's behaviour, one cycle at a time. Reads the hardware, takes the
// stop lane and a bounded number of commands, hands each mode to its unit (StraightMoves:
// jog and GoTo; ProbeCycle: hits and retract; PathFollower: queued segments; HandMode;
// Homing; Outputs), checks the limits, writes the hardware, pushes events and publishes a
// snapshot. cycle() never allocates, locks, logs, throws or blocks; time comes in as an
// argument (real or virtual).
#pragma once
#include <array>
#include <atomic>

#include "imess/core/event_signal.hpp"
#include "imess/core/hand_mode.hpp"
#include "imess/core/homing.hpp"
#include "imess/core/loop_context.hpp"
#include "imess/core/outputs.hpp"
#include "imess/core/path_follower.hpp"
#include "imess/core/probe_cycle.hpp"
#include "imess/core/queues.hpp"
#include "imess/core/rest_watch.hpp"
#include "imess/core/straight_moves.hpp"
#include "imess/core/triple_buffer.hpp"
#include "imess/hal/motion_backend.hpp"

namespace imess::core {

class MotionCore {
 public:
  // sim: the simulator's hooks, or nullptr on real hardware (HandMv is then refused).
  MotionCore(hal::MotionBackend& hardware, CoreConfig config, hal::SimHooks* sim = nullptr);

  // Set-up: the backend is initialised; reads the first state. Not real-time.
  void start(Nanos now);
  // Set-up, before the loop runs: who is told at the end of a cycle that pushed events
  // (default: nobody; the signal must outlive every cycle).
  void set_event_signal(EventSignal* signal) noexcept { signal_ = signal ? signal : &no_signal_; }
  // One motion cycle. Measured budget on the simulated card: see bench/ and docs.
  void cycle(Nanos now) noexcept;

  // Crossings. submit(), request_stop(), set_param() and params(): called by exactly one
  // thread (the io thread); events() and snapshot(): read by exactly one thread.
  //
  // submit: queues a command; false when the ring is full (the caller answers QueueFull).
  bool submit(Command c) noexcept;
  // The segment ring (io thread): a planned segment for the path mode; false when the ring is
  // full (the caller keeps it and tries again after a Done). stop_ticket(): the newest stop
  // ticket issued, to stamp segments with.
  bool submit_segment(const QueuedSegment& s) noexcept { return path_.submit(s); }
  std::size_t segment_room() const noexcept { return path_.room(); }
  std::uint64_t stop_ticket() const noexcept { return next_ticket_; }
  // The stop lane: the loop reads it first thing every cycle, so a stop never waits behind
  // queued commands. Every motion brakes to rest with the axes' configured deceleration
  // (never a client-set value); motion commands submitted before the stop and not yet taken
  // are answered Ok but not started (the stop supersedes them). A retract in progress
  // finishes (it only moves away from the part), then the machine stands.
  void request_stop() noexcept;
  // The parameter lane: a whole CoreParams published to the loop, which takes the newest
  // before every command, so a Set followed by a motion command applies to it.
  void set_param(ParamId id, double value) noexcept;
  const CoreParams& params() const noexcept { return params_out_; }
  EventQueue& events() noexcept { return loop_.events; }
  const Snapshot& snapshot() noexcept { return snapshot_.read(); }
  // The configured limits (resolved: never 0), for the io side and tests.
  const CoreConfig& config() const noexcept { return limits_; }

  // For tests and the loop's owner, read on the loop's own thread only.
  Mode mode() const noexcept { return loop_.mode; }
  const hal::MachineState& machine() const noexcept { return loop_.ms; }

 private:
  void read_machine(Nanos now) noexcept;  // this cycle's state; faults from it
  void host_stall(Nanos now) noexcept;     // the card starved: warn, fail the path, brake
  void handle(const Command& c, Nanos now) noexcept;
  void take_stop(Nanos now) noexcept;
  bool superseded(const Command& c) const noexcept;
  Refusal free_machine(Nanos now) noexcept;  // Free: open the loops (not while moving)
  Refusal reset(Nanos now) noexcept;         // Reset: clear a fault, loops open
  Refusal start_homing(Nanos now) noexcept;
  void update_homing(Nanos now) noexcept;
  void check_limits(Nanos now) noexcept;
  void update_mode(Nanos now) noexcept;
  void update_idle(Nanos now) noexcept;  // a path to start, or the loops to open
  void fault(FaultKind f, Nanos now) noexcept;
  void wake_on_departure() noexcept;      // the position leaving a rest wakes the io side
  void publish(Nanos now) noexcept;

  // Declared first: the units below hold references to it.
  LoopContext loop_;    // the state every mode shares; loop_.config: the loop's copy
  CoreConfig limits_;   // as configured, axis limits resolved; read by any thread
  CommandQueue commands_;
  TripleBuffer<CoreParams> params_in_;
  CoreParams params_out_;                    // the io thread's copy (what Get reports)
  std::uint64_t next_ticket_ = 0;            // io thread only
  std::atomic<std::uint64_t> stop_ticket_{0};
  EventSignal no_signal_;
  EventSignal* signal_ = &no_signal_;
  RestWatch rest_watch_;                     // the position leaving a rest also wakes the io side,
  std::uint64_t rest_departures_ = 0;        // and so do the kDepartureWakes cycles after it
  int departure_wakes_ = 0;                  // (the io side looks for the first printed change)
  TripleBuffer<Snapshot> snapshot_;
  int comm_failures_ = 0;
  bool host_starved_ = false;                // the card reported kHostStarved last cycle
  double longest_gap_s_ = 0;                 // the longest time between cycles lately ...
  Nanos longest_gap_at_{0};                  // ... and when it was (forgotten after a second)
  std::uint64_t cycles_ = 0;
  Nanos last_cycle_{-1};                     // the previous cycle's time (-1: none yet)

  // The modes, each with its own state (Homing: the reference search).
  Outputs outputs_{loop_};
  HandMode hand_{loop_};
  StraightMoves moves_{loop_};
  ProbeCycle probe_{loop_, moves_, path_, hand_, outputs_};
  PathFollower path_{loop_, outputs_, probe_};
  Homing homing_;
};

}  // namespace imess::core
