// 3-2-1 frames of plan features and the part frame from measured alignment features:
// part -> machine = measured datum frame * (nominal datum frame)^-1.
#include "inspection_alignment.hpp"

#include <cmath>
#include <map>

#include <Eigen/Dense>

#include "imess/metrology/alignment.hpp"
#include "imess/metrology/inspection.hpp"
#include "inspection_fit.hpp"

namespace imess::metrology::detail {

using Eigen::Vector3d;

Frame frame_321(const Geometry& primary, const Geometry& secondary, const Geometry& tertiary) {
  Plane plane;
  plane.point = primary.point;
  plane.normal = primary.direction;
  Line3 line;
  if (secondary.kind == FeatureKind::Plane) {
    // X along the intersection of the two planes; the point where it passes nearest the
    // secondary plane's own point.
    const Vector3d d = primary.direction.cross(secondary.direction);
    if (!(d.norm() > 1e-6))
      throw AlignmentError("alignment 3-2-1: the secondary plane is parallel to the primary plane; they meet in no line");
    Eigen::Matrix3d a;
    a.row(0) = primary.direction;
    a.row(1) = secondary.direction;
    a.row(2) = d.normalized();
    const Vector3d b(primary.direction.dot(primary.point), secondary.direction.dot(secondary.point),
                     d.normalized().dot(secondary.point));
    line.point = a.colPivHouseholderQr().solve(b);
    line.direction = d.normalized();
  } else {
    line.point = secondary.point;
    line.direction = secondary.direction;
  }
  Vector3d origin = tertiary.point;
  if (tertiary.kind == FeatureKind::Plane) {
    // x = 0 where the X axis pierces the tertiary plane.
    const Frame provisional = align_321(plane, line, line.point);
    const Vector3d o = provisional.translation();
    const Vector3d x = provisional.rotation().col(0);
    const double along = tertiary.direction.dot(x);
    if (!(std::abs(along) > 1e-6))
      throw AlignmentError("alignment 3-2-1: the tertiary plane is parallel to the X axis; it fixes no x = 0");
    origin = o + tertiary.direction.dot(tertiary.point - o) / along * x;
  }
  return align_321(plane, line, origin);
}

}  // namespace imess::metrology::detail

namespace imess::metrology {

Frame align_part(const InspectionPlan& plan, std::span<const MeasuredPoint> points) {
  if (!plan.alignment) throw InspectionError("the plan has no alignment");
  const auto& al = *plan.alignment;
  auto measured = [&](const std::string& name) {
    const PlanFeature& f = plan.feature(name);
    std::vector<detail::FitInput> in;
    for (const auto& p : points)
      if (p.feature == name) in.push_back({p.point, p.approach, p.radius});
    // Fitted in machine coordinates, oriented like the nominal placed on the machine.
    auto fit = detail::fit_feature(name, to_parent(plan.placement, f.nominal), in);
    if (!fit) throw InspectionError("alignment: " + fit.error().message);
    return fit->geometry;
  };
  try {
    const Frame machine_datums = detail::frame_321(measured(al.primary), measured(al.secondary), measured(al.tertiary));
    const Frame part_datums = detail::frame_321(plan.feature(al.primary).nominal, plan.feature(al.secondary).nominal,
                                                plan.feature(al.tertiary).nominal);
    return machine_datums * part_datums.inverse();
  } catch (const AlignmentError& e) {
    throw InspectionError(e.what());
  }
}

}  // namespace imess::metrology
