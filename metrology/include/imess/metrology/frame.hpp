// Rigid coordinate frames: a validated rotation (orthonormal, det = +1) plus a translation,
// mapping coordinates in the frame ("local") to the coordinates of its parent.
#pragma once

#include <stdexcept>

#include <Eigen/Core>

namespace imess::metrology {

// Bad frame input (not a rotation, reflection, singular, non-finite). Set-up code: thrown.
class FrameError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Tolerance for "is already a rotation": max |R^T R - I| and |det R - 1|.
inline constexpr double kFrameTolerance = 1e-9;
// Largest change orthonormalisation may make to a raw matrix before it is rejected as not
// meant to be a rotation (wrong units, a scale factor, a typo).
inline constexpr double kMaxOrthonormalisation = 1e-3;

class Frame {
 public:
  Frame() = default;  // identity
  // Validating: throws FrameError unless `rotation` is orthonormal with det +1 within tolerance.
  Frame(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
        double tolerance = kFrameTolerance);

  // Homogeneous 4x4 [R t; 0 0 0 1], validated like the constructor (bottom row exact).
  static Frame from_matrix(const Eigen::Matrix4d& m, double tolerance = kFrameTolerance);
  // Nearest rotation to a raw (measured, typed, rounded) matrix by polar decomposition (SVD:
  // R = U V^T). Throws if the matrix is singular, a reflection (det < 0), or needs a change larger
  // than max_change (max element) to become a rotation.
  static Frame orthonormalised(const Eigen::Matrix3d& raw, const Eigen::Vector3d& translation,
                               double max_change = kMaxOrthonormalisation);
  static Frame orthonormalised(const Eigen::Matrix4d& raw, double max_change = kMaxOrthonormalisation);

  const Eigen::Matrix3d& rotation() const noexcept { return r_; }
  const Eigen::Vector3d& translation() const noexcept { return t_; }
  Eigen::Matrix4d matrix() const;
  Frame inverse() const;
  // (a * b) maps b-local coordinates to a's parent: a.point_to_parent(b.point_to_parent(p)).
  Frame operator*(const Frame& other) const;

  // Points use the full affine map.
  Eigen::Vector3d point_to_parent(const Eigen::Vector3d& p) const { return r_ * p + t_; }
  Eigen::Vector3d point_from_parent(const Eigen::Vector3d& p) const { return r_.transpose() * (p - t_); }
  // Directions, corrections and deviations use the rotation only (no translation leaks in).
  Eigen::Vector3d direction_to_parent(const Eigen::Vector3d& v) const { return r_ * v; }
  Eigen::Vector3d direction_from_parent(const Eigen::Vector3d& v) const { return r_.transpose() * v; }

  // Largest deviation of a 3x3 matrix from a rotation: max(|R^T R - I|max, |det R - 1|).
  static double rotation_error(const Eigen::Matrix3d& r);

 private:
  Eigen::Matrix3d r_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t_ = Eigen::Vector3d::Zero();
};

}  // namespace imess::metrology
