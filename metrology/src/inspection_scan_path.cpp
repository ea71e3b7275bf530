// ScanPath's geometry: the surface normals at a scan's ends and its end point, from which a
// live inspection positions the probe before and after it.
#include <cmath>

#include <Eigen/Geometry>

#include "imess/metrology/inspection_plan.hpp"

namespace imess::metrology {
namespace {

// The unit vector from the axis toward p, square to the axis.
Eigen::Vector3d scan_radial(const ScanPath& s, const Eigen::Vector3d& p) {
  const Eigen::Vector3d off = p - s.center;
  return (off - off.dot(s.axis) * s.axis).normalized();
}

}  // namespace

Eigen::Vector3d ScanPath::end_point() const {
  if (kind == Kind::Line) return end;
  return center + Eigen::AngleAxisd(sweep_deg * M_PI / 180.0, axis) * (start - center);
}

Eigen::Vector3d ScanPath::normal_at_start() const {
  if (kind == Kind::Line) return normal;
  return bore ? -scan_radial(*this, start) : scan_radial(*this, start);
}

Eigen::Vector3d ScanPath::normal_at_end() const {
  if (kind == Kind::Line) return normal;
  const Eigen::Vector3d p = end_point();
  return bore ? -scan_radial(*this, p) : scan_radial(*this, p);
}

double ScanPath::length() const {
  if (kind == Kind::Line) return (end - start).norm();
  const Eigen::Vector3d off = start - center;
  return (off - off.dot(axis) * axis).norm() * std::abs(sweep_deg) * M_PI / 180.0;
}

}  // namespace imess::metrology
