// (d) The worked example of 1996 through the protocol: a cube with a vertical bore on the
// table, measured with the fewest points — table plane 3, one side 3, the other sides 1
// each, top 1, bore 3 — and reconstructed. The simulated part: 120 x 100 x 80 mm, bore
// diameter 30 mm, turned 0.3 degrees about the vertical.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

#include "daemon_process.hpp"
#include "measuring_operator.hpp"
#include "imess/metrology/fit.hpp"
#include "imess/protocol/messages.hpp"

using namespace imess::test;
using Eigen::Vector3d;


TEST_CASE("the 1996 worked example: cube and bore reconstructed within 5 um", "[long]") {
  DaemonProcess messd({"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/fast-cmm.json"});
  LineClient c(messd.port());
  MeasuringOperator op(c);
  const double safe_z = 120;

  // 1. The resting plane (the table beside the cube), 3 points far apart.
  std::vector<Vector3d> table;
  for (Vector3d xy : {Vector3d(300, 200, 0), Vector3d(700, 220, 0), Vector3d(320, 520, 0)}) {
    op.go_to({xy.x(), xy.y(), safe_z});
    table.push_back(op.probe({xy.x(), xy.y(), 20}, -Vector3d::UnitZ()));
    op.go_to({xy.x(), xy.y(), safe_z});
  }
  // 2. One side (the left face, x = 400) from 3 points, approached along +X.
  std::vector<Vector3d> left;
  op.go_to({380, 320, safe_z});
  for (Vector3d yz : {Vector3d(0, 320, 20), Vector3d(0, 385, 25), Vector3d(0, 350, 65)})
    left.push_back(op.probe({380, yz.y(), yz.z()}, Vector3d::UnitX()));
  op.go_to({380, 350, safe_z});
  // 3. The other three sides, 1 point each (perpendicular faces).
  op.go_to({540, 350, safe_z});
  Vector3d right = op.probe({540, 350, 40}, -Vector3d::UnitX());
  op.go_to({540, 350, safe_z});
  op.go_to({460, 280, safe_z});
  Vector3d front = op.probe({460, 280, 30}, Vector3d::UnitY());
  op.go_to({460, 280, safe_z});
  op.go_to({460, 420, safe_z});
  Vector3d back = op.probe({460, 420, 40}, -Vector3d::UnitY());
  op.go_to({460, 420, safe_z});
  // 4. The top, 1 point.
  Vector3d top = op.probe({430, 330, 100}, -Vector3d::UnitZ());
  // 5. The bore: 3 points on the wall from its middle.
  op.go_to({460, 350, 100});
  std::vector<Vector3d> bore;
  for (double deg : {10.0, 130.0, 250.0}) {
    double a = deg * M_PI / 180;
    bore.push_back(op.probe({460, 350, 40}, {std::cos(a), std::sin(a), 0}));
  }
  op.go_to({460, 350, 100});

  // Reconstruction.
  auto table_plane = imess::metrology::fit_plane(table).value();
  auto left_plane = imess::metrology::fit_plane(left).value();
  Vector3d up = table_plane.normal.z() > 0 ? table_plane.normal : Vector3d(-table_plane.normal);
  Vector3d across = up.cross(left_plane.normal).normalized();  // in the table, along the left face

  double length = std::abs(left_plane.signed_distance(right));
  double width = std::abs((back - front).dot(across));
  double height = std::abs(table_plane.signed_distance(top));
  auto circle = imess::metrology::fit_circle3d(bore).value();

  CHECK(length == Approx(120.0).margin(0.005));
  CHECK(width == Approx(100.0).margin(0.005));
  CHECK(height == Approx(80.0).margin(0.005));
  CHECK(circle.diameter == Approx(30.0).margin(0.005));
  // The bore axis is parallel to the vertical edges: perpendicular to the table.
  CHECK(std::abs(circle.normal.dot(up)) == Approx(1.0).margin(1e-6));
  // The cube is turned 0.3 degrees: the left face normal shows it.
  double yaw = std::atan2(std::abs(left_plane.normal.y()), std::abs(left_plane.normal.x())) * 180 / M_PI;
  CHECK(yaw == Approx(0.3).margin(0.01));
}
