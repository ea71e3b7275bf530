// The planned path as polylines for drawing: every line and arc segment of the dry run,
// arcs sampled every degree (planner::pose_at), joined into strokes of one kind of move —
// feed, rapid or probe — and the target of every probing move.
#pragma once
#include <cstdint>
#include <vector>

#include "imess/planner/segment.hpp"
#include "imess/programs/program.hpp"

namespace imess::messprog {

enum class MoveKind : std::uint8_t { Feed, Rapid, Probe };

struct Stroke {
  MoveKind kind = MoveKind::Feed;
  std::vector<planner::Pose> points;  // two or more
};

struct PathTrace {
  std::vector<Stroke> strokes;
  std::vector<planner::Pose> probe_targets;  // one per probing move, where its search ends
};

inline constexpr double kArcStepRadians = 3.14159265358979323846 / 180;  // one degree

class TraceBuilder {
 public:
  // A SegmentVisitor for programs::check_program: lines and arcs are drawn, dwells and
  // outputs are not.
  void add(const planner::PlannedSegment& seg, const programs::Item& item);
  const PathTrace& trace() const { return trace_; }

 private:
  PathTrace trace_;
};

}  // namespace imess::messprog
