// G-code errors: every kind, each naming line and column, what was found and what is
// accepted; a refused program yields no items at all.
#include <catch2/catch.hpp>

#include "imess/programs/gcode.hpp"
#include "program_text.hpp"

using namespace imess::programs;
using namespace imess::programs::test;

namespace {
std::string err(const char* text, const GcodeOptions& o = {}) { return error_text(translate_gcode(text, o)); }
constexpr const char* kAllWords = "N G M X Y Z A B C U V W I J K R F P Q S L T";
}  // namespace

TEST_CASE("gcode errors: characters, numbers, words and codes") {
  CHECK(err("G1 X1 #5") == std::string("line 1:7: bad character: found '#', accepted words ") + kAllWords + ", '(comment)', ';comment'");
  CHECK(err("G1 X F10") == "line 1:4: bad number: found X followed by 'F', accepted a decimal number after X");
  CHECK(err("G1 X1e3") == std::string("line 1:6: unsupported word: found E, accepted words ") + kAllWords);
  CHECK(err("G0 X1\nG0 Y1\nG0 H1") == std::string("line 3:4: unsupported word: found H, accepted words ") + kAllWords);
  CHECK(err("G0 X1 /Y1") == std::string("line 1:7: bad character: found '/', accepted words ") + kAllWords + ", '(comment)', ';comment'");
  const std::string g =
      "G0 G1 G2 G3 G4 G10 G17 G18 G19 G20 G21 G28 G30 G38.2 G38.3 G40 G49 G53 G54 G55 G56 G57 G58 G59 G59.1 G59.2 G59.3 G61 G61.1 G64 "
      "G80 G90 G91 G91.1 G92 G92.1 G92.2 G92.3 G94";
  CHECK(err("G81 X1") == "line 1:1: unsupported code: found G81, accepted " + g);
  CHECK(err("G38.4 Z1") == "line 1:1: unsupported code: found G38.4, accepted " + g);
  CHECK(err("G1.5") == "line 1:1: unsupported code: found G1.5, accepted " + g);
  CHECK(err("M48") == "line 1:1: unsupported code: found M48, accepted M0 M1 M2 M3 M4 M5 M6 M7 M8 M9 M30 M62 M63 M64 M65");
  CHECK(err("G0 (abc") == "line 1:4: unterminated comment: found '(' without ')', accepted a comment closed by ')' on the same line");
}

TEST_CASE("gcode errors: modal groups, repeated words, N placement") {
  CHECK(err("G0 G1 X1") == "line 1:4: two words of one modal group: found G1 after G0 at column 1, accepted one word of group motion (G0 G1 G2 G3 G38.2 G38.3) per line");
  CHECK(err("G17 G18") == "line 1:5: two words of one modal group: found G18 after G17 at column 1, accepted one word of group plane (G17 G18 G19) per line");
  CHECK(err("G90 G91") == "line 1:5: two words of one modal group: found G91 after G90 at column 1, accepted one word of group distance (G90 G91) per line");
  CHECK(err("G20 G21") == "line 1:5: two words of one modal group: found G21 after G20 at column 1, accepted one word of group units (G20 G21) per line");
  CHECK(err("G54 G55") == "line 1:5: two words of one modal group: found G55 after G54 at column 1, accepted one word of group work offset (G54-G59.3) per line");
  CHECK(err("G4 P1 G28") == "line 1:7: two words of one modal group: found G28 after G4 at column 1, accepted one word of group non-modal (G4 G10 G28 G30 G53 G92 G92.1 G92.2 G92.3) per line");
  CHECK(err("M0 M2") == "line 1:4: two words of one modal group: found M2 after M0 at column 1, accepted one word of group stop (M0 M1 M2 M30) per line");
  CHECK(err("M3 M5") == "line 1:4: two words of one modal group: found M5 after M3 at column 1, accepted one word of group spindle (M3 M4 M5) per line");
  CHECK(err("M62 P1 M63 P2") == "line 1:8: two words of one modal group: found M63 after M62 at column 1, accepted one word of group output (M62 M63 M64 M65) per line");
  CHECK(err("G1 X1 X2 F1") == "line 1:7: repeated word: found X2 after X1 at column 4, accepted one X word per line");
  CHECK(err("X1 N5") == "line 1:4: word not allowed here: found N5 after other words, accepted N only as the first word of a line");
}

TEST_CASE("gcode errors: axes, missing words, feed, values") {
  CHECK(err("G0 A5") == "line 1:4: axis not on this machine: found A5, accepted axis words of this machine: X Y Z");
  CHECK(err("G4") == "line 1:1: missing word: found G4 without P, accepted G4 P<seconds>");
  CHECK(err("G2 X10 F60") == "line 1:1: missing word: found G2 without centre, accepted I/J or R");
  CHECK(err("X5") == "line 1:1: missing word: found axis words without a motion mode, accepted G0 G1 G2 G3 G38.2 G38.3 before or on this line");
  CHECK(err("G38.2 F10") == "line 1:1: missing word: found G38.2 without axis words, accepted G38.2/G38.3 with the point to probe toward");
  CHECK(err("G1 X1") == "line 1:1: no feed rate: found G1 with feed F0 (none set yet?), accepted an F word > 0 on this or an earlier line");
  CHECK(err("G4 P-1") == "line 1:4: value out of range: found P-1, accepted P >= 0 seconds");
  CHECK(err("G1 X1 F-5") == "line 1:7: value out of range: found F-5, accepted F >= 0 (units per minute)");
  CHECK(err("G0 X2000") == "line 1:4: out of travel: found X at 2000 (machine), accepted X within -1000 ... 1000");
  GcodeOptions o;
  o.digital_output_count = 2;
  CHECK(err("M64 P2", o) == "line 1:5: value out of range: found P2, accepted P0 ... P1");
  CHECK(err("M64", o) == "line 1:1: missing word: found M64 without P, accepted P<output number> with M64");
}

TEST_CASE("gcode errors: arcs") {
  CHECK(err("G2 X10 I3 F60") == "line 1:1: bad arc: found end radius 7 vs start radius 3, accepted an end on the circle (as LinuxCNC: within 0.028284 mm, or 0.1 % of the radius up to 2.828427 mm)");
  CHECK(err("G20\nG2 X1 I0.3 F60") == "line 2:1: bad arc: found end radius 0.7 vs start radius 0.3, accepted an end on the circle (as LinuxCNC: within 0.002828 in, or 0.1 % of the radius up to 0.282843 in)");
  CHECK(err("G2 X10 R4 F60") == "line 1:8: bad arc: found R4 for ends 10 apart, accepted |R| >= half the distance between the ends (less 0.00127 mm, as LinuxCNC)");
  CHECK(err("G2 R4 F60") == "line 1:4: bad arc: found R4 with the end on the start, accepted R arcs with distinct ends (a full circle takes I/J/K)");
  CHECK(err("G2 X10 I5 K1 F60") == "line 1:11: word not allowed here: found K1 in G17, accepted centre offsets I J in G17");
  CHECK(err("G2 X10 I5 R5 F60") == "line 1:11: word not allowed here: found R5 with centre offsets, accepted either R or centre offsets");
  CHECK(err("G2 X10 I5 P0 F60") == "line 1:11: value out of range: found P0, accepted P1 ... P10000 (turns)");
  CHECK(err("G2 X1 I0 J0 F60") == "line 1:1: bad arc: found centre on the start point, accepted a centre away from the start");
  GcodeOptions o;
  o.machine = imess::planner::make_machine("XY", -1000, 1000, 100, 1000);
  CHECK(err("G2 X10 I5 F60", o) == "line 1:1: axis not on this machine: found G2 on a machine with axes X Y, accepted arcs on machines with linear X, Y and Z");
}

TEST_CASE("gcode errors: words that do not fit the line") {
  CHECK(err("G0 X1 I5") == "line 1:7: word not allowed here: found I5, accepted I only with G2/G3");
  CHECK(err("G0 X1 P2") == "line 1:7: word not allowed here: found P2, accepted P only with G4, G10, M62-M65, G2/G3 (turns) or G64");
  CHECK(err("G0 X1 Q2") == "line 1:7: word not allowed here: found Q2, accepted Q only with G64");
  CHECK(err("G28 G1 X1") == "line 1:5: word not allowed here: found G1 with G28, accepted G28 or a motion code on a line: both take the axis words");
  CHECK(err("G91 G53 G0 X1") == "line 1:5: word not allowed here: found G53 in G91, accepted G53 in G90");
  CHECK(err("G53 G2 X1 I1 F1") == "line 1:1: word not allowed here: found G53 with G2, accepted G53 with G0 or G1");
  CHECK(err("M3") == "line 1:1: not configured: found M3, accepted M3/M4/M5 only with a configured spindle output");
  CHECK(err("M62 P0") == "line 1:1: not configured: found M62, accepted M62-M65 only with configured digital outputs");
}

TEST_CASE("gcode errors: the error names the first failing line, after good ones") {
  const auto t = translate_gcode("G0 X1\nG1 X2 F60\nG1 X3 Y\n");
  REQUIRE_FALSE(t.ok);
  CHECK(t.items.empty());
  CHECK(t.error.kind == ErrorKind::BadNumber);
  CHECK(t.error.line == 3);
  CHECK(t.error.column == 7);
  CHECK(t.error.message() == "line 3:7: bad number: found Y followed by end of line, accepted a decimal number after Y");
}
