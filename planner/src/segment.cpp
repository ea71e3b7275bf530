// Geometry of a planned segment: path length → pose, for lines and arcs/helices.
#include "imess/planner/segment.hpp"

#include <cmath>

namespace imess::planner {

void pose_at(const PlannedSegment& seg, double s, Pose& pose, Pose& d) noexcept {
  d.fill(0);
  const double L = seg.length;
  if (L <= 0) {
    pose = seg.end;
    return;
  }
  if (s >= L) pose = seg.end;
  const double f = std::fmin(std::fmax(s / L, 0.0), 1.0);
  for (int i = 0; i < kMaxAxes; ++i) {
    const double delta = seg.end[i] - seg.start[i];
    if (s < L) pose[i] = seg.start[i] + f * delta;
    d[i] = delta / L;
  }
  if (seg.kind != SegmentKind::Arc) return;
  const ArcGeometry& g = seg.arc;
  const double th = f * g.phi, c = std::cos(th), sn = std::sin(th);
  const double r = g.r0 + f * (g.r1 - g.r0);
  const double dr = (g.r1 - g.r0) / L, dth = g.phi / L, dh = g.h / L;
  for (int k = 0; k < 3; ++k) {
    const int i = g.axes[k];
    const double radial = c * g.e1[k] + sn * g.e2[k];
    const double tangential = -sn * g.e1[k] + c * g.e2[k];
    if (s < L) pose[i] = g.centre[k] + r * radial + f * g.h * g.n[k];
    d[i] = dr * radial + r * dth * tangential + dh * g.n[k];
  }
}

}  // namespace imess::planner
