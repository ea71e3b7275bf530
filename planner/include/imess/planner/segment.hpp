// What the planner is asked for (requests) and what it hands to the motion loop
// (PlannedSegment: trivially copyable, fixed size, so it crosses an SPSC ring as it is).
#pragma once
#include <array>
#include <cstdint>
#include <type_traits>
#include <variant>

#include "imess/planner/axes.hpp"
#include "imess/planner/profile.hpp"

namespace imess::planner {

// Requests. Ids are the client's; poses are absolute and full (the caller fills the axes a
// command does not name with their current position). Feeds follow the feed rule
// (axes.hpp AxisGroup): mm/s along XYZ (else UVW), else deg/s over ABC.
// The part of a probing cycle a segment is (Probe: a fast approach up to PrehitDist before
// the target, then the search at ProbeSpeed up to SearchDist beyond it, both with the
// Probe's id). The motion loop treats a probe edge by it: a hit in the search, an
// unexpected hit anywhere else; the search running out is PartNotFound.
enum class ProbePhase : std::uint8_t { None, Approach, Search };

// The part of a scan a segment is (planner/scan.hpp builds them, all with the scan's id):
// Position (an ordinary move to the clearance point: a probe edge there is an unexpected
// hit), Approach (toward the surface at the approach speed), Follow (the nominal path in
// contact, the motion loop holding the deflection at its set-point and taking points), Leave
// (away from the surface; the loop's correction fades to zero along it, so the scan ends
// exactly at its planned end). Only the Leave's end is answered `Done id`. Contour (an
// unknown contour, after Position and Approach, the scan's last segment): the loop steers the
// ball centre along the surface it finds (ScanContour); the segment's line only gives the
// speed. The loop ends it at its stop body, backs off and answers `Done id` as a Probe's
// (probe_end, where the machine stands).
enum class ScanPhase : std::uint8_t { None, Position, Approach, Follow, Leave, Contour };

// An unknown contour's steering and end (ScanPhase::Contour; planner/scan.hpp
// ScanContourShape): the ball centre stays in a plane (through the touched start, normal
// `plane_normal`) or on a cylinder (about the axis through `axis_point` along `axis`, through
// the touched start), moving along the surface's tangent in it, first along `direction`; the
// scan ends when the measured surface point meets the stop body the `count`-th time: a sphere
// (centre `stop_point`, radius `stop_radius`) on its count-th entry, where the distance to its
// centre is least; a plane (through `stop_point`, normal `stop_normal`) or a cylinder (axis
// through `stop_point` along `stop_normal`, radius `stop_radius`) on its count-th crossing.
// Meetings count once `stop_after` mm of contour lie behind. Then the machine backs off
// `clearance` (plus the deflection) along `end_normal`. Unit vectors; machine X Y Z, mm.
enum class ContourConstraint : std::uint8_t { Plane, Cylinder };
enum class StopBody : std::uint8_t { Sphere, Plane, Cylinder };
struct ScanContour {
  ContourConstraint constraint = ContourConstraint::Plane;
  std::array<double, 3> plane_normal{};            // Plane
  std::array<double, 3> axis_point{}, axis{};      // Cylinder
  std::array<double, 3> direction{};               // the first tangent
  StopBody stop = StopBody::Sphere;
  std::array<double, 3> stop_point{}, stop_normal{};
  double stop_radius = 0;
  std::int32_t count = 1;
  double stop_after = 0;
  std::array<double, 3> end_normal{};
  double clearance = 2;
};

// What the motion loop needs to hold contact on a scan segment: the nominal surface's outward
// normal (X Y Z) — constant on a line; on a circle, at a pose p, radial · unit(p − centre,
// projected off the axis) · √(1 − axial²) + axial · axis — the deflection set-point and band
// and the spacing of the points, mm.
struct ScanSpec {
  ScanPhase phase = ScanPhase::None;
  std::array<double, 3> normal{};          // radial 0: the surface's outward normal (unit)
  std::array<double, 3> centre{}, axis{};  // radial ±1: a point on the axis, its unit direction
  std::int8_t radial = 0;  // 0 a line; +1 the surface faces away from the axis (a boss, a sphere), -1 toward it (a bore)
  double axial = 0;        // the normal's component along the axis (a cone or a sphere off its equator)
  double deflection = 0.3, band = 0.1, step = 0.1;
  ScanContour contour{};  // phase Contour
};

// The largest correction the motion loop makes off a scan's nominal path, mm: a part further
// off its nominal than this is lost contact (or over range), never chased.
inline constexpr double kMaxScanCorrection = 1.0;

struct Line {
  std::uint32_t id = 0;
  Pose target{};
  double feed = 0;
  ProbePhase probe = ProbePhase::None;
  double max_accel = 0;  // > 0: caps the path acceleration (I++ DME's GoToPar.Accel); else the axes' limits alone
  ScanSpec scan{};
};

// A circular arc or helix. The circle lies in the plane through the three linear axes
// `plane_axes` (machine axis indices, e.g. X Y Z = 0 1 2) with unit `normal` (in those
// axes' coordinates; (0,0,1) = the XY plane); `centre` is given in those three axes and
// projected onto the plane through the start. ccw = counter-clockwise seen from +normal.
// turns: extra full turns (≥ 0). The end's component along the normal, and every other
// axis, move linearly along the arc (helix); `planar` refuses an end off the plane through
// the start instead (ArcOffPlane, the same tolerance). The end must lie on the circle:
// |r_end − r_start| ≤ max(Options::arc_tolerance, 1e-3·r, radius_tolerance) or append
// refuses it (ArcRadiusMismatch); between the radii the arc is a spiral.
struct Arc {
  std::uint32_t id = 0;
  Pose target{};
  std::array<double, 3> centre{};
  std::array<double, 3> normal{0, 0, 1};
  std::array<std::int8_t, 3> plane_axes{0, 1, 2};
  bool ccw = true;
  int turns = 0;
  bool planar = false;
  double feed = 0;  // mm/s along the helix
  double radius_tolerance = 0;  // mm, > 0: a wider end-radius tolerance the caller accepted (G-code)
  ScanSpec scan{};
};

struct Dwell {
  std::uint32_t id = 0;
  double seconds = 0;
};

// Sets a digital output when the motion before it has come to rest (exact stop), then holds
// the path there for `hold` seconds (the output's settle time: a probe arming after power-on,
// a gripper closing) before the segment completes.
struct SetOutput {
  std::uint32_t id = 0;
  std::uint16_t output = 0;
  double value = 0;
  double hold = 0;
};

using Request = std::variant<Line, Arc, Dwell, SetOutput>;

enum class SegmentKind : std::uint8_t { Line, Arc, Dwell, SetOutput };

// The circle of an arc segment, in its three plane axes: point(f) = centre + r(f)·(cos θ·e1 +
// sin θ·e2) + f·h·n with θ = f·φ, r(f) = r0 + f·(r1 − r0), f = s / L. The other axes move
// linearly from start to end.
struct ArcGeometry {
  std::array<std::int8_t, 3> axes{0, 1, 2};
  std::array<double, 3> centre{}, e1{}, e2{}, n{};
  double r0 = 0, r1 = 0;  // start and end radius (equal within the tolerance)
  double phi = 0;         // swept angle, radians, signed about n
  double h = 0;           // travel along n (helix lead over the whole arc)
};

struct PlannedSegment {
  std::uint32_t id = 0;
  SegmentKind kind = SegmentKind::Line;
  ProbePhase probe = ProbePhase::None;  // kind Line
  ScanSpec scan{};             // kind Line, Arc
  std::uint16_t output = 0;    // SetOutput
  double output_value = 0;     // SetOutput
  Pose start{}, end{};         // end of one segment == start of the next, bit for bit
  ArcGeometry arc{};           // kind Arc
  double length = 0;           // L, mm (deg for a rotary-only line)
  double v0 = 0, vc = 0, v1 = 0, a = 0;           // the trapezoid
  double t_acc = 0, t_cruise = 0, t_dec = 0;      // its phases, s (Dwell, SetOutput: t_cruise = seconds held)
  Profile profile{};           // s(t), what the sampler evaluates

  double duration() const noexcept { return profile.duration; }
};
static_assert(std::is_trivially_copyable_v<PlannedSegment>);

// The pose at path length s (0 ≤ s ≤ L; s ≥ L gives `end` exactly) and the derivative of
// the pose along the path (axis units per unit of s; zero for a segment that does not move).
void pose_at(const PlannedSegment& seg, double s, Pose& pose, Pose& dpose_ds) noexcept;

}  // namespace imess::planner
