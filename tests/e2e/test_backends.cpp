// One behaviour, every backend: the same measuring scenario through messd's TCP protocol
// on the emulated servo card, the stepper machine on the parallel port (both pin maps) and
// the port-I/O drive kit. Cube top from one point, the table plane from three, the bore
// from three; every result within 5 um of the simulated part.
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

namespace {


void measure_the_part(const std::string& config) {
  DaemonProcess messd({"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/" + config});
  LineClient c(messd.port());
  MeasuringOperator op(c);
  // The machine stands at (430, 330, 100) over the cube (top z = 80, bore at (460, 350), d 30).
  Vector3d top = op.touch(-Vector3d::UnitZ());
  op.go_to({430, 330, 90});
  // The table beside the cube, three points around the front-left corner.
  std::vector<Vector3d> table;
  op.go_to({385, 320, 90});
  table.push_back(op.probe({385, 320, 10}, -Vector3d::UnitZ()));
  table.push_back(op.probe({385, 380, 10}, -Vector3d::UnitZ()));
  op.go_to({385, 290, 10});
  table.push_back(op.probe({460, 290, 10}, -Vector3d::UnitZ()));
  op.go_to({460, 290, 90});
  // The bore: three points on the wall from its middle.
  op.go_to({460, 350, 90});
  std::vector<Vector3d> bore;
  for (double deg : {10.0, 130.0, 250.0}) {
    double a = deg * M_PI / 180;
    bore.push_back(op.probe({460, 350, 40}, {std::cos(a), std::sin(a), 0}));
  }
  op.go_to({460, 350, 90});

  auto plane = imess::metrology::fit_plane(table).value();
  Vector3d up = plane.normal.z() > 0 ? plane.normal : Vector3d(-plane.normal);
  auto circle = imess::metrology::fit_circle3d(bore).value();
  INFO(config);
  CHECK(top.z() == Approx(80.0).margin(0.005));
  for (const auto& p : table) CHECK(p.z() == Approx(0.0).margin(0.005));
  CHECK(std::abs(plane.signed_distance(top)) == Approx(80.0).margin(0.005));
  CHECK(std::acos(std::min(1.0, up.z())) < 0.005 / 100);  // flat within 5 um over 100 mm
  CHECK(circle.diameter == Approx(30.0).margin(0.005));
  CHECK(circle.center.x() == Approx(460.0).margin(0.005));
  CHECK(circle.center.y() == Approx(350.0).margin(0.005));
  c.send("Quit");
}

}  // namespace

TEST_CASE("one behaviour: the servo card measures the part within 5 um", "[long]") { measure_the_part("backend-servo-card.json"); }
TEST_CASE("one behaviour: the SHD-adapter stepper measures the part within 5 um", "[long]") {
  measure_the_part("backend-parport-shd.json");
}
TEST_CASE("one behaviour: the 3D-Step stepper measures the part within 5 um", "[long]") {
  measure_the_part("backend-parport-3dstep.json");
}
TEST_CASE("one behaviour: the port-I/O drive kit measures the part within 5 um", "[long]") {
  measure_the_part("backend-portio-drive.json");
}
