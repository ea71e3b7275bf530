// Frames: validation, polar-decomposition orthonormalisation, point vs direction transforms.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include "imess/metrology/frame.hpp"

using namespace imess::metrology;

namespace {

Eigen::Matrix3d some_rotation() {
  return (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

TEST_CASE("frame maps points affinely and directions by rotation only", "[frame]") {
  const Eigen::Matrix3d r = some_rotation();
  const Eigen::Vector3d t(100, -200, 50);
  const Frame f(r, t);
  const Eigen::Vector3d p(1, 2, 3);
  CHECK((f.point_to_parent(p) - (r * p + t)).norm() < 1e-12);
  CHECK((f.direction_to_parent(p) - r * p).norm() < 1e-12);
  CHECK((f.point_from_parent(f.point_to_parent(p)) - p).norm() < 1e-12);
  CHECK((f.direction_from_parent(f.direction_to_parent(p)) - p).norm() < 1e-14);
  // A delta between two points transforms like a direction: no translation leaks in.
  const Eigen::Vector3d q(-4, 0.5, 9);
  CHECK(((f.point_to_parent(q) - f.point_to_parent(p)) - f.direction_to_parent(q - p)).norm() < 1e-12);

  const Frame inv = f.inverse();
  CHECK((inv.point_to_parent(f.point_to_parent(p)) - p).norm() < 1e-12);
  CHECK(((f * inv).matrix() - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff() < 1e-12);
  const Frame g(some_rotation().transpose(), Eigen::Vector3d(1, 1, 1));
  CHECK(((f * g).point_to_parent(p) - f.point_to_parent(g.point_to_parent(p))).norm() < 1e-12);
  CHECK((Frame::from_matrix(f.matrix()).matrix() - f.matrix()).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("frame validation rejects non-rotations with a clear message", "[frame][errors]") {
  Eigen::Matrix3d scaled = 1.01 * Eigen::Matrix3d::Identity();
  CHECK_THROWS_WITH(Frame(scaled, Eigen::Vector3d::Zero()), Catch::Contains("not orthonormal"));
  Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity();
  mirror(2, 2) = -1.0;
  CHECK_THROWS_WITH(Frame(mirror, Eigen::Vector3d::Zero()), Catch::Contains("reflection"));
  CHECK_THROWS_WITH(Frame::orthonormalised(mirror, Eigen::Vector3d::Zero()), Catch::Contains("reflection"));
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(0, 1) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(Frame(nan, Eigen::Vector3d::Zero()), FrameError);
  Eigen::Matrix4d bottom = Eigen::Matrix4d::Identity();
  bottom(3, 0) = 1.0;
  CHECK_THROWS_WITH(Frame::from_matrix(bottom), Catch::Contains("bottom row"));
  Eigen::Matrix3d singular = Eigen::Matrix3d::Identity();
  singular.col(2) = singular.col(0);
  CHECK_THROWS_WITH(Frame::orthonormalised(singular, Eigen::Vector3d::Zero()), Catch::Contains("singular"));
  CHECK_THROWS_WITH(Frame::orthonormalised(Eigen::Matrix3d(2.0 * Eigen::Matrix3d::Identity()), Eigen::Vector3d::Zero()),
                    Catch::Contains("too far"));
}

TEST_CASE("orthonormalisation is the polar decomposition, not per-column normalisation", "[frame]") {
  const Eigen::Matrix3d r0 = some_rotation();
  // raw = R0 * P with P symmetric positive definite: its nearest rotation is exactly R0.
  Eigen::Matrix3d p;
  p << 1.0002, 3e-4, -2e-4, 3e-4, 0.9997, 1e-4, -2e-4, 1e-4, 1.0001;
  const Eigen::Matrix3d raw = r0 * p;
  const Frame f = Frame::orthonormalised(raw, Eigen::Vector3d(1, 2, 3));
  CHECK((f.rotation() - r0).cwiseAbs().maxCoeff() < 1e-14);
  CHECK(Frame::rotation_error(f.rotation()) < 1e-14);
  CHECK(std::abs(f.rotation().determinant() - 1.0) < 1e-14);
  // Per-column normalisation would leave non-orthogonal columns:
  Eigen::Matrix3d cols = raw;
  for (int k = 0; k < 3; ++k) cols.col(k).normalize();
  CHECK(std::abs(cols.col(0).dot(cols.col(1))) > 1e-4);
  // 4x4 form keeps the translation.
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = raw;
  m.topRightCorner<3, 1>() = Eigen::Vector3d(7, 8, 9);
  CHECK((Frame::orthonormalised(m).translation() - Eigen::Vector3d(7, 8, 9)).norm() == 0.0);
}
