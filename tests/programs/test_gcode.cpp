// G-code: worked examples compared item by item, modal behaviour, units, offsets, arcs in
// every plane (checked through the planner's own geometry), probe, home, outputs.
#include <catch2/catch.hpp>
#include <cmath>

#include "imess/planner/planner.hpp"
#include "imess/programs/gcode.hpp"
#include "program_text.hpp"

using namespace imess::programs;
using namespace imess::programs::test;
using imess::planner::Machine;
using imess::planner::make_machine;

namespace {
constexpr double kPi = 3.14159265358979323846;

Lines run(const char* text, const GcodeOptions& o = {}) { return lines(translate_gcode(text, o), o.machine); }

// The planner's segment for the only arc of `text`, starting at o.start.
imess::planner::PlannedSegment arc_segment(const char* text, const GcodeOptions& o = {}) {
  const auto t = translate_gcode(text, o);
  INFO(t.error.message());
  REQUIRE(t.ok);
  imess::planner::Planner p(o.machine);
  p.set_position(o.start);
  imess::planner::PlannedSegment seg;
  for (const auto& it : t.items) {
    if (const auto* a = std::get_if<imess::planner::Arc>(&it.step)) {
      const auto r = p.append(*a);
      INFO(describe(r, o.machine));
      REQUIRE(r.ok());
      p.flush();
      REQUIRE(p.take(seg));
      return seg;
    }
  }
  FAIL("no arc in the program");
  return seg;
}

imess::planner::Pose at_fraction(const imess::planner::PlannedSegment& seg, double f) {
  imess::planner::Pose p{}, d{};
  pose_at(seg, f * seg.length, p, d);
  return p;
}
}  // namespace

TEST_CASE("gcode: worked example — modal G1, G91, comments, N numbers, M2 ends") {
  const char* program =
      "%\n"
      "N10 G21 G90 G17 (set-up)\n"
      "N20 G0 X10 Y5\n"
      "N30 G1 Z-1 F600 ; feed in mm/min\n"
      "N40 X20\n"
      "\n"
      "n50 g91 y5\n"
      "N60 G4 P0.5\n"
      "N70 M0\n"
      "N80 M2\n"
      "N90 G0 X0 (after the end: not translated)\n";
  CHECK(run(program) == Lines{"3 LINE rapid X10 Y5 Z0 F100", "4 LINE X10 Y5 Z-1 F10", "5 LINE X20 Y5 Z-1 F10",
                              "7 LINE X20 Y10 Z-1 F10", "8 DWELL 0.5", "9 PAUSE", "10 END"});
  const auto t = translate_gcode(program);
  std::uint32_t id = 0;
  for (const auto& it : t.items)
    std::visit(
        [&](const auto& x) {
          if constexpr (requires { x.id; }) CHECK(x.id == ++id);
        },
        it.step);
  CHECK(id == 5);
}

TEST_CASE("gcode: G0 alone and G1 without axis words do not move — motion mode persists") {
  CHECK(run("G0\nG1 F60\nX1\nG0\nY2\n") == Lines{"3 LINE X1 Y0 Z0 F1", "5 LINE rapid X1 Y2 Z0 F100"});
}

TEST_CASE("gcode: rapid feed from the options, else the fastest axis") {
  GcodeOptions o;
  o.machine.axes[1].max_velocity = 250;
  CHECK(run("G0 X1", o) == Lines{"1 LINE rapid X1 Y0 Z0 F250"});
  o.rapid_feed = 42;
  CHECK(run("G0 X1", o) == Lines{"1 LINE rapid X1 Y0 Z0 F42"});
}

TEST_CASE("gcode: G20 inches scale linear axes, offsets and feeds — rotary axes stay degrees") {
  GcodeOptions o;
  o.machine = make_machine("XYZA", -1000, 1000, 100, 1000);
  CHECK(run("G20\nG1 X1 F10\nG91 Y-0.5\nA90 F600\nG21\nX1 F60\n", o) ==
        Lines{"2 LINE X25.4 Y0 Z0 A0 F4.233333", "3 LINE X25.4 Y-12.7 Z0 A0 F4.233333",
              "4 LINE X25.4 Y-12.7 Z0 A90 F10", "6 LINE X26.4 Y-12.7 Z0 A90 F1"});
  // Arc centre offsets are in the programmed unit too.
  CHECK(run("G20\nG2 X1 I0.5 F1") == Lines{"2 ARC cw X25.4 Y0 Z0 C12.7,0,0 N0,0,1 P0,1,2 T0 F0.423333"});
}

TEST_CASE("gcode: work offsets G54-G59 from the caller's table, G53 in machine coordinates") {
  GcodeOptions o;
  o.work_offsets[0] = {1, 2, 3};
  o.work_offsets[1] = {100, 0, -10};
  o.work_offsets[5] = {0, 50, 0};
  CHECK(run("G0 X0 Y0 Z0\nG55 X1\nG53 G0 X5\nY1\nG59 G0 Y0\nG91 X1\nG90 G54 X0\n", o) ==
        Lines{"1 LINE rapid X1 Y2 Z3 F100", "2 LINE rapid X101 Y2 Z3 F100", "3 LINE rapid X5 Y2 Z3 F100",
              "4 LINE rapid X5 Y1 Z3 F100", "5 LINE rapid X5 Y50 Z3 F100", "6 LINE rapid X6 Y50 Z3 F100",
              "7 LINE rapid X1 Y50 Z3 F100"});
  o.work_offset = 1;  // G55 active at start
  CHECK(run("G0 X0", o) == Lines{"1 LINE rapid X100 Y0 Z0 F100"});
}

TEST_CASE("gcode: G59.1 G59.2 G59.3 are the 7th to 9th work offsets, G10 P7 to P9 set them, P10 is refused") {
  GcodeOptions o;
  o.work_offsets[6] = {7, 0, 0};
  o.work_offsets[7] = {0, 8, 0};
  o.work_offsets[8] = {0, 0, 9};
  CHECK(run("G59.1 G0 X0 Y0 Z0\nG59.2 X0 Y0 Z0\nG59.3 X0 Y0 Z0\nG10 L2 P7 X-1\nG59.1 X0 Y0 Z0\n", o) ==
        Lines{"1 LINE rapid X7 Y0 Z0 F100", "2 LINE rapid X0 Y8 Z0 F100", "3 LINE rapid X0 Y0 Z9 F100",
              "5 LINE rapid X-1 Y0 Z0 F100"});
  o.work_offset = 8;  // G59.3 active at start
  CHECK(run("G0 Z0", o) == Lines{"1 LINE rapid X0 Y0 Z9 F100"});
  const auto t = translate_gcode("G10 L2 P10 X1\n");
  REQUIRE_FALSE(t.ok);
  CHECK_THAT(t.error.message(), Catch::Contains("P0 ... P9 (P0 the offset in force, P1 ... P9 G54 ... G59.3)"));
  const auto g594 = translate_gcode("G59.4 X1\n");
  REQUIRE_FALSE(g594.ok);
  CHECK_THAT(g594.error.message(), Catch::Contains("G59.4"));
}

TEST_CASE("gcode: start pose is where incremental moves begin and unnamed axes stay") {
  GcodeOptions o;
  o.start = {5, 6, 7};
  CHECK(run("G91 G0 X1\nG90 Y0", o) == Lines{"1 LINE rapid X6 Y6 Z7 F100", "2 LINE rapid X6 Y0 Z7 F100"});
}

TEST_CASE("gcode: arcs by centre I J and by radius R, both senses, short and long") {
  CHECK(run("G2 X10 Y0 I5 J0 F60") == Lines{"1 ARC cw X10 Y0 Z0 C5,0,0 N0,0,1 P0,1,2 T0 F1"});
  CHECK(run("G3 X10 Y10 R10 F60") == Lines{"1 ARC ccw X10 Y10 Z0 C0,10,0 N0,0,1 P0,1,2 T0 F1"});
  CHECK(run("G3 X10 Y10 R-10 F60") == Lines{"1 ARC ccw X10 Y10 Z0 C10,0,0 N0,0,1 P0,1,2 T0 F1"});
  CHECK(run("G2 X10 Y10 R10 F60") == Lines{"1 ARC cw X10 Y10 Z0 C10,0,0 N0,0,1 P0,1,2 T0 F1"});
  CHECK(run("G2 X10 Y10 R-10 F60") == Lines{"1 ARC cw X10 Y10 Z0 C0,10,0 N0,0,1 P0,1,2 T0 F1"});
  // Lengths through the planner: quarter (short) and three quarters (long).
  CHECK(arc_segment("G3 X10 Y10 R10 F60").length == Approx(kPi * 10 / 2));
  CHECK(arc_segment("G3 X10 Y10 R-10 F60").length == Approx(3 * kPi * 10 / 2));
  CHECK(arc_segment("G2 X10 Y10 R10 F60").length == Approx(kPi * 10 / 2));
  // The G2 quarter from the origin around (10, 0) passes above the chord (y > x side).
  const auto mid = at_fraction(arc_segment("G2 X10 Y10 R10 F60"), 0.5);
  CHECK(mid[0] == Approx(10 - 10 / std::sqrt(2.0)));
  CHECK(mid[1] == Approx(10 / std::sqrt(2.0)));
}

TEST_CASE("gcode: full circle by I J (end on the start), extra turns by P, helix") {
  CHECK(run("G2 I5 F60") == Lines{"1 ARC cw X0 Y0 Z0 C5,0,0 N0,0,1 P0,1,2 T0 F1"});
  CHECK(arc_segment("G2 I5 F60").length == Approx(2 * kPi * 5));
  CHECK(run("G17 G3 X0 Y0 Z-3 I5 P2 F60") == Lines{"1 ARC ccw X0 Y0 Z-3 C5,0,0 N0,0,1 P0,1,2 T1 F1"});
  const auto helix = arc_segment("G17 G3 X0 Y0 Z-3 I5 P2 F60");
  CHECK(helix.length == Approx(std::hypot(4 * kPi * 5, 3)));
  CHECK(at_fraction(helix, 0.5)[2] == Approx(-1.5));
  // A quarter helix: Z moves with the angle.
  CHECK(at_fraction(arc_segment("G3 X5 Y5 Z2 J5 F60"), 0.5)[2] == Approx(1));
}

TEST_CASE("gcode: G18 (ZX, I K, normal Y) and G19 (YZ, J K, normal X) planes") {
  CHECK(run("G18 G2 X10 I5 K0 F60") == Lines{"1 ARC cw X10 Y0 Z0 C5,0,0 N0,1,0 P0,1,2 T0 F1"});
  // Clockwise seen from +Y: from X0 round (5, 0) the tool passes Z = -5.
  const auto g18 = at_fraction(arc_segment("G18 G2 X10 I5 F60"), 0.5);
  CHECK(g18[0] == Approx(5));
  CHECK(g18[2] == Approx(-5));
  CHECK(run("G19 G3 Y10 J5 F60") == Lines{"1 ARC ccw X0 Y10 Z0 C0,5,0 N1,0,0 P0,1,2 T0 F1"});
  // Counter-clockwise seen from +X: from Y0 round (5, 0) the tool passes Z = -5.
  const auto g19 = at_fraction(arc_segment("G19 G3 Y10 J5 F60"), 0.5);
  CHECK(g19[1] == Approx(5));
  CHECK(g19[2] == Approx(-5));
  // R form in G18 and a helix along Y.
  CHECK(arc_segment("G18 G3 Z10 X10 R10 Y4 F60").length == Approx(std::hypot(kPi * 10 / 2, 4)));
}

TEST_CASE("gcode: G38.2 / G38.3 probes — probed axes must be named in G90 before moving") {
  CHECK(run("G38.2 Z-10 F60\nG38.3 X5 Z-10 F120\nG0 Z5 X0\nG91 G1 Z1\n") ==
        Lines{"1 PROBE X0 Y0 Z-10 F1 error", "2 PROBE X5 Y0 Z-10 F2 silent", "3 LINE rapid X0 Y0 Z5 F100",
              "4 LINE X0 Y0 Z6 F2"});
  CHECK(error_text(translate_gcode("G38.2 Z-10 F60\nG0 X1")) ==
        "line 2:1: position known only at run time: found no Z word after the probe on line 1, accepted every axis "
        "the probe moved named in G90 (or G53) before it moves again");
}

TEST_CASE("gcode: G28 goes home, through the via point when axis words are given") {
  GcodeOptions o;
  o.home = {0, 0, 50};
  CHECK(run("G0 X10\nG28\nG28 Z60\n", o) == Lines{"1 LINE rapid X10 Y0 Z0 F100", "2 HOME X0 Y0 Z50",
                                                  "3 LINE rapid X0 Y0 Z60 F100", "3 HOME X0 Y0 Z50"});
  // After G28 a probed axis is known again.
  CHECK(run("G38.2 Z-5 F60\nG28\nG91 G1 Z1\n", o) ==
        Lines{"1 PROBE X0 Y0 Z-5 F1 error", "2 HOME X0 Y0 Z50", "3 LINE X0 Y0 Z51 F1"});
}

TEST_CASE("gcode: spindle M3 M4 M5 and digital outputs M62-M65 on configured outputs") {
  GcodeOptions o;
  o.spindle_output = 3;
  o.spindle_ccw_output = 4;
  o.digital_output_base = 10;
  o.digital_output_count = 4;
  CHECK(run("M3\nS1200 M4\nM5\nM62 P0\nM63 P1\nM64 P2\nM65 P3\n", o) ==
        Lines{"1 OUT 4=0", "1 OUT 3=1", "2 OUT 4=1", "2 OUT 3=1200", "3 OUT 3=0", "4 OUT 10=1", "5 OUT 11=0",
              "6 OUT 12=1", "7 OUT 13=0"});
  // Order of execution on one line: outputs and dwell before motion, stop last.
  CHECK(run("G1 X1 F60 M62 P1 M2", o) == Lines{"1 OUT 11=1", "1 LINE X1 Y0 Z0 F1", "1 END"});
  o.spindle_ccw_output.reset();
  CHECK(run("M4", o) == Lines{"1 OUT 3=1"});
}

TEST_CASE("gcode: M30 ends like M2 — nothing after the end is read, not even errors") {
  CHECK(run("G0 X1\nM30\nthis is not g-code") == Lines{"1 LINE rapid X1 Y0 Z0 F100", "2 END"});
}

TEST_CASE("gcode: words are case-insensitive, blanks between letter and number, CRLF lines") {
  CHECK(run("g1 x 1 y-2.5 f 60\r\nG01 X+.5\r\n") == Lines{"1 LINE X1 Y-2.5 Z0 F1", "2 LINE X0.5 Y-2.5 Z0 F1"});
}

TEST_CASE("gcode: axis words map to the machine's axes, any of X Y Z A B C U V W") {
  GcodeOptions o;
  o.machine = make_machine("XYZBCUVW", -1000, 1000, 100, 1000);
  CHECK(run("G0 X1 Y2 Z3 B4 C5 U6 V7 W8", o) == Lines{"1 LINE rapid X1 Y2 Z3 B4 C5 U6 V7 W8 F100"});
  o.machine = make_machine("XY", -1000, 1000, 100, 1000);
  CHECK(run("G1 X1 Y1 F60", o) == Lines{"1 LINE X1 Y1 F1"});
}

TEST_CASE("gcode: the example in docs/programs.md") {
  CHECK(run("G21 G90 G17\nG0 X10 Y5\nG1 Z-1 F600\nG2 X20 Y5 I5\nG4 P0.5\nM2\n") ==
        Lines{"2 LINE rapid X10 Y5 Z0 F100", "3 LINE X10 Y5 Z-1 F10", "4 ARC cw X20 Y5 Z-1 C15,5,-1 N0,0,1 P0,1,2 T0 F10",
              "5 DWELL 0.5", "6 END"});
}
