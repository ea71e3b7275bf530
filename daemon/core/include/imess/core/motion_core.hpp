// MotionCore: the machine's behaviour, one cycle at a time. Reads the hardware, takes a
// bounded number of commands, runs jog / move / probe-hit / retract / homing / idle logic,
// writes the hardware, pushes events and publishes a snapshot. cycle() never allocates,
// locks, logs, throws or blocks; time comes in as an argument (real or virtual).
#pragma once
#include <array>
#include <atomic>

#include "imess/core/event_signal.hpp"
#include "imess/core/hand_travel.hpp"
#include "imess/core/homing.hpp"
#include "imess/core/queues.hpp"
#include "imess/core/rest_watch.hpp"
#include "imess/core/triple_buffer.hpp"
#include "imess/hal/motion_backend.hpp"
#include "imess/planner/sampler.hpp"

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
  bool submit_segment(const QueuedSegment& s) noexcept { return segments_.push(s); }
  std::size_t segment_room() const noexcept { return segments_.write_available(); }
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
  EventQueue& events() noexcept { return events_; }
  const Snapshot& snapshot() noexcept { return snapshot_.read(); }
  // The configured limits (resolved: never 0), for the io side and tests.
  const CoreConfig& config() const noexcept { return limits_; }

  // For tests and the loop's owner, read on the loop's own thread only.
  Mode mode() const noexcept { return mode_; }
  const hal::MachineState& machine() const noexcept { return ms_; }

 private:
  void handle(const Command& c, Nanos now) noexcept;
  void take_stop(Nanos now) noexcept;
  bool superseded(const Command& c) const noexcept;
  Refusal start_jog(const AxisVec& percent, Nanos now) noexcept;
  Refusal go_to(const AxisVec& target, unsigned given, double speed, Nanos now) noexcept;
  // A new motion while moving brakes to rest first and starts from there (straight paths,
  // no axis retargeted at a fraction of its acceleration).
  void launch_pending(Nanos now) noexcept;
  Refusal start_homing(Nanos now) noexcept;
  void stop_motion() noexcept;
  void on_probe_latch(Nanos now) noexcept;
  // Outputs: their start states (set-up), the switches of a sampler tick, and whether a
  // probe edge now is a hit (the probe powered and past its arming time).
  void start_outputs(Nanos now);
  void refresh_outputs() noexcept;  // outputs_on_ from the backend (the one place it is set)
  void probe_switched(bool on, Nanos now) noexcept;
  const std::uint32_t* switch_outputs(const planner::Sample& smp, Nanos now) noexcept;
  bool probe_armed(Nanos now) const noexcept { return probe_powered_ && now >= arming_until_; }
  void retract_from(const AxisVec& latched, const AxisVec& dir, Nanos now) noexcept;
  // A probe edge in a Probe's search: the hit (with the Probe's id), then the retract from it.
  void probe_hit(const AxisVec& latched, Nanos now) noexcept;
  // The Failed or Done that closes a Probe whose hit has been reported (after its retract).
  void close_probe(EventKind k, FailReason why, Nanos now) noexcept;
  void check_limits(Nanos now) noexcept;
  void update_mode(Nanos now) noexcept;
  void stand_still(Nanos now) noexcept;
  void drop_axes_into_limits(AxisVec& v) const noexcept;
  AxisVec jog_target(const AxisVec& u) const noexcept;
  Refusal start_straight(const AxisVec& target, const AxisVec& u, double speed, Mode mode, Nanos now) noexcept;
  void launch_pending_or_idle(Nanos now) noexcept;
  void update_retract(double in_mode, Nanos now) noexcept;
  void update_homing(Nanos now) noexcept;
  void enter(Mode m, Nanos now) noexcept;
  // Path mode (queued segments): start when idle, one sampler tick per cycle, the failing of
  // every queued id with a reason (the stop lane, limits, faults, hits).
  void start_path(Nanos now) noexcept;
  void run_path(Nanos now) noexcept;
  void settle(Nanos now) noexcept;            // the queue ended: wait for arrival, then idle
  void release_arrivals(Nanos now) noexcept;  // the Done ids that waited for arrival
  bool pop_segment(planner::PlannedSegment& out) noexcept;  // fails stale segments on the way
  bool fresh_segments_waiting(Nanos now) noexcept;
  bool stale(const QueuedSegment& q) const noexcept;
  void fail_queue(FailReason why, Nanos now, bool tell = true) noexcept;
  void segment_event(EventKind k, std::uint32_t id, FailReason why, Nanos now) noexcept;
  void fail_segment(std::uint32_t id, planner::ProbePhase phase, FailReason why, Nanos now) noexcept;
  void fault(FaultKind f, Nanos now) noexcept;
  void emit(const Event& e) noexcept;
  void reply(const Command& c, Refusal r) noexcept;
  void measured(const Vec3& point, const Vec3& dir, bool compensated, Nanos now, std::uint32_t id = 0) noexcept;
  // The Cartesian part (X Y Z axes) of a machine position, and of a direction as a unit vector.
  Vec3 cartesian(const AxisVec& p) const noexcept { return config_.layout.cartesian(p); }
  Vec3 cartesian_dir(const AxisVec& d) const noexcept;
  void warn(Warning w, const AxisVec& where, Nanos now, const char* reason = nullptr) noexcept;
  void publish(Nanos now) noexcept;
  // Per-axis speeds and accelerations for a straight path along unit direction u at the
  // requested path speed, within max_velocity, every axis' speed limit and the runtime
  // acceleration (itself within every axis' limit; configured_accel: the axes' configured
  // values, for moves that begin by braking another). Axes with u = 0 are not in the mask.
  AxisArray<hal::AxisMove> straight_moves(const AxisVec& target, const AxisVec& u, double speed,
                                          bool configured_accel = false) const noexcept;
  unsigned moving_axes(const AxisVec& u) const noexcept;
  bool moving_into_limit(int axis, int side) const noexcept;
  // May the machine move along u while the tip is deflected? Only away from the approach
  // of the hit that deflected it.
  bool away_from_touch(const AxisVec& u) const noexcept;

  hal::MotionBackend& hw_;
  CoreConfig config_;   // params: the loop's copy, refreshed from the parameter lane
  CoreConfig limits_;   // as configured, axis limits resolved; read by any thread
  hal::SimHooks* sim_;
  CommandQueue commands_;
  TripleBuffer<CoreParams> params_in_;
  CoreParams params_out_;                    // the io thread's copy (what Get reports)
  std::uint64_t next_ticket_ = 0;            // io thread only
  std::atomic<std::uint64_t> stop_ticket_{0};
  std::uint64_t stop_taken_ = 0;             // loop: the newest stop acted on
  Mode stopped_from_ = Mode::Idle;           // what was braking in Mode::Stopping
  AxisVec approach_dir_ = AxisVec::Zero();       // direction of the last hit (zero: unknown)
  EventQueue events_;
  EventSignal no_signal_;
  EventSignal* signal_ = &no_signal_;
  bool pushed_ = false;                      // this cycle pushed an event: notify at its end
  RestWatch rest_watch_;                     // the position leaving a rest also wakes the io side,
  std::uint64_t rest_departures_ = 0;        // and so do the kDepartureWakes cycles after it
  int departure_wakes_ = 0;                  // (the io side looks for the first printed change)
  TripleBuffer<Snapshot> snapshot_;

  int n_ = 3;  // the machine's axes (config_.layout.count)
  hal::MachineState ms_;
  Mode mode_ = Mode::Free;
  bool homed_ = false, referenced_ = false;
  AxisVec motion_dir_ = AxisVec::Zero();    // unit direction of the current jog / move
  AxisArray<std::int8_t> started_in_limit_{};  // side of a limit an axis sat in when motion began
  Nanos mode_since_{0};
  Nanos last_hand_hit_{-1'000'000'000'000};
  HandTravel hand_;
  Homing homing_;
  int comm_failures_ = 0;
  bool state_stale_ = false;
  enum class Pending : std::uint8_t { None, Jog, GoTo } pending_ = Pending::None;
  AxisVec pending_v_ = AxisVec::Zero();
  unsigned pending_axes_ = ~0u;
  double pending_speed_ = 0;  // a move was commanded after this cycle's state was read
  std::uint64_t cycles_ = 0, events_dropped_ = 0, hardware_errors_ = 0;
  // Path mode. held_ids_: the ids the sampler holds (current, then the buffered one), in order.
  SegmentQueue segments_;
  planner::Sampler sampler_;
  std::array<std::uint32_t, 4> held_ids_{};
  std::array<planner::ProbePhase, 4> held_probe_{};  // the probe phase of each held segment
  int held_count_ = 0;
  AxisVec probe_dir_ = AxisVec::Zero();  // unit approach of the Probe being run (set as it is popped)
  bool probe_retracting_ = false;  // a Probe hit: its Done follows the retract
  std::uint32_t probe_id_ = 0;     // that Probe's id
  AxisVec retract_target_ = AxisVec::Zero();  // where the last retract ends
  bool failed_approach_ = false;   // the last segment failed was a Probe's approach ...
  std::uint32_t failed_id_ = 0;    // ... with this id (its search is not failed again)
  std::uint32_t drops_ = 0;       // queue drops by the loop (stamped on segments by the io side)
  bool check_start_ = false;      // the next segment popped must start where the machine stands
  bool low_sent_ = false;         // QueueLow sent since the last segment popped
  // Arrival: the ids whose path ended at rest, answered Done once the machine is in position.
  static constexpr double kSettleLimit = 0.5;  // s: a backend that never reports arrival
  static constexpr double kMaxPathStep = 0.1;  // s: the most a late cycle advances the path
  struct Arrival {
    std::uint32_t id = 0;
    EventKind kind = EventKind::Done;  // Done, or Failed PartNotFound (a search that ended at rest)
    FailReason why = FailReason::Stopped;
  };
  std::array<Arrival, planner::kMaxCompletionsPerTick> arrivals_{};
  int arrivals_count_ = 0;
  Nanos settle_since_{0};
  Nanos path_now_{0};             // the cycle's time, for events raised inside pop_segment
  Nanos last_cycle_{-1};          // the previous cycle's time (-1: none yet)
  // Outputs: bit i = config_.outputs[i] on; the probe's power output (-1: none, always powered).
  std::uint32_t outputs_on_ = 0;
  int probe_output_ = -1;
  bool probe_powered_ = true;
  Nanos arming_until_{0};         // probe edges before this are its power edges
  bool quiet_arming_ = false;     // the arming of start-up: its edges go without a warning
  double since_last_s_ = 0;       // s since the previous cycle, the period at the first
};

}  // namespace imess::core
