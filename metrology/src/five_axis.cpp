// 5-axis offset convention: rotated offsets, [base, correction] pairs, design-frame mapping.
#include "imess/metrology/five_axis.hpp"

#include <cmath>
#include <numbers>

namespace imess::metrology {
namespace {

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

}  // namespace

Eigen::Matrix3d rotation_x(double angle_rad) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  Eigen::Matrix3d r;
  r << 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c;
  return r;
}

Eigen::Matrix3d rotation_y(double angle_rad) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  Eigen::Matrix3d r;
  r << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
  return r;
}

Eigen::Vector3d rotate_offset(const Eigen::Vector3d& p, double a_deg, double b_deg) {
  return rotation_x(-rad(a_deg)) * (rotation_y(-rad(b_deg)) * p);
}

WorkOffset WorkOffset::from_base(const Eigen::Vector3d& base, double a_deg, double b_deg) {
  WorkOffset w;
  for (int k = 0; k < 3; ++k) w.axis[static_cast<std::size_t>(k)].base = base(k);
  w.a_deg = a_deg;
  w.b_deg = b_deg;
  return w;
}

Eigen::Vector3d WorkOffset::base() const { return {axis[0].base, axis[1].base, axis[2].base}; }

Eigen::Vector3d WorkOffset::correction() const {
  return {axis[0].correction, axis[1].correction, axis[2].correction};
}

Eigen::Vector3d WorkOffset::total() const { return {axis[0].total(), axis[1].total(), axis[2].total()}; }

void WorkOffset::add_correction(const Eigen::Vector3d& delta) {
  for (int k = 0; k < 3; ++k) axis[static_cast<std::size_t>(k)].correction += delta(k);
}

DesignFrame::DesignFrame(const Eigen::Matrix3d& t, const Eigen::Vector3d& w_machine,
                         const Eigen::Vector3d& w_design, double tolerance)
    : frame_(t, w_design - t * w_machine, tolerance) {}

Eigen::Vector3d DesignFrame::point_to_design(const Eigen::Vector3d& p_machine) const {
  return frame_.point_to_parent(p_machine);
}
Eigen::Vector3d DesignFrame::point_to_machine(const Eigen::Vector3d& p_design) const {
  return frame_.point_from_parent(p_design);
}
Eigen::Vector3d DesignFrame::correction_to_design(const Eigen::Vector3d& d_machine) const {
  return frame_.direction_to_parent(d_machine);
}
Eigen::Vector3d DesignFrame::correction_to_machine(const Eigen::Vector3d& d_design) const {
  return frame_.direction_from_parent(d_design);
}

}  // namespace imess::metrology
