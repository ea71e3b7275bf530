// Sampling planned segments into strokes.
#include "path_trace.hpp"

#include <algorithm>
#include <cmath>

namespace imess::messprog {

void TraceBuilder::add(const planner::PlannedSegment& seg, const programs::Item& item) {
  if (seg.kind != planner::SegmentKind::Line && seg.kind != planner::SegmentKind::Arc) return;
  if (!(seg.length > 0)) return;
  const MoveKind kind = seg.probe != planner::ProbePhase::None ? MoveKind::Probe
                        : item.rapid                          ? MoveKind::Rapid
                                                              : MoveKind::Feed;
  auto& strokes = trace_.strokes;
  if (strokes.empty() || strokes.back().kind != kind || strokes.back().points.back() != seg.start)
    strokes.push_back({kind, {seg.start}});
  auto& points = strokes.back().points;
  if (seg.kind == planner::SegmentKind::Line) {
    points.push_back(seg.end);
  } else {
    const double steps = std::ceil(std::abs(seg.arc.phi) / kArcStepRadians);
    const int n = static_cast<int>(std::clamp(steps, 4.0, 1e5));
    planner::Pose p{}, d{};
    for (int k = 1; k < n; ++k) {
      planner::pose_at(seg, seg.length * k / n, p, d);
      points.push_back(p);
    }
    points.push_back(seg.end);  // exactly, so the next segment joins this stroke
  }
  if (kind == MoveKind::Probe) trace_.probe_targets.push_back(seg.end);
}

}  // namespace imess::messprog
