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

TEST_CASE("probed point files: seven numbers per hit, ball centre behind the surface", "[point_file][probed]") {
  const auto hits = parse_probed_points(
      "# messd hits: x y z i j k r\n"
      "2\n"
      "430 330 80 0 0 -1 2\n"
      "10,20,30, 0.6,0.8,0, 1.5  # a bore wall\n");
  REQUIRE(hits.size() == 2);
  CHECK(hits[0].surface == Eigen::Vector3d(430, 330, 80));
  CHECK(hits[0].approach == Eigen::Vector3d(0, 0, -1));
  CHECK(hits[0].radius == 2.0);
  CHECK(hits[0].centre() == Eigen::Vector3d(430, 330, 82));  // the probe came down from above
  CHECK((hits[1].centre() - Eigen::Vector3d(10 - 0.9, 20 - 1.2, 30)).norm() < 1e-12);
  CHECK(hits[1].has_approach());
  // Directions printed with few decimals are normalised.
  const auto rounded = parse_probed_points("0 0 0 0.577 0.577 0.577 1\n");
  CHECK(std::abs(rounded[0].approach.norm() - 1.0) < 1e-15);
  // messd's ForcePt: no direction, no radius; the centre is the point itself.
  const auto forced = parse_probed_points("1 2 3 0 0 0 0\n");
  CHECK_FALSE(forced[0].has_approach());
  CHECK(forced[0].centre() == Eigen::Vector3d(1, 2, 3));
  CHECK(parse_probed_points("# nothing\n\n").empty());
}

TEST_CASE("probed point files: errors name line, column and the expected form", "[point_file][probed][errors]") {
  CHECK_THROWS_WITH(parse_probed_points("1 2 3 0 0 1 2\n1 2 3\n", "h.hits"),
                    Catch::Contains("h.hits:2:1:") && Catch::Contains("expected 7 numbers") && Catch::Contains("got 3"));
  CHECK_THROWS_WITH(parse_probed_points("1 2 3 0 0 1 2 9\n", "h.hits"),
                    Catch::Contains("h.hits:1:15:") && Catch::Contains("got 8"));
  CHECK_THROWS_WITH(parse_probed_points("1 2 3 0 0 1 x\n", "h.hits"),
                    Catch::Contains("h.hits:1:13:") && Catch::Contains("'x'"));
  CHECK_THROWS_WITH(parse_probed_points("1 2 3  0 0.5 0.5 2\n", "h.hits"),
                    Catch::Contains("h.hits:1:8:") && Catch::Contains("unit vector"));
  CHECK_THROWS_WITH(parse_probed_points("1 2 3 0 0 1 -2\n", "h.hits"),
                    Catch::Contains("h.hits:1:13:") && Catch::Contains(">= 0"));
  CHECK_THROWS_WITH(parse_probed_points("1 2 3 0 0 0 2\n", "h.hits"),
                    Catch::Contains("h.hits:1:7:") && Catch::Contains("0 0 0"));
  CHECK_THROWS_WITH(parse_probed_points("3\n1 2 3 0 0 1 2\n", "h.hits"),
                    Catch::Contains("says 3 points") && Catch::Contains("holds 1"));
  CHECK_THROWS_WITH(read_probed_points("/nonexistent/x.hits"), Catch::Contains("cannot open"));
}

TEST_CASE("point files: the column count tells plain from probed", "[point_file][probed]") {
  CHECK(point_file_columns("# c\n3\n1 2 3\n") == 3);
  CHECK(point_file_columns("1 2 3 0 0 1 2\n1 2 3\n") == 7);  // only the first line decides
  CHECK(point_file_columns("\n# none\n") == 0);
  CHECK_THROWS_WITH(point_file_columns("1 y 3\n", "p"), Catch::Contains("p:1:3:"));
}
