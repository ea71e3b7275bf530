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

// An unknown contour (I++ DME's ScanInPlaneEndIs… / ScanInCylEndIs…): from the surface point
// `start` with outward normal `start_normal`, the ball centre kept in the plane through the
// touched start with normal `plane_normal` (constraint Plane) or on the cylinder about the
// axis through `axis_point` along `axis` through the touched start (Cylinder; the start off
// the axis), leaving toward the point `direction`, following whatever surface it finds until
// the stop body is met the `count`-th time (segment.hpp ScanContour: a sphere's entry, a
// plane's or a cylinder's crossing; `stop_after` mm of contour first), then backing off along
// `end_normal`. The contour runs at most `max_length` mm (and within the travel). Vectors of
// any length but zero; machine X Y Z, mm.
struct ScanContourShape {
  Point3 start{}, start_normal{};
  ContourConstraint constraint = ContourConstraint::Plane;
  Point3 plane_normal{};           // Plane
  Point3 axis_point{}, axis{};     // Cylinder
  Point3 direction{};              // a point the scan leaves toward (not the start)
  StopBody stop = StopBody::Sphere;
  Point3 stop_point{};             // the sphere's centre, a point of the plane, of the cylinder's axis
  Point3 stop_normal{};            // the plane's normal, the cylinder's axis
  double stop_diameter = 0;        // the sphere's, the cylinder's
  int count = 1;                   // which meeting ends the scan, from 1
  double stop_after = 0;           // mm of contour before meetings count (I++: |direction − start| for a plane)
  Point3 end_normal{};             // the back-off's direction at the end
  double max_length = 2000;        // mm
};

using ScanShape = std::variant<ScanLineShape, ScanCircleShape, ScanContourShape>;

struct ScanSettings {
  double tip_radius = 2;      // mm
  double deflection = 0.3;    // mm, the set-point the loop holds
  double band = 0.1;          // mm, ± around it
  double step = 0.1;          // mm between points
  double speed = 5;           // mm/s along the surface (Follow)
  double approach_speed = 5;  // mm/s onto and off the surface
  double clearance = 2;       // mm: the approach starts, and the leave ends, this far off contact
  double feed = 50;           // mm/s to the clearance point
  // The travel (X Y Z), mm: an unknown contour's planned line stays within it.
  Point3 travel_min{-1e9, -1e9, -1e9}, travel_max{1e9, 1e9, 1e9};
};

// The requests, or why there are none (a zero normal or axis, a line shorter than 0.001 mm,
// a normal along the line, a start on the axis, a zero sweep, |axial| > 1, a bore too small
// for the ball, a clearance not above the largest correction; an unknown contour's: see
// scan.cpp contour_requests). An unknown contour gives Position, Approach and one Contour
// segment, no Leave: the loop ends it (its Done carries where the machine stands, as a Probe's).
using ScanRequests = std::variant<std::vector<Request>, std::string>;
ScanRequests scan_requests(std::uint32_t id, const Pose& from, const ScanShape& shape, const ScanSettings& settings);

}  // namespace imess::planner
