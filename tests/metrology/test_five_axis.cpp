// The 5-axis offset convention: the six reference rows (rotated and corrected) and the
// design-frame mapping (points affine, corrections rotation only).
#include <catch2/catch.hpp>

#include <numbers>

#include "imess/metrology/five_axis.hpp"

using namespace imess::metrology;

namespace {

constexpr double kTol = 1e-9;

struct Row {
  const char* name;
  Eigen::Vector3d p;
  double a;
  double b;
  Eigen::Vector3d correction;
  Eigen::Vector3d rotated;
  Eigen::Vector3d corrected;
};

const Eigen::Vector3d kFirst(-327.957, 612.5, 222.0);
const Eigen::Vector3d kSecond(287.5, -40.5, -60.0);

const Row kRows[] = {
    {"1 G510", kFirst, 0, 0, {0.2, 0, 0}, {-327.957, 612.5, 222.0}, {-327.757, 612.5, 222.0}},
    {"1 G511", kFirst, 0, 270, {0.2, 0, 0}, {222.0, 612.5, 327.957}, {222.0, 612.5, 327.757}},
    {"1 G512", kFirst, -90, 180, {0.2, 0, -0.2}, {327.957, 222.0, 612.5}, {327.757, 221.8, 612.5}},
    {"1 G513", kFirst, 0, 90, {0.2, 0, 0}, {-222.0, 612.5, -327.957}, {-222.0, 612.5, -327.757}},
    {"2 G510", kSecond, 0, 180, {0, 0, 0}, {-287.5, -40.5, 60.0}, {-287.5, -40.5, 60.0}},
    {"2 G512", kSecond, -90, 0, {0, 0, 0.2}, {287.5, 60.0, -40.5}, {287.5, 59.8, -40.5}},
};

}  // namespace

TEST_CASE("rotated offsets reproduce the six reference rows", "[five_axis]") {
  for (const Row& row : kRows) {
    INFO(row.name);
    CHECK((rotate_offset(row.p, row.a, row.b) - row.rotated).cwiseAbs().maxCoeff() < kTol);
    WorkOffset w = WorkOffset::from_base(row.p, row.a, row.b);
    w.add_correction(row.correction);
    CHECK((w.rotated_base() - row.rotated).cwiseAbs().maxCoeff() < kTol);
    CHECK((w.rotated() - row.corrected).cwiseAbs().maxCoeff() < kTol);
    CHECK((w.base() - row.p).norm() == 0.0);  // the base is never overwritten
    CHECK((w.correction() - row.correction).norm() == 0.0);
  }
}

TEST_CASE("corrections accumulate next to the base", "[five_axis]") {
  WorkOffset w = WorkOffset::from_base(kFirst, -90, 180);
  w.add_correction({0.1, 0, 0});
  w.add_correction({0.1, 0, -0.2});
  CHECK(w.axis[0].base == -327.957);
  CHECK(w.axis[0].correction == Approx(0.2));
  CHECK((w.rotated() - Eigen::Vector3d(327.757, 221.8, 612.5)).cwiseAbs().maxCoeff() < kTol);
}

TEST_CASE("rotation convention: Rx(-a) Ry(-b), right-handed", "[five_axis]") {
  CHECK((rotation_x(std::numbers::pi / 2) * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm() < 1e-15);
  CHECK((rotation_y(std::numbers::pi / 2) * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm() < 1e-15);
  const Eigen::Vector3d p(1, 2, 3);
  const Eigen::Vector3d expect = rotation_x(-0.3) * rotation_y(-0.5) * p;
  CHECK((rotate_offset(p, 0.3 * 180 / std::numbers::pi, 0.5 * 180 / std::numbers::pi) - expect).norm() < 1e-14);
}

TEST_CASE("design frame: 180 degrees about z turns -0.200 in design x into +0.200 in machine x",
          "[five_axis][frames]") {
  const Eigen::Matrix3d t = Eigen::Vector3d(-1, -1, 1).asDiagonal();
  const Eigen::Vector3d w_machine(100, 200, 0);
  const Eigen::Vector3d w_design(-5, 7, 30);
  const DesignFrame df(t, w_machine, w_design);
  const Eigen::Vector3d corr = df.correction_to_machine({-0.200, 0, 0});
  CHECK((corr - Eigen::Vector3d(0.200, 0, 0)).norm() < 1e-15);
  CHECK((df.correction_to_design(corr) - Eigen::Vector3d(-0.200, 0, 0)).norm() < 1e-15);
  // Points use the full map p_KKS = T (p_MKS - w_MKS) + w_KKS ...
  const Eigen::Vector3d p_mks(110, 195, 12);
  const Eigen::Vector3d p_kks = df.point_to_design(p_mks);
  CHECK((p_kks - (t * (p_mks - w_machine) + w_design)).norm() < 1e-12);
  CHECK((df.point_to_machine(p_kks) - p_mks).norm() < 1e-12);
  // ... the workpiece zeros map onto each other, and a correction is not a point.
  CHECK((df.point_to_design(w_machine) - w_design).norm() < 1e-12);
  CHECK((df.correction_to_design(Eigen::Vector3d::Zero())).norm() == 0.0);
}

TEST_CASE("design frame rejects a matrix that is not a rotation", "[five_axis][frames][errors]") {
  const Eigen::Matrix3d mirror = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  CHECK_THROWS_AS(DesignFrame(mirror, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), FrameError);
  Eigen::Matrix3d skew = Eigen::Matrix3d::Identity();
  skew(0, 1) = 0.01;
  CHECK_THROWS_AS(DesignFrame(skew, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), FrameError);
}
