// PathFollower: the path mode (Mode::Path) — queued planner segments from the segment ring,
// one Sampler tick per cycle to MotionBackend::follow, Done per completed id once the machine
// has arrived, and the failing of every queued id with a reason (the stop lane, limits,
// faults, hits). "Queued moves as built" in docs/architecture.md.
#pragma once
#include <array>
#include <cstdint>

#include "imess/core/loop_context.hpp"
#include "imess/core/queues.hpp"
#include "imess/core/scan_control.hpp"
#include "imess/planner/sampler.hpp"

namespace imess::core {

class Outputs;
class ProbeCycle;

class PathFollower {
 public:
  PathFollower(LoopContext& loop, Outputs& outputs, ProbeCycle& probe) noexcept;

  // The segment ring (io thread): false when full (the caller keeps it and tries again).
  bool submit(const QueuedSegment& s) noexcept { return segments_.push(s); }
  std::size_t room() const noexcept { return segments_.write_available(); }

  // Feed hold (Pause / Resume): the sampler leaves the plan's time, never its path.
  void hold() noexcept { sampler_.hold(); }
  void resume() noexcept { sampler_.resume(); }
  bool holding() const noexcept { return sampler_.holding(); }

  // Idle or free: fails the stale segments at the ring's front; true when fresh ones wait.
  bool fresh_segments_waiting(Nanos now) noexcept;
  // Close the loops and follow the waiting segments from where the machine stands.
  void start(Nanos now) noexcept;
  // One sampler tick: the setpoint to the backend, a Done per completed segment, QueueLow
  // when only the running segment is left, idle when the queue ran out at rest.
  void run(Nanos now) noexcept;
  // Fails every queued id (the running one, the buffered one, those in the ring) with why, and
  // tells the io side (tell: QueueDropped with the new drop count). The stop lane (tell
  // false) fails only the segments sent before the stop.
  void fail_queue(FailReason why, Nanos now, bool tell = true) noexcept;

  // The segment in hand: is there one, its id, is it a Probe's search, the Probe's approach.
  bool running() const noexcept { return held_count_ > 0; }
  std::uint32_t running_id() const noexcept { return held_count_ > 0 ? held_ids_[0] : 0; }
  bool in_search() const noexcept { return held_count_ > 0 && held_probe_[0] == planner::ProbePhase::Search; }
  const AxisVec& probe_direction() const noexcept { return probe_dir_; }
  // A scan's segment in contact with the part (Approach, Follow, Leave): the measuring probe
  // deflects by design, so its switch edge is no hit.
  bool in_scan_contact() const noexcept { return held_count_ > 0 && scan_.in_contact_phase(); }
  // A Probe's hit ends its search: nothing held, the ring emptied (what follows a Probe is
  // held by the io side; anything else there is Failed Stopped), the sampler where it stands.
  void end_search(std::uint32_t id, Nanos now) noexcept;

 private:
  void settle(Nanos now) noexcept;            // the queue ended: wait for arrival, then idle
  void release_arrivals(Nanos now) noexcept;  // the Done ids that waited for arrival
  bool pop_segment(planner::PlannedSegment& out) noexcept;  // fails stale segments on the way
  bool stale(const QueuedSegment& q) const noexcept;
  void fail_segment(std::uint32_t id, planner::ProbePhase phase, FailReason why, Nanos now,
                    planner::ScanPhase scan = planner::ScanPhase::None) noexcept;
  void fail_and_brake(FailReason why, Nanos now) noexcept;  // the whole queue, then brake to rest
  void sampler_to_machine() noexcept;  // the sampler set to where the machine stands
  // A scan stopped (lost contact, over range, no measuring probe, an unknown contour's length
  // run out): the queue fails; over range and a run-out contour back the probe off along the
  // measured normal, anything else brakes to rest.
  void scan_stop(FailReason why, Nanos now) noexcept;
  // An unknown contour met its stop body: it ends as a Probe's search does (the ring emptied
  // of other ids), then brakes and backs off along its end normal; the retract's end closes
  // the id Done with where the machine stands (ProbeCycle::finish_scan).
  void contour_end(std::uint32_t id, Nanos now) noexcept;

  LoopContext& loop_;
  Outputs& outputs_;
  ProbeCycle& probe_;
  // held_ids_: the ids the sampler holds (current, then the buffered one), in order.
  SegmentQueue segments_;
  planner::Sampler sampler_;
  ScanControl scan_{loop_};
  std::array<std::uint32_t, 4> held_ids_{};
  std::array<planner::ProbePhase, 4> held_probe_{};  // the probe phase of each held segment
  std::array<planner::ScanPhase, 4> held_scan_{};    // the scan phase of each held segment
  int held_count_ = 0;
  AxisVec probe_dir_ = AxisVec::Zero();  // unit approach of the Probe being run (set as it is popped)
  bool failed_approach_ = false;   // the last segment failed was a Probe's approach ...
  bool failed_scan_ = false;       // ... or a scan's segment ...
  std::uint32_t failed_id_ = 0;    // ... with this id (its search, the scan's rest, is not failed again)
  std::uint32_t drops_ = 0;        // queue drops by the loop (stamped on segments by the io side)
  bool check_start_ = false;       // the next segment popped must start where the machine stands
  bool low_sent_ = false;          // QueueLow sent since the last segment popped
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
  Nanos path_now_{0};  // the cycle's time, for events raised inside pop_segment
  double path_time_ = 0;  // s, the sum of every path step taken (Setpoint::time), never reset
};

}  // namespace imess::core
