// Geometry helpers of the inspection: signed distance from an ideal feature, and a feature
// moved into another frame.
#include <cmath>

#include "imess/metrology/inspection.hpp"
#include "imess/metrology/compare.hpp"

namespace imess::metrology {

double signed_distance(const Geometry& g, const Eigen::Vector3d& p) {
  const Eigen::Vector3d v = p - g.point;
  const double side = g.inner ? -1.0 : 1.0;
  switch (g.kind) {
    case FeatureKind::Point:
    case FeatureKind::Plane: return v.dot(g.direction);
    case FeatureKind::Line: return point_line_distance(p, g.point, g.direction);
    case FeatureKind::Circle: return side * ((v - v.dot(g.direction) * g.direction).norm() - 0.5 * g.diameter);
    case FeatureKind::Sphere: return side * (v.norm() - 0.5 * g.diameter);
    case FeatureKind::Cylinder: return side * ((v - v.dot(g.direction) * g.direction).norm() - 0.5 * g.diameter);
    case FeatureKind::Cone: {
      const double phi = 0.5 * g.apex_angle_deg * M_PI / 180.0;
      const double h = v.dot(g.direction);
      const double rho = (v - h * g.direction).norm();
      return side * (rho * std::cos(phi) - h * std::sin(phi) - 0.5 * g.diameter * std::cos(phi));
    }
  }
  return 0.0;
}

Geometry to_parent(const Frame& frame, const Geometry& g) {
  Geometry out = g;
  out.point = frame.point_to_parent(g.point);
  out.direction = frame.direction_to_parent(g.direction);
  return out;
}

}  // namespace imess::metrology
