// Planner: the non-real-time side. Validates requests against the machine, limits each
// segment by every moving axis, links segments by junction deviation, runs look-ahead in v²
// and hands out segments whose profile can no longer change. The queued tail always ends
// at rest, so a loop that runs out of segments stops on the path.
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>

#include "imess/planner/axes.hpp"
#include "imess/planner/segment.hpp"

namespace imess::planner {

struct PlannerOptions {
  // Cornering: junction deviation δ, mm (grbl's default). When square_corner_velocity > 0
  // (mm/s, Klipper's form) δ = v_sc²(√2 − 1)/a is derived from it per junction instead.
  double junction_deviation = 0.01;
  double square_corner_velocity = 0;
  double loop_period = 0.001;           // s, the sampler's tick
  double min_segment_periods = 1.02;    // v ≤ L / (periods · loop_period): ≥ 1 tick per segment
  double arc_tolerance = 0.002;         // mm: allowed end-radius mismatch (or 1e-3·r if larger)
  double min_feed = 0;                  // a moving segment's feed below this is BadFeed (0: any > 0)
};

// Why append refused a request. Never renumbered; the daemon maps them to protocol errors
// (OutOfTravel → Err 206 naming the id and axis).
enum class PlanError : std::uint8_t {
  None = 0,
  OutOfTravel = 1,        // the segment leaves the travel of `axis` (arc: its extreme points too)
  BadFeed = 2,            // feed ≤ 0, below min_feed or not finite for a segment that moves
  BadPose = 3,            // a target value is not finite
  BadDwell = 4,           // negative or not finite seconds
  ArcBadPlane = 5,        // plane axes not three distinct linear axes, or normal zero
  ArcRadiusMismatch = 6,  // the end is not on the circle through the start
  ArcDegenerate = 7,      // start on the centre (radius 0)
  ArcZeroNormal = 8,      // the plane's normal is zero or not finite
  ArcOffPlane = 9,        // a planar arc whose end is off the plane through the start
  ArcBadTurns = 10,       // extra turns below 0
  ProbeNoDirection = 11,  // a probing move's target on its start (the daemon's Probe)
  BadScan = 12,           // a scan's shape makes no scan (scan_requests says why)
};

struct AppendResult {
  PlanError error = PlanError::None;
  std::uint32_t id = 0;    // the refused request's id
  std::int8_t axis = -1;   // OutOfTravel: machine axis index
  double value = 0;        // OutOfTravel: the offending coordinate; ArcRadiusMismatch: |Δr|;
                           // ArcOffPlane: the end's distance from the plane
  double limit = 0;        // ArcRadiusMismatch, ArcOffPlane: the tolerance that was exceeded
  bool ok() const noexcept { return error == PlanError::None; }
};
// One line for a log or an Err reply: "segment 12: axis Y leaves its travel at 1012.5".
std::string describe(const AppendResult& r, const Machine& m);

class Planner {
 public:
  // Throws std::invalid_argument when the machine or the options are not usable.
  explicit Planner(const Machine& machine, const PlannerOptions& options = {});

  // Where planning starts. Discards everything not yet taken (the daemon calls it after a
  // stop, with the position where the machine came to rest).
  void set_position(const Pose& pose);
  // The end of the last accepted request.
  const Pose& position() const noexcept { return position_; }

  // Validates and queues a request; on refusal nothing changes. Segments that became final
  // are ready for take().
  AppendResult append(const Request& request);
  // Makes everything queued final, ending at rest (input paused or ended).
  void flush();

  // Final segments, oldest first: their profile never changes again.
  std::size_t ready() const noexcept { return ready_.size(); }
  bool take(PlannedSegment& out);
  // Queued but not final yet (their speeds may still rise as more requests arrive).
  std::size_t pending() const noexcept { return pending_.size(); }
  // Seconds of motion in the final segments not yet taken.
  double ready_duration() const noexcept;

  const Machine& machine() const noexcept { return machine_; }
  const PlannerOptions& options() const noexcept { return options_; }

 private:
  struct Entry {
    PlannedSegment seg;
    double v_nom2 = 0;      // cruise speed² limit (feed, axes, centripetal, min duration)
    double max_entry2 = 0;  // junction limit with the previous segment
    double entry2 = 0;      // planned entry speed² (the tail ends at rest)
    double best2 = 0;       // the same if the tail could end at any speed: an upper bound
                            // for every future plan, so entry2 == best2 means final
    Pose dir_in{}, dir_out{};  // unit tangents at start and end (all axes); zero: no motion
    bool moves = false;
    AxisGroup path_group = AxisGroup::Primary;  // the axes L is measured over
  };
  bool feed_ok(double feed) const noexcept;
  AppendResult queue_line(const Line& l);
  AppendResult queue_arc(const Arc& a);
  void queue_rest(PlannedSegment seg);
  void push(Entry e);
  double junction_v2(const Entry& prev, const Entry& next) const noexcept;
  void recalculate();
  void release_final(bool all);
  void finish(Entry& e, double exit2);
  AppendResult check_travel(std::uint32_t id, const Pose& p) const;

  Machine machine_;
  PlannerOptions options_;
  std::array<AxisGroup, kMaxAxes> group_{};
  Pose position_{};
  std::deque<Entry> pending_;
  std::deque<PlannedSegment> ready_;
  // The newest released segment: its exit speed is the entry of pending_.front().
  Entry last_final_{};
  bool have_last_final_ = false;
};

}  // namespace imess::planner
