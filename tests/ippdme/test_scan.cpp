// The scanning methods (docs/ippdme.md, "Scanning"): the lines the spec's examples and the NIST
// suite send parse to the geometry they mean (the 1.4.0 unknown-contour forms too), every bad
// form gets the spec's number, OnScanReport's items and default, and the scan data lines.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "imess/ippdme/format.hpp"
#include "imess/ippdme/parser.hpp"

using namespace imess::ippdme;

namespace {
constexpr Tag kT16{TagKind::Command, 16};

Command command_of(std::string_view line) {
  auto r = parse_line(line);
  if (auto* e = std::get_if<LineError>(&r)) FAIL("error " << number_of(e->code) << " for: " << line);
  return std::get<Request>(r).command;
}
int error_number(std::string_view line) {
  auto r = parse_line(line);
  if (std::holds_alternative<Request>(r)) FAIL("parsed, expected an error: " << line);
  return number_of(std::get<LineError>(r).code);
}
}  // namespace

TEST_CASE("ippdme scanning: the spec's examples (1.4.3 §11.4)") {
  // A bore of radius 20 about (100, 0, -3), all round, inner surface (sfa 180), a point every 0.5°.
  CHECK(command_of("00016 ScanOnCircle (100, 0, -3, 120, 0, -3, 0, 0, 1, 360, 180, 0.5)") ==
        Command{ScanOnCircle{{100, 0, -3}, {120, 0, -3}, {0, 0, 1}, 360, 180, 0.5}});
  CHECK(command_of("00015 ScanOnCircleHint (0.01, 0.001)") == Command{ScanOnCircleHint{0.01, 0.001}});
  CHECK(command_of("00015 ScanUnknownHint (100.0)") == Command{ScanUnknownHint{100}});
  // §11.4.2 writes ScanInPlaneEndIsSphere in its 1.4.0 form (no plane normal, no n): the plane
  // then holds the start's surface direction and the way to the direction point: x = 100.
  const Command sphere = command_of("00016 ScanInPlaneEndIsSphere (100,0,0,0,0,1,100,1,0,0.2,100,100,1.5,1.0,0,0,1)");
  CHECK(sphere ==
        Command{ScanInPlaneEndIsSphere{{100, 0, 0}, {0, 0, 1}, std::nullopt, {100, 1, 0}, 0.2, {100, 100, 1.5}, 1, 1, {0, 0, 1}}});
  CHECK(scan_plane_normal(std::get<ScanInPlaneEndIsSphere>(sphere)) == Vector3{-1, 0, 0});
}

TEST_CASE("ippdme scanning: the NIST suite's scan lines parse (allCmdOK.prg and the Scan*.prg files)") {
  CHECK(command_of("00510 OnScanReport(X(), Y(), Tool.A(), R(), Tool.B(), Z(), Tool.C())") ==
        Command{OnScanReport{{Item::X, Item::Y, Item::ToolA, Item::R, Item::ToolB, Item::Z, Item::ToolC}}});
  CHECK(command_of("00330 OnScanReport(ER(),IJK(),Q(),R(),X(),Y(),Z(),Tool.A(),Tool.B(),Tool.C())") ==
        Command{OnScanReport{{Item::ER, Item::IJK, Item::Q, Item::R, Item::X, Item::Y, Item::Z, Item::ToolA, Item::ToolB,
                              Item::ToolC}}});
  CHECK(command_of("00590 ScanOnCircle(0,0,0,4,5,6,6,0,-4,10,1,2)") ==
        Command{ScanOnCircle{{0, 0, 0}, {4, 5, 6}, {6, 0, -4}, 10, 1, 2}});
  CHECK(command_of("00020 ScanOnCircle(2,1,0,6,4,0,0,0,7,143.2,90,90)") ==
        Command{ScanOnCircle{{2, 1, 0}, {6, 4, 0}, {0, 0, 7}, 143.2, 90, 90}});
  CHECK(command_of("00600 ScanOnCircleHint(10.0, 1)") == Command{ScanOnCircleHint{10, 1}});
  CHECK(command_of("00030 ScanOnCircleHint(0, 0)") == Command{ScanOnCircleHint{0, 0}});
  CHECK(command_of("00610 ScanOnLine(0,1,2,14,15,2,0,0,1,0.5)") == Command{ScanOnLine{{0, 1, 2}, {14, 15, 2}, {0, 0, 1}, 0.5}});
  CHECK(command_of("00620 ScanOnLineHint(20, 2.45)") == Command{ScanOnLineHint{20, 2.45}});
  CHECK(command_of("00630 ScanUnknownHint(0.1)") == Command{ScanUnknownHint{0.1}});
  // The unknown-contour scans in their 1.4.0 form: no plane normal (derived: SIJK × (D − S)), n 1.
  const Command sphere = command_of("00580 ScanInPlaneEndIsSphere(0,0,0,0,0,1,2,0,0,0.5,9,0,0,1.4,0,0,1)");
  CHECK(sphere ==
        Command{ScanInPlaneEndIsSphere{{0, 0, 0}, {0, 0, 1}, std::nullopt, {2, 0, 0}, 0.5, {9, 0, 0}, 1.4, 1, {0, 0, 1}}});
  CHECK(scan_plane_normal(std::get<ScanInPlaneEndIsSphere>(sphere)) == Vector3{0, 2, 0});
  const Command plane = command_of("00570 ScanInPlaneEndIsPlane(0,0,0,0,0,1,2,0,0,0.5,9,0,0,-1,0,0,1,0,0,1)");
  CHECK(plane ==
        Command{ScanInPlaneEndIsPlane{{0, 0, 0}, {0, 0, 1}, std::nullopt, {2, 0, 0}, 0.5, {9, 0, 0}, {-1, 0, 0}, 1, {0, 0, 1}}});
  CHECK(scan_plane_normal(std::get<ScanInPlaneEndIsPlane>(plane)) == Vector3{0, 2, 0});
  const Command cyl = command_of("00560 ScanInPlaneEndIsCyl(0,0,0,0,0,1,2,2,0,0.5,8,8,0,0,0,1,0.7,1,0,0,1)");
  CHECK(cyl ==
        Command{ScanInPlaneEndIsCyl{{0, 0, 0}, {0, 0, 1}, std::nullopt, {2, 2, 0}, 0.5, {8, 8, 0}, {0, 0, 1}, 0.7, 1, {0, 0, 1}}});
  CHECK(scan_plane_normal(std::get<ScanInPlaneEndIsCyl>(cyl)) == Vector3{-2, 2, 0});
  CHECK(command_of("00550 ScanInCylEndIsSphere(0,0,0,0,0,1,2,0,0,1,0,0,2,1,0,0.8,0,2,7,4,0,1,0)") ==
        Command{ScanInCylEndIsSphere{{0, 0, 0}, {0, 0, 1}, {2, 0, 0}, {1, 0, 0}, {2, 1, 0}, 0.8, {0, 2, 7}, 4, 1, {0, 1, 0}}});
  CHECK(command_of("00540 ScanInCylEndIsPlane(0,0,0,0,0,1,2,0,0,1,0,0,2,-1,0,0.9,0,2,7,0,0,1,1,0,-1,0)") ==
        Command{ScanInCylEndIsPlane{{0, 0, 0}, {0, 0, 1}, {2, 0, 0}, {1, 0, 0}, {2, -1, 0}, 0.9, {0, 2, 7}, {0, 0, 1}, 1, {0, -1, 0}}});
  // ScanOnLine.prg's surface normal (1, 1, 1) runs along its line (2, 2, 2) -> (4, 4, 4): no scan
  // plane; the spec wants them orthogonal.
  CHECK(error_number("00010 ScanOnLine(2,2,2,4,4,4,1,1,1,.1)") == 509);
}

TEST_CASE("ippdme scanning: every bad form gets 0502, 0505, 1010 or 0509") {
  struct Bad {
    std::string line;
    int number;
  };
  const std::vector<Bad> bad{
      // 0502: count or kind (the NIST parser's cases among them)
      {"00001 ScanOnCircle(1)", 502},
      {"00001 ScanOnCircle(0, 0, 0, 4, 5, 6, 6, 0, -4, 10, 1, X)", 502},
      {"00001 ScanOnCircle(0, 0, 0, 4, 5, 6, 6, 0, -4, 10, 1)", 502},
      {"00001 ScanOnCircle(0, 0, 0, 4, 5, 6, 6, 0, -4, 10, 1, 2, 3)", 502},
      {"00001 ScanOnCircleHint(1)", 502},
      {"00001 ScanOnLineHint(1, \"2\")", 502},
      {"00001 ScanOnLine(1)", 502},
      {"00001 ScanOnHelix(0, 0, 0, 4, 5, 6, 6, 0, -4, 10, 1, 2)", 502},
      {"00001 ScanUnknownHint()", 502},
      {"00001 ScanUnknownHint(\"bigger than a breadbox\")", 502},
      {"00001 ScanUnknownDensity()", 502},
      {"00001 ScanUnknownDensity(1, 1)", 502},
      {"00001 ScanUnknownDensity(Dis(1), Dis(2))", 502},
      {"00001 ScanUnknownDensity(Dis())", 502},
      {"00001 ScanInPlaneEndIsSphere(0,0,0,0,0,1,2,0,0,0.5,9,0,0,1.4,0,0)", 502},
      {"00001 ScanInPlaneEndIsPlane(0,0,0,0,0,1,2,0,0,0.5,9,0,0,-1,0,0,1,0,0,1,1)", 502},
      {"00001 ScanInPlaneEndIsCyl(1,2,3,4,5,6,7,8,9,10,1,2,3,4,5,6,X,8,9,10,1)", 502},
      {"00001 ScanInCylEndIsSphere(0,0,0,0,0,1,2,0,0,1,0,0,2,1,0,0.8,0,2,7,4,0,1)", 502},
      {"00001 ScanInCylEndIsPlane(0,0,0,0,0,1,2,0,0,1,0,0,2,-1,0,0.9,0,2,7,0,0,1,0,-1,0)", 502},
      {"00001 OnScanReport(X(), X())", 502},
      {"00001 OnScanReport(X(1))", 502},
      // 0505: a name not known there
      {"00001 ScanUnknownDensity(Dis(1), Step(2))", 505},
      // 1010: a direction without norm
      {"00001 ScanOnCircle(1,2,3,4,5,6,0,0,0,10,1,2)", 1010},
      {"00001 ScanOnLine(0, 0, 0, 10, 0, 0, 0, 0, 0, 1)", 1010},
      {"00001 ScanInCylEndIsPlane(1,2,3,0,0,0,7,8,9,0,1,2,3,4,5,6,7,8,9,0,1,2,3,4,5,6)", 1010},
      {"00001 ScanInCylEndIsPlane(1,2,3,4,5,6,7,8,9,0,0,0,3,4,5,6,7,8,9,0,1,2,3,4,5,6)", 1010},
      {"00001 ScanInCylEndIsPlane(1,2,3,4,5,6,7,8,9,0,1,2,3,4,5,6,7,8,9,0,0,0,3,4,5,6)", 1010},
      {"00001 ScanInCylEndIsPlane(1,2,3,4,5,6,7,8,9,0,1,2,3,4,5,6,7,8,9,0,1,2,3,0,0,0)", 1010},
      {"00001 ScanInPlaneEndIsSphere(0,0,0,0,0,1,0,0,0,2,0,0,0.5,9,0,0,1.4,1,0,0,1)", 1010},  // the plane normal
      {"00001 ScanInPlaneEndIsCyl(0,0,0,0,0,1,2,2,0,0.5,8,8,0,0,0,0,0.7,1,0,0,1)", 1010},    // the stop axis
      // 0509: a value outside its domain
      {"00001 ScanOnCircleHint(-0.1, 1)", 509},
      {"00001 ScanOnLineHint(1, -1)", 509},
      {"00001 ScanUnknownHint(-1)", 509},
      {"00001 ScanUnknownHint(0)", 509},
      {"00001 ScanUnknownDensity(Angle(0))", 509},
      {"00001 ScanOnCircle(1,2,3,1,2,3,7,8,9,10,1,2)", 509},       // no radius
      {"00001 ScanOnCircle(1,2,3,4,5,6,7,8,9,10,1,2)", 509},       // the start direction not in the circle's plane
      {"00001 ScanOnCircle(0,0,0,4,5,6,6,0,-4,0,1,2)", 509},       // delta 0
      {"00001 ScanOnCircle(0,0,0,4,5,6,6,0,-4,10,1,0)", 509},      // StepW 0
      {"00001 ScanOnHelix(0,0,0,10,0,0,0,0,1,720,90,2,1)", 509},   // a helix on a plane face
      {"00001 ScanOnHelix(0,0,0,10,0,0,0,0,1,720,-270,2,1)", 509},
      {"00001 ScanOnLine(1,2,3,1,2,3,7,8,9,10)", 509},             // start is end
      {"00001 ScanOnLine(1,2,3,4,5,6,7,8,9,-10)", 509},
      {"00001 ScanOnLine(0,0,0,10,0,0,0,0,1,0)", 509},             // StepW 0
      {"00001 ScanInPlaneEndIsSphere(0,0,0,0,0,1,2,0,0,-0.5,9,0,0,1.4,0,0,1)", 509},  // StepW < 0
      {"00001 ScanInPlaneEndIsSphere(0,0,0,0,0,1,2,0,0,0.5,9,0,0,0,0,0,1)", 509},     // Dia 0
      {"00001 ScanInPlaneEndIsSphere(0,0,0,0,0,1,0,0,0,0.5,9,0,0,1.4,0,0,1)", 509},   // direction is start
      {"00001 ScanInPlaneEndIsSphere(0,0,0,0,0,1,0,0,5,0.5,9,0,0,1.4,0,0,1)", 509},   // 1.4.0: no plane
      {"00001 ScanInPlaneEndIsSphere(0,0,0,0,0,1,0,1,0,2,0,0,0.5,9,0,0,1.4,0,0,0,1)", 509},   // n 0
      {"00001 ScanInPlaneEndIsPlane(0,0,0,0,0,1,2,0,0,0.5,9,0,0,-1,0,0,2.5,0,0,1)", 509},     // n not whole
      {"00001 ScanInPlaneEndIsCyl(0,0,0,0,0,1,2,2,0,0.5,8,8,0,0,0,1,-0.7,1,0,0,1)", 509},     // d < 0
      {"00001 ScanInCylEndIsSphere(1,2,3,4,5,6,1,2,3,10,1,2,3,4,5,6,7,8,9,10,1,2,3)", 509},   // start on the axis
      {"00001 ScanInCylEndIsPlane(0,0,0,0,0,1,0,0,5,1,0,0,2,-1,0,0.9,0,2,7,0,0,1,1,0,-1,0)", 509},
      {"00001 ScanInCylEndIsPlane(0,0,0,0,0,1,2,0,0,1,0,0,2,-1,0,0.9,0,2,7,0,0,1,1e10,0,-1,0)", 509},  // n beyond an int
      // 0510: a report list without items or with one that is none
      {"00001 OnScanReport()", 510},
      {"00001 OnScanReport(Dis())", 510},
      {"00001 OnScanReport(Tool())", 510},
  };
  for (const auto& b : bad) {
    INFO(b.line);
    CHECK(error_number(b.line) == b.number);
  }
}

TEST_CASE("ippdme scanning: a 1.4.0 form is written back as read (a plane scan) or with its n (on a cylinder)") {
  const Tag t1{TagKind::Command, 1};
  const Command cyl = command_of("00001 ScanInCylEndIsSphere(0,0,0,0,0,1,2,0,0,1,0,0,2,1,0,0.8,0,2,7,4,0,1,0)");
  const std::string cyl_line = format_command(t1, cyl);
  CHECK(cyl_line == "00001 ScanInCylEndIsSphere(0, 0, 0, 0, 0, 1, 2, 0, 0, 1, 0, 0, 2, 1, 0, 0.8, 0, 2, 7, 4, 1, 0, 1, 0)\r\n");
  CHECK(command_of(cyl_line.substr(0, cyl_line.size() - 2)) == cyl);
  const Command plane = command_of("00001 ScanInPlaneEndIsSphere(0.1,0.2,0.3,0.1,0.2,0.7,2.01,0.03,0,0.5,9,0,0,1.4,0,0,1)");
  const std::string plane_line = format_command(t1, plane);
  CHECK(plane_line == "00001 ScanInPlaneEndIsSphere(0.1, 0.2, 0.3, 0.1, 0.2, 0.7, 2.01, 0.03, 0, 0.5, 9, 0, 0, 1.4, 0, 0, 1)\r\n");
  CHECK(command_of(plane_line.substr(0, plane_line.size() - 2)) == plane);
}

TEST_CASE("ippdme scanning: OnScanReport's default, every report item once in the order given") {
  CHECK(kDefaultScanReport == std::vector<Item>{Item::X, Item::Y, Item::Z, Item::Q});  // StartSession's
  CHECK(command_of("00001 OnScanReport(Q(), IJK(), X())") == Command{OnScanReport{{Item::Q, Item::IJK, Item::X}}});
  CHECK(declaration_of(OnScanReport{}).queue == Queue::Normal);
  CHECK(declaration_of(ScanOnCircle{}).queue == Queue::Normal);
  CHECK(error_number("E0001 ScanOnCircle(0,0,0,4,5,6,6,0,-4,10,1,2)") == 1);  // a normal-queue method
}

TEST_CASE("ippdme scanning: the data line: values without names, ',' between, in OnScanReport's order") {
  const std::vector<ScanPoint> points{
      {{118.5, 0.0001, -3.0002}, {-1, 0, 0}, 1.5, 0, 0, 0, 0, 0},
      {{118.4992, 0.16141, -3.0002}, {-0.99996, -0.00807, 0}, 1.5, 7.4, 0, 0, 0, 0},
  };
  CHECK(format_scan_data(kT16, kDefaultScanReport, points) ==
        "00016 # 118.5000,0.0001,-3.0002,0,118.4992,0.1614,-3.0002,7\r\n");
  CHECK(format_scan_data(kT16, {Item::IJK, Item::ER, Item::Z}, std::span(points).first(1)) ==
        "00016 # -1.000000,0.000000,0.000000,1.5000,-3.0002\r\n");
  CHECK(format_scan_data(kT16, {Item::R, Item::ToolA, Item::ToolB, Item::ToolC}, std::span(points).first(1)) ==
        "00016 # 0.0000,0.0000,0.0000,0.0000\r\n");
  CHECK(format_scan_data(kT16, kDefaultScanReport, {}).empty());
  // Q is a whole number 0..100.
  ScanPoint q;
  q.q = 250;
  CHECK(format_scan_data(kT16, {Item::Q}, std::span(&q, 1)) == "00016 # 100\r\n");
  CHECK(scan_values_per_point(kDefaultScanReport) == 4);
  CHECK(scan_values_per_point({Item::X, Item::IJK}) == 4);
}

TEST_CASE("ippdme scanning: a full line of every item stays short, and reads back as it was written") {
  const std::vector<Item> all{Item::X, Item::Y, Item::Z, Item::IJK, Item::ER, Item::Q, Item::R, Item::ToolA, Item::ToolB, Item::ToolC};
  std::vector<ScanPoint> points(kScanPointsPerLine);
  for (std::size_t n = 0; n < points.size(); ++n) {
    auto& p = points[n];
    p.xyz = {-12345.5 + static_cast<double>(n), 2.25, 1e5 + 0.125};  // exact in 4 decimals
    p.ijk = {0.6, -0.8, 0};
    p.er = 1.5;
    p.q = static_cast<double>(n);
    p.r = 90;
    p.tool_b = -45;
  }
  const std::string line = format_scan_data(kT16, all, points);
  CHECK(line.size() < 4096);
  CHECK(line.find_first_of("\r\n") == line.size() - 2);
  const auto back = read_scan_data(std::string_view(line).substr(8, line.size() - 10), all);
  REQUIRE(back);
  CHECK(*back == points);
  // A payload that is not whole points, or holds something else than numbers, is refused.
  CHECK_FALSE(read_scan_data("1,2,3", kDefaultScanReport));
  CHECK_FALSE(read_scan_data("1,2,3,X(4)", kDefaultScanReport));
  CHECK(read_scan_data("118.5, 0.0001, -3.0002, 0", kDefaultScanReport)->size() == 1);  // the spec's spaces
}
