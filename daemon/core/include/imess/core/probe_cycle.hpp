// ProbeCycle: what a probe edge means in each mode and the retract that follows a hit. A jog
// hit is a point compensated along the jog; an edge in a queued Probe's search is that
// Probe's hit (its MeasPt, then Done once the retract ends with the tip free); an edge on any
// other motion is an unexpected hit (the queue fails, no point); with the loops open it is a
// hand hit (HandMode). Every hit backs off RetractDist from the latched point.
#pragma once
#include <cstdint>

#include "imess/core/loop_context.hpp"

namespace imess::core {

class HandMode;
class Outputs;
class PathFollower;
class StraightMoves;

class ProbeCycle {
 public:
  ProbeCycle(LoopContext& loop, StraightMoves& moves, PathFollower& path, HandMode& hand, Outputs& outputs) noexcept
      : loop_(loop), moves_(moves), path_(path), hand_(hand), outputs_(outputs) {}

  // The backend latched a probe edge this cycle.
  void on_latch(Nanos now) noexcept;
  // One cycle in Retract: the retract ends in position with the tip free; a tip still
  // touched after RetractTime opens the loops (free), and a motion that waited is refused.
  void update_retract(Nanos now) noexcept;
  // The Failed or Done that closes a Probe whose hit has been reported (after its retract);
  // nothing when no Probe is retracting.
  void close(EventKind k, FailReason why, Nanos now) noexcept;
  // Brakes, then backs the probe off `distance` from `from` against `dir` (the direction it
  // pressed in), in Retract like after a hit (a scan pressed over range).
  void back_off(const AxisVec& from, const AxisVec& dir, double distance, Nanos now) noexcept;
  // An unknown contour scan `id` met its stop body: back_off, and the retract's end closes the
  // id as a Probe's (Done, probe_end, `end` = where the machine stands).
  void finish_scan(std::uint32_t id, const AxisVec& from, const AxisVec& dir, double distance, Nanos now) noexcept;

 private:
  // A probe edge in a Probe's search: the hit (with the Probe's id), then the retract from it.
  void probe_hit(const AxisVec& latched, Nanos now) noexcept;
  void unexpected_hit(const AxisVec& latched, Nanos now) noexcept;
  // The move that first brakes with the configured deceleration, then backs off RetractDist
  // from the latched point (within the soft limits once referenced).
  void retract_from(const AxisVec& latched, const AxisVec& dir, Nanos now) noexcept;
  void retract_by(const AxisVec& latched, const AxisVec& dir, double distance, Nanos now) noexcept;

  LoopContext& loop_;
  StraightMoves& moves_;
  PathFollower& path_;
  HandMode& hand_;
  Outputs& outputs_;
  bool retracting_ = false;  // a Probe hit (or an unknown contour's end): its Done follows the retract
  std::uint32_t probe_id_ = 0;  // that Probe's (scan's) id
  bool scan_end_ = false;       // it is an unknown contour's end: its Done says where the machine stands
  AxisVec retract_target_ = AxisVec::Zero();  // where the last retract ends
};

}  // namespace imess::core
