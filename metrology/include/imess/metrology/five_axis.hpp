// The 5-axis work-offset convention (rotary A about x, B about y, swivelling table): offsets
// rotated into a clamping's orientation, corrections kept apart from the base values, and the
// mapping between machine (MKS) and design (KKS) frames.
#pragma once

#include <array>

#include <Eigen/Core>

#include "imess/metrology/frame.hpp"

namespace imess::metrology {

// Right-handed rotations about x and y (angles in radians).
Eigen::Matrix3d rotation_x(double angle_rad);
Eigen::Matrix3d rotation_y(double angle_rad);

// p_rot = Rx(-a) * Ry(-b) * p: the transpose of Ry(b) * Rx(a) ("rotate about y by b, then about
// x by a" as a change of frame). This is the one reading that reproduces all six reference rows.
Eigen::Vector3d rotate_offset(const Eigen::Vector3d& p, double a_deg, double b_deg);

// One axis of a work offset: the base value is never overwritten; corrections accumulate.
struct AxisValue {
  double base = 0.0;
  double correction = 0.0;
  double total() const noexcept { return base + correction; }
};

// A work offset (G510...) of one clamping: per-axis [base, correction] pairs and the rotary
// orientation (degrees) the offset is used at.
struct WorkOffset {
  std::array<AxisValue, 3> axis{};
  double a_deg = 0.0;
  double b_deg = 0.0;

  static WorkOffset from_base(const Eigen::Vector3d& base, double a_deg, double b_deg);
  Eigen::Vector3d base() const;
  Eigen::Vector3d correction() const;
  Eigen::Vector3d total() const;  // base + correction
  // Adds a correction given in the offset's own (unrotated) axes.
  void add_correction(const Eigen::Vector3d& delta);
  // The rotated offsets: corrections are added before the rotation.
  Eigen::Vector3d rotated_base() const { return rotate_offset(base(), a_deg, b_deg); }
  Eigen::Vector3d rotated() const { return rotate_offset(total(), a_deg, b_deg); }
};

// Machine (MKS) <-> design (KKS) mapping p_KKS = T (p_MKS - w_MKS) + w_KKS. T's columns are the
// machine axes in design coordinates and must be a rotation (validated, det = +1); w are the
// workpiece zeros in each frame. Points use the affine map; corrections and deviations are
// directions and use T alone, so no translation ever leaks into a delta.
class DesignFrame {
 public:
  DesignFrame() = default;
  DesignFrame(const Eigen::Matrix3d& t, const Eigen::Vector3d& w_machine, const Eigen::Vector3d& w_design,
              double tolerance = kFrameTolerance);

  Eigen::Vector3d point_to_design(const Eigen::Vector3d& p_machine) const;
  Eigen::Vector3d point_to_machine(const Eigen::Vector3d& p_design) const;
  Eigen::Vector3d correction_to_design(const Eigen::Vector3d& d_machine) const;
  Eigen::Vector3d correction_to_machine(const Eigen::Vector3d& d_design) const;

  // The same mapping as a Frame whose local coordinates are machine and parent is design.
  const Frame& machine_to_design() const noexcept { return frame_; }

 private:
  Frame frame_;
};

}  // namespace imess::metrology
