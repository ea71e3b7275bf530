// The whole-program check (what messd runs at Load and Run, and messprog check prints):
// language by extension, the dry run's length, time, box and segment count against hand
// sums, and refusals with the program's line.
#include <catch2/catch.hpp>
#include <cmath>

#include "imess/programs/check.hpp"

using namespace imess::programs;
using imess::planner::make_machine;

TEST_CASE("check: the language follows the file's extension, any case") {
  CHECK(language_of("part.NGC") == Language::Gcode);
  CHECK(language_of("a.b.tap") == Language::Gcode);
  CHECK(language_of("x.nc") == Language::Gcode);
  CHECK(language_of("x.gcode") == Language::Gcode);
  CHECK(language_of("drawing.plt") == Language::Hpgl);
  CHECK(language_of("drawing.hpgl") == Language::Hpgl);
  CHECK(language_of("arm.mrm") == Language::Mrm);
  CHECK_FALSE(language_of("notes.txt"));
  CHECK_FALSE(language_of("noextension"));
  CHECK(language_named("HPGL") == Language::Hpgl);
  CHECK_FALSE(language_named("dmis"));
}

TEST_CASE("check: a square at feed, a rapid and a dwell give length, time, box and segments") {
  Setup s;
  s.machine = make_machine("XYZ", 0, 200, 50, 500);
  s.start = {10, 10, 0};
  const auto c = check_program(Language::Gcode,
                               "G0 X20 Y20\nG1 X60 F600\nY60\nX20\nY20\nG4 P1.5\nM2\n", s);
  INFO(c.error);
  REQUIRE(c.ok);
  CHECK(c.lines == 7);
  CHECK(c.blocks == 7);      // 5 moves, a dwell, the end
  CHECK(c.segments == 6);
  CHECK(c.rapid_length == Approx(std::sqrt(200.0)));
  CHECK(c.feed_length == Approx(160));
  CHECK(c.length == Approx(160 + std::sqrt(200.0)));
  // 160 mm at 10 mm/s with corners: more than 16 s of feed, plus the dwell and the rapid
  CHECK(c.time > 16 + 1.5);
  CHECK(c.time < 16 + 1.5 + 2);
  CHECK(c.low[0] == Approx(10));
  CHECK(c.low[1] == Approx(10));
  CHECK(c.high[0] == Approx(60));
  CHECK(c.high[1] == Approx(60));
}

TEST_CASE("check: an arc's box is its circle's extreme, not its end points") {
  Setup s;
  s.start = {0, 0, 0};
  const auto c = check_program(Language::Gcode, "G1 F600 X10\nG3 X-10 Y0 I-10 J0\n", s);
  REQUIRE(c.ok);
  CHECK(c.high[1] == Approx(10).margin(0.01));  // the half circle's top
  CHECK(c.low[0] == Approx(-10));
  CHECK(c.length == Approx(10 + 10 * 3.14159265358979).epsilon(1e-6));
}

TEST_CASE("check: an arc leaving the travel is refused with its line, though both ends lie inside") {
  Setup s;
  s.machine = make_machine("XYZ", -15, 15, 50, 500);
  s.gcode.check_travel = true;
  const auto c = check_program(Language::Gcode, "G1 F600 X10\n(half circle over the top)\nG3 X-10 Y0 R10\nG3 X10 Y0 R10\n", s);
  REQUIRE(c.ok);  // R10 fits in ±15
  const auto bad = check_program(Language::Gcode, "G1 F600 X10\nG1 Y-8\nG3 X10 Y8 R-10\n", s);
  REQUIRE_FALSE(bad.ok);  // the big arc round the left reaches X -16
  CHECK(bad.error_line == 3);
  CHECK_THAT(bad.error, Catch::StartsWith("line 3:1: out of travel: axis X leaves its travel"));
}

TEST_CASE("check: a translation error keeps its line and column") {
  const auto c = check_program(Language::Gcode, "G0 X1\nG1 X2 #5\n", Setup{});
  REQUIRE_FALSE(c.ok);
  CHECK(c.error_line == 2);
  CHECK_THAT(c.error, Catch::StartsWith("line 2:7: bad character"));
}

TEST_CASE("check: a probe is one search segment to its target at the program's feed") {
  Setup s;
  int probes = 0;
  const auto c = check_program(Language::Gcode, "G38.2 Z-10 F60\nG0 Z5\n", s, {},
                               [&](const imess::planner::PlannedSegment& seg, const Item& item) {
                                 if (seg.probe == imess::planner::ProbePhase::Search) {
                                   ++probes;
                                   CHECK(item.line == 1);
                                   CHECK(seg.end[2] == Approx(-10));
                                   CHECK(seg.vc == Approx(1));
                                 }
                               });
  INFO(c.error);
  REQUIRE(c.ok);
  CHECK(probes == 1);
  CHECK(c.probe_length == Approx(10));
  CHECK(c.low[2] == Approx(-10));
}

TEST_CASE("check: MRM and HPGL run through the same dry run") {
  Setup s;
  s.machine = make_machine("XYCAB", -1000, 1000, 100, 1000);
  const auto m = check_program(Language::Mrm, "N1 F1000\nN2 X5000\nN3 X-5000\nN4 M02\n", s);
  REQUIRE(m.ok);
  CHECK(m.length == Approx(1000));
  CHECK(m.high[0] == Approx(500));
  Setup h;
  const auto p = check_program(Language::Hpgl, "IN;PU0,0;PD400,0,400,400;PU;", h);
  REQUIRE(p.ok);
  CHECK(p.feed_length == Approx(20 + 5));  // 800 plotter units at 40 per mm, and the pen lowered 5 mm
  CHECK(p.high[0] == Approx(10));
}

TEST_CASE("check: an arc's box holds its exact extreme points (G3 I-300 reports +-300), G28's move home is a rapid") {
  Setup s;
  const Check c = check_program(Language::Gcode, "G0 X300\nG3 I-300 F6000\n", s);
  REQUIRE(c.ok);
  CHECK(c.low[0] == Approx(-300).epsilon(1e-12));
  CHECK(c.high[0] == Approx(300).epsilon(1e-12));
  CHECK(c.low[1] == Approx(-300).epsilon(1e-12));
  CHECK(c.high[1] == Approx(300).epsilon(1e-12));
  // A quarter arc from angle 10° to 100° passes the top of the circle, not its right.
  const Check q = check_program(Language::Gcode, "G0 X9.848078 Y1.736482\nG3 X-1.736482 Y9.848078 I-9.848078 J-1.736482 F600\n", s);
  REQUIRE(q.ok);
  CHECK(q.high[1] == Approx(10).margin(1e-5));  // the radius of the rounded input: 10.0000005
  CHECK(q.high[0] == Approx(9.848078));
  const Check h = check_program(Language::Gcode, "G0 X10 Y20 Z30\nG91 G28 Z0\n", s);
  REQUIRE(h.ok);
  CHECK(h.feed_length == 0);
  CHECK(h.rapid_length == Approx(std::sqrt(1400.0) + 30));
}
