// A scan as planner requests, as probe.hpp makes a Probe's: from where the machine stands, a
// move to a clearance point off the surface's start (Position), the approach along the
// surface's normal to the ball centre's contact position (Approach), the nominal path at the
// deflection set-point (Follow: a line, or an arc — a circle or a helix), and the way off the
// surface (Leave), every segment with the scan's id and its ScanSpec. The ball centre's path
// is the surface's, offset by (tip radius − deflection set-point) along the outward normal:
// with the part where it should be, the probe is deflected by exactly the set-point. The
// motion loop corrects along the measured normal when the part is elsewhere (docs/scanning.md).
// X Y Z are machine axes 0 1 2; the other axes stay where the machine stands.
#pragma once
#include <array>
#include <string>
#include <variant>
#include <vector>

#include "imess/planner/segment.hpp"

namespace imess::planner {

using Point3 = std::array<double, 3>;

// Along a straight line on a surface: start and end surface points, the surface's outward
// normal there (any length but zero; its part along the line is dropped).
struct ScanLineShape {
  Point3 start{}, end{}, normal{};
};

// Around an axis: a circle (lead 0) or a helix through the surface point `start`, about the
// axis through `centre` with direction `axis`, `sweep` degrees (right hand about the axis;
// more than 360 goes round again), `lead` mm along the axis over the whole sweep. radial +1:
// the surface faces away from the axis (a boss, a sphere's circle), -1: toward it (a bore).
// axial: the outward normal's part along the axis (0 on a cylinder; sin of a cone's or a
// sphere's surface angle; ±1 a ring on a flat face square to the axis), |axial| ≤ 1.
struct ScanCircleShape {
  Point3 centre{}, start{}, axis{0, 0, 1};
  double sweep = 360;
  int radial = -1;
  double axial = 0;
  double lead = 0;
};

using ScanShape = std::variant<ScanLineShape, ScanCircleShape>;

struct ScanSettings {
  double tip_radius = 2;      // mm
  double deflection = 0.3;    // mm, the set-point the loop holds
  double band = 0.1;          // mm, ± around it
  double step = 0.1;          // mm between points
  double speed = 5;           // mm/s along the surface (Follow)
  double approach_speed = 5;  // mm/s onto and off the surface
  double clearance = 2;       // mm: the approach starts, and the leave ends, this far off contact
  double feed = 50;           // mm/s to the clearance point
};

// The requests, or why there are none (a zero normal or axis, a line shorter than 0.001 mm,
// a normal along the line, a start on the axis, a zero sweep, |axial| > 1, a bore too small
// for the ball, a clearance not above the largest correction).
using ScanRequests = std::variant<std::vector<Request>, std::string>;
ScanRequests scan_requests(std::uint32_t id, const Pose& from, const ScanShape& shape, const ScanSettings& settings);

}  // namespace imess::planner
