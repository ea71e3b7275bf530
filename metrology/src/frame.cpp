// Rigid frames: validation, polar-decomposition orthonormalisation, composition, inverse.
#include "imess/metrology/frame.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/LU>
#include <Eigen/SVD>

namespace imess::metrology {
namespace {

void check_bottom_row(const Eigen::Matrix4d& m) {
  if (!(m(3, 0) == 0.0 && m(3, 1) == 0.0 && m(3, 2) == 0.0 && m(3, 3) == 1.0)) {
    std::ostringstream os;
    os << "a homogeneous frame matrix needs the bottom row 0 0 0 1, got " << m.row(3);
    throw FrameError(os.str());
  }
}

}  // namespace

double Frame::rotation_error(const Eigen::Matrix3d& r) {
  const double ortho = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  return std::max(ortho, std::abs(r.determinant() - 1.0));
}

Frame::Frame(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation, double tolerance) {
  if (!rotation.allFinite() || !translation.allFinite())
    throw FrameError("frame has a non-finite rotation or translation element");
  const double det = rotation.determinant();
  if (det < 0.0) {
    std::ostringstream os;
    os << "frame rotation is a reflection (det " << det << "); a frame must be right-handed";
    throw FrameError(os.str());
  }
  const double err = rotation_error(rotation);
  if (!(err <= tolerance)) {
    std::ostringstream os;
    os << "frame rotation is not orthonormal with det +1 (deviation " << err << ", tolerance "
       << tolerance << ")";
    throw FrameError(os.str());
  }
  r_ = rotation;
  t_ = translation;
}

Frame Frame::from_matrix(const Eigen::Matrix4d& m, double tolerance) {
  check_bottom_row(m);
  return Frame(m.topLeftCorner<3, 3>(), m.topRightCorner<3, 1>(), tolerance);
}

Frame Frame::orthonormalised(const Eigen::Matrix3d& raw, const Eigen::Vector3d& translation,
                             double max_change) {
  if (!raw.allFinite() || !translation.allFinite())
    throw FrameError("frame has a non-finite rotation or translation element");
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(raw, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d s = svd.singularValues();
  if (!(s(2) > 1e-12 * s(0))) throw FrameError("frame rotation is singular (its columns are dependent)");
  if (raw.determinant() < 0.0)
    throw FrameError("frame rotation is a reflection (det < 0); a frame must be right-handed");
  const Eigen::Matrix3d r = svd.matrixU() * svd.matrixV().transpose();
  const double change = (r - raw).cwiseAbs().maxCoeff();
  if (!(change <= max_change)) {
    std::ostringstream os;
    os << "frame rotation is too far from a rotation to orthonormalise (nearest rotation differs by "
       << change << ", allowed " << max_change << ")";
    throw FrameError(os.str());
  }
  return Frame(r, translation);
}

Frame Frame::orthonormalised(const Eigen::Matrix4d& raw, double max_change) {
  check_bottom_row(raw);
  return orthonormalised(Eigen::Matrix3d(raw.topLeftCorner<3, 3>()),
                         Eigen::Vector3d(raw.topRightCorner<3, 1>()), max_change);
}

Eigen::Matrix4d Frame::matrix() const {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = r_;
  m.topRightCorner<3, 1>() = t_;
  return m;
}

Frame Frame::inverse() const {
  Frame f;
  f.r_ = r_.transpose();
  f.t_ = -(r_.transpose() * t_);
  return f;
}

Frame Frame::operator*(const Frame& other) const {
  Frame f;
  f.r_ = r_ * other.r_;
  f.t_ = r_ * other.t_ + t_;
  return f;
}

}  // namespace imess::metrology
