// An inspection plan: the part's nominal features (geometry in part coordinates and the probe
// points that measure them), its nominal placement on the machine, the 3-2-1 alignment and the
// toleranced characteristics. Parsed from JSON (docs/metrology.md §14 has the format).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "imess/metrology/frame.hpp"

namespace imess::metrology {

// A bad plan: "<source>: <key path>: <what was expected>". Set-up code: thrown.
class InspectionPlanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class FeatureKind { Point, Line, Plane, Circle, Sphere, Cylinder, Cone };
std::string_view to_string(FeatureKind kind) noexcept;  // "point", "line", ...

// The ideal geometry of one feature, in one frame. What `point` and `direction` mean per kind:
//   point:    the surface point / the outward surface normal there
//   line:     a point on the line / its direction
//   plane:    a point on it / the outward normal (pointing out of the material)
//   circle:   the centre / the normal of its plane
//   sphere:   the centre / unused
//   cylinder: a point on the axis / the axis direction
//   cone:     a point on the axis / the axis, toward increasing radius
struct Geometry {
  FeatureKind kind = FeatureKind::Point;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit
  double diameter = 0.0;        // circle, sphere, cylinder; cone: the cross-section through `point`
  double apex_angle_deg = 0.0;  // cone: full apex angle
  bool inner = false;           // circle, sphere, cylinder, cone: material outside (a bore)
};

// One nominal probe point: the surface point touched and the direction the probe moves in
// (into the material), both in part coordinates.
struct ProbeTarget {
  Eigen::Vector3d point;
  Eigen::Vector3d approach;  // unit
};

// One scan of a feature with a measuring probe (messd's ScanCirc or ScanLine), part coordinates.
struct ScanPath {
  enum class Kind { Circle, Line };
  Kind kind = Kind::Circle;
  Eigen::Vector3d start = Eigen::Vector3d::Zero();   // the surface point the scan starts at
  // Circle: round `axis` (unit) through `center`, `sweep_deg` degrees (right hand about the
  // axis; beyond 360 it goes round again), the surface facing the axis (`bore`) or away.
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double sweep_deg = 360.0;
  bool bore = false;
  // Line: from `start` to the surface point `end`, on a surface whose outward normal is `normal` (unit).
  Eigen::Vector3d end = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  std::optional<double> step;   // mm between points (messd's ScanStep); none: the machine's
  std::optional<double> speed;  // mm/s along the surface; none: the machine's ScanSpeed

  // The surface's outward unit normal where the scan starts and where it ends, and that end.
  Eigen::Vector3d normal_at_start() const;
  Eigen::Vector3d end_point() const;
  Eigen::Vector3d normal_at_end() const;
  double length() const;  // mm along the surface
};

struct PlanFeature {
  std::string name;
  Geometry nominal;
  std::vector<ProbeTarget> probes;  // may be empty when points come from a file
  std::vector<ScanPath> scans;      // measured after the probe points
  bool lift_between = false;        // "moves": "lift": to the safe height between its points
};

enum class CharacteristicKind {
  Size, Position, Distance, Angle, Flatness, Roundness, Cylindricity, Perpendicularity, Parallelism, Sphericity
};
std::string_view to_string(CharacteristicKind kind) noexcept;  // "size", "position", ...
// Zone characteristics (position, form, orientation) have nominal 0 and one limit: the zone
// width; the others have a nominal value and lower/upper limits on the deviation.
bool is_zone(CharacteristicKind kind) noexcept;

struct Characteristic {
  std::string name;
  CharacteristicKind kind = CharacteristicKind::Size;
  std::string feature;             // the toleranced feature (distance, angle: the first)
  std::string other;               // distance, angle: the second feature; orientation: the datum
  std::optional<double> nominal;   // size, distance, angle: overrides the value from the nominals
  bool radius = false;             // size: report the radius instead of the diameter
  double lower = 0.0, upper = 0.0; // limits of the deviation (zones: lower 0, upper the width)
};

// Moves of a live measurement: every probe starts `clearance` mm off the surface (plus the tip
// radius) and moves between features at part z = safe_z.
struct ProbingSettings {
  double clearance = 5.0;
  double safe_z = 50.0;                 // part coordinates
  double feed = 50.0;                   // mm/s, positioning and probe approach
  std::optional<double> tip_radius;     // sent as Set TipRadius when given
  std::optional<double> search;         // sent as Set SearchDist when given
};

struct Alignment321 {
  std::string primary;    // a plane
  std::string secondary;  // a plane (X along its intersection with the primary) or a line
  std::string tertiary;   // a point, plane, circle or sphere (x = 0 there)
};

struct InspectionPlan {
  std::string part;                     // a name for reports (and the part frame on messd)
  Frame placement;                      // nominal part -> machine
  std::optional<Alignment321> alignment;
  ProbingSettings probing;
  std::vector<PlanFeature> features;
  std::vector<Characteristic> characteristics;

  const PlanFeature* find(std::string_view name) const;
  const PlanFeature& feature(std::string_view name) const;  // throws std::out_of_range
};

// Parses and checks a plan: every key's type and range, names unique and referenced features
// present, characteristics applicable to their features' kinds, alignment features of the kinds
// 3-2-1 needs. Throws InspectionPlanError "<source>: features[2].probe[0].approach: expected ...".
InspectionPlan parse_inspection_plan(std::string_view json_text, std::string_view source = "<plan>");

}  // namespace imess::metrology
