// G-code read as LinuxCNC reads it (issue 25): G28/G30 move only the named axes, '%' starts
// and ends a program, F keeps its speed across G20/G21, LinuxCNC's arc tolerances, modal
// codes IMESS is always in (noted), block delete, blanks inside numbers, G4 with axis words.
#include <catch2/catch.hpp>

#include "imess/programs/check.hpp"
#include "imess/programs/gcode.hpp"
#include "program_text.hpp"

using namespace imess::programs;
using namespace imess::programs::test;

namespace {
std::string notes(const Translation& t) {
  std::string s;
  for (const auto& n : t.notes) s += n.code + "@" + std::to_string(n.line) + "x" + std::to_string(n.count) + " ";
  return s;
}
}  // namespace

TEST_CASE("linuxcnc: G91 G28 Z0 sends Z alone home — no diagonal through the part") {
  GcodeOptions o;
  o.home = {0, 0, 50};
  CHECK(run("G0 X10 Y20 Z5\nG91 G28 Z0\n", o) == Lines{"1 LINE rapid X10 Y20 Z5 F100", "2 HOME X10 Y20 Z50"});
  // Through the via point, then the named axes only.
  CHECK(run("G0 X10 Y20 Z5\nG91 G28 Z10\nG90 G28 X1\n", o) ==
        Lines{"1 LINE rapid X10 Y20 Z5 F100", "2 LINE rapid X10 Y20 Z15 F100", "2 HOME X10 Y20 Z50",
              "3 LINE rapid X1 Y20 Z50 F100", "3 HOME X0 Y20 Z50"});
  // Without axis words: every axis.
  CHECK(run("G0 X10 Y20 Z5\nG28\n", o) == Lines{"1 LINE rapid X10 Y20 Z5 F100", "2 HOME X0 Y0 Z50"});
  // The move home is a rapid.
  const auto t = translate_gcode("G0 X10\nG91 G28 Z0\n", o);
  REQUIRE(t.ok);
  CHECK(t.items.back().rapid);
}

TEST_CASE("linuxcnc: G30 like G28 to its own position (GcodeOptions::g30, default 0)") {
  GcodeOptions o;
  CHECK(run("G0 X10 Y20 Z5\nG91 G30 Z0\nG30\n", o) ==
        Lines{"1 LINE rapid X10 Y20 Z5 F100", "2 HOME X10 Y20 Z0", "3 HOME X0 Y0 Z0"});
  o.g30 = {100, 200, 300};
  CHECK(run("G0 X10 Y20 Z5\nG30 Y7\n", o) ==
        Lines{"1 LINE rapid X10 Y20 Z5 F100", "2 LINE rapid X10 Y7 Z5 F100", "2 HOME X10 Y200 Z5"});
}

TEST_CASE("linuxcnc: after a probe, G91 G28 Z0 retracts the probed Z — an unnamed probed axis is refused") {
  GcodeOptions o;
  o.home = {0, 0, 50};
  CHECK(run("G38.2 Z-10 F60\nG91 G28 Z0\nG1 Z40\n", o) ==
        Lines{"1 PROBE X0 Y0 Z-10 F1 error", "2 HOME X0 Y0 Z50", "3 LINE X0 Y0 Z90 F1"});
  CHECK(err("G38.2 X5 F60\nG91 G28 Z0\n", o) ==
        "line 2:5: position known only at run time: found no X word after the probe on line 1, accepted every axis "
        "the probe moved named in G90 (or G53), or in this G28, before it moves again");
}

TEST_CASE("linuxcnc: '%' first starts the program, the next '%' ends it — elsewhere it is refused") {
  CHECK(run("%\nG0 X1\n%\nG0 X2\nthis is not read\n") == Lines{"2 LINE rapid X1 Y0 Z0 F100"});
  CHECK(run("\n  %  \nG0 X1\n%\n") == Lines{"3 LINE rapid X1 Y0 Z0 F100"});
  CHECK(run("%\nG0 X1\n") == Lines{"2 LINE rapid X1 Y0 Z0 F100"});  // no closing '%': ends at the last line
  CHECK(err("G0 X1\n%\nG0 X2\n") ==
        "line 2:1: bad character: found '%' after the first line of a program that did not begin with '%', accepted '%' "
        "as the first line (it starts the program) and once more to end it");
  CHECK(err("(title)\n%\n").substr(0, 24) == "line 2:1: bad character:");
}

TEST_CASE("linuxcnc: F keeps its speed across G20/G21 — F on a G20 line is read before the change") {
  // 600 mm/min stays 10 mm/s after G20 (it was 254 mm/s when F was re-read in inches).
  CHECK(run("G21 G1 X10 F600\nG20\nX1\nG21\nX20\n") ==
        Lines{"1 LINE X10 Y0 Z0 F10", "3 LINE X25.4 Y0 Z0 F10", "5 LINE X20 Y0 Z0 F10"});
  // An F after G20: inches per minute.
  CHECK(run("G20\nG1 X1 F60\n") == Lines{"2 LINE X25.4 Y0 Z0 F25.4"});
  // On the G20 line itself F comes first (LinuxCNC's order): mm/min, and check says so.
  const auto t = translate_gcode("G20 G1 X1 F60\n");
  CHECK(lines(t, GcodeOptions{}.machine) == Lines{"1 LINE X25.4 Y0 Z0 F1"});
  CHECK(notes(t) == "F with G20@1x1 ");
}

TEST_CASE("linuxcnc: G94 sets F to 0 as LinuxCNC does — G93 and G95 stay refused") {
  CHECK(run("G94 G1 X1 F60\n") == Lines{"1 LINE X1 Y0 Z0 F1"});
  CHECK(err("G1 X1 F60\nG94\nG1 X2\n") ==
        "line 3:1: no feed rate: found G1 with feed F0 (G94 on line 2 set it to 0), accepted an F word > 0 on this or an "
        "earlier line");
  CHECK(err("G93").substr(0, 40) == "line 1:1: unsupported code: found G93, a");
  CHECK(err("G95").substr(0, 40) == "line 1:1: unsupported code: found G95, a");
}

TEST_CASE("linuxcnc: centre-format arcs within LinuxCNC's tolerance run as its spiral — beyond it they are refused") {
  // r = 10: 0.028 mm off is accepted (0.02·√2 mm), 0.029 refused (and > 0.1 %).
  CHECK(translate_gcode("G0 X-10\nG2 X10.028 I10 F60\n").ok);
  CHECK(!translate_gcode("G0 X-10\nG2 X10.029 I10 F60\n").ok);
  // r = 500: 0.1 % (0.5 mm) is accepted, beyond it refused; r = 5000: refused beyond 2.83 mm.
  CHECK(translate_gcode("G0 X-500\nG2 X500.5 I500 F60\n").ok);
  CHECK(!translate_gcode("G0 X-500\nG2 X500.51 I500 F60\n").ok);
  GcodeOptions far;
  far.check_travel = false;
  CHECK(translate_gcode("G0 X-5000\nG2 X5002.8 I5000 F60\n", far).ok);
  CHECK(!translate_gcode("G0 X-5000\nG2 X5002.9 I5000 F60\n", far).ok);
  // Inches: 0.002·√2 in.
  CHECK(translate_gcode("G20\nG0 X-1\nG2 X1.0028 I1 F60\n").ok);
  CHECK(!translate_gcode("G20\nG0 X-1\nG2 X1.0029 I1 F60\n").ok);
  // What the translator accepts, the planner plans (the dry run of messd and messprog).
  Setup s;
  const auto c = check_program(Language::Gcode, "G0 X-10\nG2 X10.028 I10 F600\nG3 X-10 I-10.014 F600\n", s);
  INFO(c.error);
  CHECK(c.ok);
}

TEST_CASE("linuxcnc: R-format arcs may fall 0.00127 mm short of half the chord") {
  CHECK(run("G2 X10.0025 R5 F60") == Lines{"1 ARC cw X10.0025 Y0 Z0 C5.00125,0,0 N0,0,1 P0,1,2 T0 F1"});
  CHECK(!translate_gcode("G2 X10.0026 R5 F60").ok);
  Setup s;
  CHECK(check_program(Language::Gcode, "G2 X10.0025 R5 F60\n", s).ok);
}

TEST_CASE("linuxcnc: modal codes IMESS is always in are accepted and noted, G80 cancels the motion mode") {
  const auto t = translate_gcode("G17 G21 G40 G49 G80 G90 G94 G91.1\nG64 P0.01 Q0.01\nG61\nG61.1\nG0 X1\nM1\nG40\n");
  CHECK(lines(t, GcodeOptions{}.machine) == Lines{"5 LINE rapid X1 Y0 Z0 F100"});
  CHECK(notes(t) == "G94@1x1 G40@1x2 G49@1x1 G91.1@1x1 G80@1x1 G64@2x1 G61@3x1 G61.1@4x1 M1@6x1 ");
  CHECK(t.notes.front().meaning.find("sets F to 0") != std::string::npos);
  CHECK(err("G0 X1\nG80\nX2\n") ==
        "line 3:1: missing word: found axis words without a motion mode (G80 cancelled it), accepted G0 G1 G2 G3 G38.2 "
        "G38.3 before or on this line");
  CHECK(run("G80 G0 X1\n") == Lines{"1 LINE rapid X1 Y0 Z0 F100"});  // as LinuxCNC: the motion code wins
}

TEST_CASE("linuxcnc: block delete '/' skips the line unless the switch is off") {
  const auto t = translate_gcode("G0 X1\n/G0 X5\n  / G0 Y5\nG0 Z1\n");
  CHECK(lines(t, GcodeOptions{}.machine) == Lines{"1 LINE rapid X1 Y0 Z0 F100", "4 LINE rapid X1 Y0 Z1 F100"});
  CHECK(notes(t) == "/@2x2 ");
  GcodeOptions o;
  o.block_delete = false;
  CHECK(run("G0 X1\n/G0 X5\n", o) == Lines{"1 LINE rapid X1 Y0 Z0 F100", "2 LINE rapid X5 Y0 Z0 F100"});
}

TEST_CASE("linuxcnc: blanks inside numbers and words are ignored, columns still name the source") {
  CHECK(run("G0 X 4 0 0 . 5\nG 1 Y - 2 F1 0 0\n") == Lines{"1 LINE rapid X400.5 Y0 Z0 F100", "2 LINE X400.5 Y-2 Z0 F1.666667"});
  CHECK(run("G0 X1 (a comment with  blanks) Y 2\n") == Lines{"1 LINE rapid X1 Y2 Z0 F100"});
  CHECK(err("G0 X 1 Q 7") == "line 1:8: word not allowed here: found Q7, accepted Q only with G64");
}

TEST_CASE("linuxcnc: G4 P1 X5 dwells, then moves in the motion mode") {
  CHECK(run("G1 X1 F60\nG4 P1 X5\n") == Lines{"1 LINE X1 Y0 Z0 F1", "2 DWELL 1", "2 LINE X5 Y0 Z0 F1"});
}

TEST_CASE("linuxcnc: a modal arc line with I/J only is a full circle") {
  CHECK(run("G0 X10\nG2 X10 Y0 I5 F60\nI5\nX10 I-5\n") ==
        Lines{"1 LINE rapid X10 Y0 Z0 F100", "2 ARC cw X10 Y0 Z0 C15,0,0 N0,0,1 P0,1,2 T0 F1",
              "3 ARC cw X10 Y0 Z0 C15,0,0 N0,0,1 P0,1,2 T0 F1", "4 ARC cw X10 Y0 Z0 C5,0,0 N0,0,1 P0,1,2 T0 F1"});
  CHECK(err("G1 X5 F60\nI5\n") == "line 2:1: word not allowed here: found I5, accepted I only with G2/G3");
}

TEST_CASE("linuxcnc: canned cycles, cutter compensation and parameters stay refused with line:column") {
  CHECK(err("G0 X1\nG81 X1 Y1 Z-1 R1 F60\n").substr(0, 41) == "line 2:1: unsupported code: found G81, ac");
  CHECK(err("G0 X1\nG1 G41 D1 X5 F60\n").substr(0, 41) == "line 2:4: unsupported code: found G41, ac");
  CHECK(err("G0 X1 #1=5\n").substr(0, 34) == "line 1:7: bad character: found '#'");
}

TEST_CASE("linuxcnc: G92 makes the position read the axis words, G92.1 clears, G92.2 suspends, G92.3 restores") {
  CHECK(run("G0 X10 Y10 Z10\nG92 X0 Y0\nG0 X1\nG92.2\nG0 X1\nG92.3\nG0 X2\nG92.1 X3\n") ==
        Lines{"1 LINE rapid X10 Y10 Z10 F100", "3 LINE rapid X11 Y10 Z10 F100", "5 LINE rapid X1 Y10 Z10 F100",
              "7 LINE rapid X12 Y10 Z10 F100", "8 LINE rapid X3 Y10 Z10 F100"});
  CHECK(err("G0 X1\nG92\n") == "line 2:1: missing word: found G92 without axis words, accepted G92 with the values the current position gets");
  CHECK(err("G92 G0 X1\n") == "line 1:5: word not allowed here: found G0 with G92, accepted G92 or a motion code on a line: both take the axis words");
  CHECK(err("G38.2 Z-5 F60\nG92 Z0\n").substr(0, 74) == "line 2:5: position known only at run time: found Z0 with G92 after the pro");
}

TEST_CASE("linuxcnc: G10 L2 and L20 set a work offset for the rest of the program, and list it as a write to store") {
  const auto t = translate_gcode("G0 X10 Y10\nG10 L2 P1 X5\nG0 X0\nG10 L20 P1 X1\nG0 X0\nG10 L2 P2 X100\nG55 G0 X1\n");
  CHECK(lines(t, GcodeOptions{}.machine) == Lines{"1 LINE rapid X10 Y10 Z0 F100", "3 LINE rapid X5 Y10 Z0 F100",
                                                  "5 LINE rapid X4 Y10 Z0 F100", "7 LINE rapid X101 Y10 Z0 F100"});
  CHECK(notes(t) == "G10@2x3 ");
  // Each write: before which item, its line, which offset, the whole offset afterwards.
  REQUIRE(t.offset_writes.size() == 3);
  CHECK(t.offset_writes[0].before_item == 1);
  CHECK(t.offset_writes[0].line == 2);
  CHECK(t.offset_writes[0].offset == 0);
  CHECK(t.offset_writes[0].origin[0] == 5);
  CHECK(t.offset_writes[1].before_item == 2);
  CHECK(t.offset_writes[1].offset == 0);
  CHECK(t.offset_writes[1].origin[0] == 4);  // L20: X reads 1 where the machine stands (5)
  CHECK(t.offset_writes[2].before_item == 3);
  CHECK(t.offset_writes[2].line == 6);
  CHECK(t.offset_writes[2].offset == 1);
  CHECK(t.offset_writes[2].origin[0] == 100);
  CHECK(t.offset_writes[2].origin[1] == 0);  // an axis not named keeps its value
  CHECK(err("G10 L1 P1 X1") == "line 1:1: missing word: found G10 L1, accepted G10 L2 or G10 L20");
  CHECK(err("G10 L2 P10 X1") == "line 1:8: value out of range: found P10, accepted P0 ... P9 (P0 the offset in force, P1 ... P9 G54 ... G59.3)");
  CHECK(err("G0 X1 L2") == "line 1:7: word not allowed here: found L2, accepted L only with G10");
}

TEST_CASE("linuxcnc: T selects a tool, M6 stops the spindle and pauses like M0 naming it — or only records it") {
  GcodeOptions o;
  o.spindle_output = 3;
  const auto t = translate_gcode("T3 M6\nG0 X1\nT4\nM6\n", o);
  CHECK(lines(t, o.machine) == Lines{"1 OUT 3=0", "1 PAUSE M6 T3", "2 LINE rapid X1 Y0 Z0 F100", "4 OUT 3=0", "4 PAUSE M6 T4"});
  CHECK(notes(t) == "T@1x2 M6@1x2 ");
  o.tool_change_pause = false;
  o.spindle_output.reset();
  CHECK(run("T3 M6\nG0 X1\n", o) == Lines{"2 LINE rapid X1 Y0 Z0 F100"});
  CHECK(err("T1.5") == "line 1:1: value out of range: found T1.5, accepted T0, T1, T2 ... (a tool number)");
}

TEST_CASE("linuxcnc: M7 M8 M9 switch the configured coolant outputs, and are refused without them") {
  GcodeOptions o;
  o.mist_output = 5;
  o.flood_output = 6;
  CHECK(run("M7\nM8\nM9\n", o) == Lines{"1 OUT 5=1", "2 OUT 6=1", "3 OUT 5=0", "3 OUT 6=0"});
  CHECK(err("M8") == "line 1:1: not configured: found M8, accepted M8 only with a configured flood output");
  CHECK(err("M9") == "line 1:1: not configured: found M9, accepted M9 only with a configured mist or flood output");
  CHECK(err("M7 M8", o).substr(0, 45) == "line 1:4: two words of one modal group: found");
}
