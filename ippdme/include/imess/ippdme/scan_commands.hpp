// The scanning methods (I++ DME 1.4.3 §11; docs/ippdme.md, "Scanning"): the report list, the
// hints, the known-contour scans (line, circle, helix) and the unknown-contour scans (in a
// plane or on a cylinder, ending at a sphere, a plane or a cylinder). Points and directions as
// the client sent them, in the session's current coordinate system; directions never without
// norm (the parser refuses those with 1010), not normalised.
#pragma once
#include <array>
#include <optional>
#include <type_traits>
#include <vector>

#include "imess/ippdme/tag.hpp"

namespace imess::ippdme {

// Items of Get, OnPtMeasReport, OnScanReport and OnMoveReportE: X(), Tool.A(), IJK() ...
enum class Item : unsigned char { X, Y, Z, R, ToolA, ToolB, ToolC, IJK, ER, Q };

using Point3 = std::array<double, 3>;  // x, y, z in mm

struct Vector3 {
  double i = 0, j = 0, k = 0;
  friend bool operator==(const Vector3&, const Vector3&) = default;
};

#define IMESS_IPPDME_EQ(T) friend bool operator==(const T&, const T&) = default
// OnScanReport(X(), Y(), Z(), Q()): what each scanned point reports, in this order (not empty).
// StartSession sets kDefaultScanReport.
struct OnScanReport { std::vector<Item> items; IMESS_IPPDME_EQ(OnScanReport); };
inline const std::vector<Item> kDefaultScanReport{Item::X, Item::Y, Item::Z, Item::Q};

// Hints (§11.1.1): they only let the server optimise (slow down); StartSession clears them.
struct ScanOnCircleHint {
  double displacement = 0;  // mm >= 0: the largest expected distance of the real centre from the nominal
  double form = 0;          // mm >= 0: the largest expected form deviation (Gauss circle)
  IMESS_IPPDME_EQ(ScanOnCircleHint);
};
struct ScanOnLineHint {
  double angle = 0;  // degrees >= 0: the largest expected angle between the real and the nominal line
  double form = 0;   // mm >= 0: the largest expected form deviation (Gauss line)
  IMESS_IPPDME_EQ(ScanOnLineHint);
};
struct ScanUnknownHint {
  double min_radius = 0;  // mm > 0: the smallest radius of curvature expected on the contour
  IMESS_IPPDME_EQ(ScanUnknownHint);
};
// ScanUnknownDensity(Dis(d), Angle(a), AngleBaseLength(l)): the point density of the
// unknown-contour scans whose StepW is 0 (each > 0 when given, at least one given).
struct ScanUnknownDensity {
  std::optional<double> dis;                // mm: the largest distance between two points reported
  std::optional<double> angle;              // degrees: the largest angle between the last two segments
  std::optional<double> angle_base_length;  // mm: the base length the angle is taken over (spec 2.x)
  IMESS_IPPDME_EQ(ScanUnknownDensity);
};

// ScanOnCircle(Cx, Cy, Cz, Sx, Sy, Sz, i, j, k, delta, sfa, StepW). The server probes the start
// point first (a PtMeas along the surface normal the surface angle gives, Retract 0), then
// follows the circle about (center, normal) through the touched point for delta degrees.
struct ScanOnCircle {
  Point3 center{};   // the nominal centre
  Point3 start{};    // a point of the circle where the scan starts; |start - center| > 0 is the radius
  Vector3 normal;    // the circle's plane normal, orthogonal to start - center
  double delta = 0;  // degrees, != 0: > 0 counter-clockwise about normal, < 0 clockwise
  double sfa = 0;    // degrees: the surface angle: the surface normal at the start (out of the material)
                     // is cos(sfa) x + sin(sfa) z, x the start direction, z normal: 0 an outer circle
                     // (a shaft), 180 an inner one (a bore), 90 and 270 a plane face, a cone between
  double step = 0;   // degrees, != 0: the mean angle between two points reported (|StepW| is used)
  IMESS_IPPDME_EQ(ScanOnCircle);
};
// ScanOnHelix(Cx, Cy, Cz, Sx, Sy, Sz, i, j, k, delta, sfa, StepW, pitch) (spec 1.5 on): as
// ScanOnCircle, rising by pitch mm along normal per turn; sfa 90 or 270 (a plane) is refused.
struct ScanOnHelix {
  Point3 center{};  // a point of the helix's axis (along normal)
  Point3 start{};   // where the scan starts, off the axis: its distance from the axis is the radius
  Vector3 normal;
  double delta = 0, sfa = 0, step = 0;
  double pitch = 0;  // mm per 360 degrees along normal (negative: against it)
  IMESS_IPPDME_EQ(ScanOnHelix);
};
// ScanOnLine(Sx, Sy, Sz, Ex, Ey, Ez, i, j, k, StepW): a PtMeas at start along -normal (Retract
// 0), then the contour in the plane through start spanned by end - start and normal, until a
// point lies farther from the touched start than |end - start|.
struct ScanOnLine {
  Point3 start{}, end{};  // end != start
  Vector3 normal;         // the surface normal on the line, orthogonal to end - start
  double step = 0;        // mm > 0: the mean distance between two points reported
  IMESS_IPPDME_EQ(ScanOnLine);
};

// The unknown-contour scans (§11.3) start the same: a PtMeas at start along -start_normal
// (Retract 0); the scan then leaves toward `direction` (a point, != start), reports a point
// every `step` mm (0: ScanUnknownDensity's, else the server's), stops at the n-th (`count`)
// meeting of its stop body and retracts along end_normal. In a plane: the tip centre stays in
// the plane through the touched point with normal plane_normal (1.4.3). The 1.4.0 form, which
// the NIST suite sends, has none (nullopt; and ScanInPlaneEndIsSphere no n: count 1): its plane
// holds start_normal and direction - start, scan_plane_normal() gives its normal.
struct ScanInPlaneEndIsSphere {
  Point3 start{};
  Vector3 start_normal;
  std::optional<Vector3> plane_normal;
  Point3 direction{};
  double step = 0;      // mm >= 0
  Point3 end_center{};  // the stop sphere: the scan stops near its centre (a local minimum of the distance)
  double diameter = 0;  // mm > 0
  int count = 1;        // the n-th entry into the sphere ends the scan (1.4.0 form: 1)
  Vector3 end_normal;   // the surface direction at the end: the retract direction
  IMESS_IPPDME_EQ(ScanInPlaneEndIsSphere);
};
struct ScanInPlaneEndIsPlane {
  Point3 start{};
  Vector3 start_normal;
  std::optional<Vector3> plane_normal;
  Point3 direction{};
  double step = 0;
  Point3 stop_point{};  // the stop plane: a point and its normal; checked once the scan has gone
  Vector3 stop_normal;  // farther than |direction - start|
  int count = 1;        // the n-th crossing ends the scan
  Vector3 end_normal;
  IMESS_IPPDME_EQ(ScanInPlaneEndIsPlane);
};
struct ScanInPlaneEndIsCyl {
  Point3 start{};
  Vector3 start_normal;
  std::optional<Vector3> plane_normal;
  Point3 direction{};
  double step = 0;
  Point3 axis_point{};  // the stop cylinder: a point of its axis, the axis, the diameter
  Vector3 axis;
  double diameter = 0;  // mm > 0
  int count = 1;        // the n-th crossing ends the scan
  Vector3 end_normal;
  IMESS_IPPDME_EQ(ScanInPlaneEndIsCyl);
};
// On a cylinder: the tip centre stays on the cylinder about (axis_point, axis) through the
// touched start point (start must lie off the axis).
struct ScanInCylEndIsSphere {
  Point3 axis_point{};
  Vector3 axis;
  Point3 start{};
  Vector3 start_normal;
  Point3 direction{};
  double step = 0;
  Point3 end_center{};
  double diameter = 0;
  int count = 1;  // 1.4.0 form: 1
  Vector3 end_normal;
  IMESS_IPPDME_EQ(ScanInCylEndIsSphere);
};
struct ScanInCylEndIsPlane {
  Point3 axis_point{};
  Vector3 axis;
  Point3 start{};
  Vector3 start_normal;
  Point3 direction{};
  double step = 0;
  Point3 stop_point{};
  Vector3 stop_normal;
  int count = 1;
  Vector3 end_normal;
  IMESS_IPPDME_EQ(ScanInCylEndIsPlane);
};
#undef IMESS_IPPDME_EQ

// The scanning plane's normal of a scan in a plane: plane_normal, or for the 1.4.0 form
// start_normal × (direction - start) (the parser refuses a form where that has no norm).
template <class T>
Vector3 scan_plane_normal(const T& c) {
  if (c.plane_normal) return *c.plane_normal;
  const Vector3& n = c.start_normal;
  const double dx = c.direction[0] - c.start[0], dy = c.direction[1] - c.start[1], dz = c.direction[2] - c.start[2];
  return {n.j * dz - n.k * dy, n.k * dx - n.i * dz, n.i * dy - n.j * dx};
}

// The scanning methods: the server answers them together (0501 until the scan is mapped).
template <class T>
inline constexpr bool is_scan_method_v =
    std::is_same_v<T, OnScanReport> || std::is_same_v<T, ScanOnCircleHint> || std::is_same_v<T, ScanOnLineHint> ||
    std::is_same_v<T, ScanUnknownHint> || std::is_same_v<T, ScanUnknownDensity> || std::is_same_v<T, ScanOnCircle> ||
    std::is_same_v<T, ScanOnHelix> || std::is_same_v<T, ScanOnLine> || std::is_same_v<T, ScanInPlaneEndIsSphere> ||
    std::is_same_v<T, ScanInPlaneEndIsPlane> || std::is_same_v<T, ScanInPlaneEndIsCyl> ||
    std::is_same_v<T, ScanInCylEndIsSphere> || std::is_same_v<T, ScanInCylEndIsPlane>;
template <class T>
concept ScanMethod = is_scan_method_v<T>;

}  // namespace imess::ippdme
