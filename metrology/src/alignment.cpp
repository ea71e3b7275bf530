// 3-2-1 and plane + two hole alignments.
#include "imess/metrology/alignment.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

namespace imess::metrology {
namespace {

// Below this sine between the secondary direction and the plane normal the X axis is undefined.
constexpr double kMinInPlane = 1e-6;

Eigen::Vector3d unit_normal(const Plane& p) {
  if (!p.point.allFinite() || !p.normal.allFinite() || p.normal.norm() == 0.0)
    throw AlignmentError("alignment: the primary plane needs a finite point and a non-zero normal");
  return p.normal.normalized();
}

Eigen::Vector3d onto_plane(const Eigen::Vector3d& q, const Eigen::Vector3d& p0, const Eigen::Vector3d& z) {
  return q - (q - p0).dot(z) * z;
}

Frame make_frame(const Eigen::Vector3d& x, const Eigen::Vector3d& z, const Eigen::Vector3d& origin) {
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  return Frame(r, origin);
}

}  // namespace

Frame align_321(const Plane& primary, const Line3& secondary, const Eigen::Vector3d& origin_point) {
  const Eigen::Vector3d z = unit_normal(primary);
  if (!secondary.point.allFinite() || !secondary.direction.allFinite() || !origin_point.allFinite())
    throw AlignmentError("alignment 3-2-1: the line and the origin point must be finite");
  const Eigen::Vector3d d = secondary.direction - secondary.direction.dot(z) * z;
  if (!(d.norm() > kMinInPlane * secondary.direction.norm())) {
    std::ostringstream os;
    os << "alignment 3-2-1: the secondary line is perpendicular to the primary plane (in-plane part "
       << d.norm() << "); it cannot give the X direction";
    throw AlignmentError(os.str());
  }
  const Eigen::Vector3d x = d.normalized();
  const Eigen::Vector3d line_point = onto_plane(secondary.point, primary.point, z);
  const Eigen::Vector3d origin = line_point + (origin_point - line_point).dot(x) * x;
  return make_frame(x, z, origin);
}

Frame align_plane_two_holes(const Plane& primary, const Eigen::Vector3d& hole1,
                            const Eigen::Vector3d& hole2) {
  const Eigen::Vector3d z = unit_normal(primary);
  if (!hole1.allFinite() || !hole2.allFinite())
    throw AlignmentError("alignment plane + two holes: hole centres must be finite");
  const Eigen::Vector3d h1 = onto_plane(hole1, primary.point, z);
  const Eigen::Vector3d h2 = onto_plane(hole2, primary.point, z);
  const Eigen::Vector3d d = h2 - h1;
  const double scale = std::max({1.0, hole1.cwiseAbs().maxCoeff(), hole2.cwiseAbs().maxCoeff()});
  if (!(d.norm() > 1e-9 * scale)) {
    std::ostringstream os;
    os << "alignment plane + two holes: the holes coincide after projection into the plane (distance "
       << d.norm() << ")";
    throw AlignmentError(os.str());
  }
  return make_frame(d.normalized(), z, h1);
}

}  // namespace imess::metrology
