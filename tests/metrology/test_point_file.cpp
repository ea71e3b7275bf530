// Point file parser: NIST .ds layout, plain XYZ/CSV, comments, errors with line numbers.
#include <catch2/catch.hpp>

#include "imess/metrology/point_file.hpp"

using namespace imess::metrology;

TEST_CASE("point files: count line, tabs, commas, comments", "[point_file]") {
  const auto pts = parse_points("3\n1\t2\t3\n-4.5\t5e-1\t+6\n7 8 9\n");
  REQUIRE(pts.size() == 3);
  CHECK(pts[1] == Eigen::Vector3d(-4.5, 0.5, 6.0));
  const auto csv = parse_points("# x,y,z\n1,2,3\r\n\n4;5;6 # trailing comment\n");
  REQUIRE(csv.size() == 2);
  CHECK(csv[1] == Eigen::Vector3d(4, 5, 6));
  CHECK(parse_points("").empty());
  // Full precision is kept.
  CHECK(parse_points("0.1 -252.30142114765901617 3")[0].y() == -252.30142114765901617);
}

TEST_CASE("point files: errors say where and what", "[point_file][errors]") {
  CHECK_THROWS_WITH(parse_points("3\n1 2 3\n1 2\n", "a.ds"), Catch::Contains("a.ds:3") && Catch::Contains("expected 3"));
  CHECK_THROWS_WITH(parse_points("1 2 x\n", "b.xyz"), Catch::Contains("b.xyz:1") && Catch::Contains("'x'"));
  CHECK_THROWS_WITH(parse_points("4\n1 2 3\n", "c.ds"), Catch::Contains("says 4 points") && Catch::Contains("holds 1"));
  CHECK_THROWS_WITH(parse_points("2.5\n1 2 3\n", "d.ds"), Catch::Contains("d.ds:1"));
  CHECK_THROWS_WITH(parse_points("1 2 nan\n", "e.ds"), Catch::Contains("finite"));
  CHECK_THROWS_WITH(read_points("/nonexistent/x.ds"), Catch::Contains("cannot open"));
}

TEST_CASE("point files: the NIST copies load with their declared counts", "[point_file]") {
  const auto pts = read_points(std::string(IMESS_TEST_DATA) + "/nist-ls/Sphere/sph5.ds");
  CHECK(pts.size() == 457);
}
