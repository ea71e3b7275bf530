// Nominal-versus-actual evaluation of an inspection plan: measured points (machine coordinates)
// -> part frame (3-2-1 alignment or the nominal placement) -> one fit per feature (probe
// compensated when the points carry approach and radius) -> every characteristic with its
// deviation and verdict, and every point's deviation from its nominal feature.
// Definitions: docs/metrology.md §15.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "imess/metrology/fit_result.hpp"
#include "imess/metrology/frame.hpp"
#include "imess/metrology/inspection_plan.hpp"

namespace imess::metrology {

// Points that cannot be evaluated at all: a point of a feature the plan does not have, or an
// alignment that cannot be built (an alignment feature without enough points, a failed fit).
class InspectionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One measured point in machine coordinates, as messd's `Hit` gives it: the surface point
// (compensated by the tip radius along the approach), the unit approach and the radius. The ball
// centre was point - radius * approach. Without an approach the point is taken as it is.
struct MeasuredPoint {
  std::string feature;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> approach;
  double radius = 0.0;
};

// Signed distance of p from the ideal geometry g (same frame): positive out of the material
// (along a plane's or point's outward normal; away from a boss's axis, toward a bore's axis).
// A line gives the unsigned distance.
double signed_distance(const Geometry& g, const Eigen::Vector3d& p);
// g with its point and direction mapped by `frame` (local -> parent).
Geometry to_parent(const Frame& frame, const Geometry& g);

struct PointResult {
  std::string feature;
  MeasuredPoint measured;            // as given (machine coordinates)
  Eigen::Vector3d part;              // the surface point in part coordinates, compensated along
                                     // the fitted feature's normal when the fit is probed
  double deviation = 0.0;            // signed distance from the nominal feature
  std::optional<double> form;        // signed distance from the fitted feature (none: no fit)
};

struct FeatureResult {
  std::string name;
  std::size_t point_count = 0;
  std::optional<Geometry> actual;    // part coordinates; none when the fit failed
  FitStats stats;                    // residuals of the fit (form = max - min)
  bool compensated = false;          // fitted to ball centres and offset by the tip radius
  std::optional<std::array<Eigen::Vector3d, 2>> axis_ends;  // line, cylinder, cone: the axis
                                     // over the measured points' extent
  std::vector<Eigen::Vector3d> surface;  // compensated surface points, part coordinates
  std::string error;                 // why there is no fit
};

struct CharacteristicResult {
  Characteristic spec;
  double nominal = 0.0;
  double actual = 0.0;
  double deviation = 0.0;            // actual - nominal (zones: the zone width itself)
  bool in_tolerance = false;
  std::optional<Eigen::Vector3d> nominal_location, actual_location;  // position: the centres
  std::string error;                 // not evaluated (a feature without a fit)
  bool evaluated() const { return error.empty(); }
};

struct AlignmentResult {
  Frame part_to_machine;             // p_machine = R p_part + origin
  bool measured = false;             // from the alignment features (false: the nominal placement)
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();         // origin - placement origin (machine)
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();  // rotation from the placement's axes
                                     // to the measured ones, as a rotation vector in degrees
                                     // about the placement's (part) axes
};

struct InspectionResult {
  AlignmentResult alignment;
  std::vector<FeatureResult> features;              // plan order
  std::vector<PointResult> points;                  // plan order of features, measured order within
  std::vector<CharacteristicResult> characteristics;  // plan order
  std::size_t out_of_tolerance() const;             // evaluated and outside
  std::size_t not_evaluated() const;
};

// The part frame (part -> machine) from the alignment features' points: their fits in machine
// coordinates (oriented like the nominals placed on the machine), the 3-2-1 frame of those and
// of the nominals in part coordinates, composed so that the nominal datums land on the measured
// ones. Throws InspectionError when the plan has no alignment or the frame cannot be built.
Frame align_part(const InspectionPlan& plan, std::span<const MeasuredPoint> points);

// The whole evaluation. Throws InspectionError for points of unknown features or a failed
// alignment; a feature that cannot be fitted is reported in its FeatureResult and leaves its
// characteristics not evaluated.
InspectionResult evaluate_inspection(const InspectionPlan& plan, std::span<const MeasuredPoint> points);

}  // namespace imess::metrology
