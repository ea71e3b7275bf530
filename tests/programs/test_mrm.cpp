// MRM: the manual's example program, units (0.1 mm, 0.1°, per-minute feeds), the axis
// mapping of A B C, and every error with its line:column.
#include <catch2/catch.hpp>

#include "imess/programs/mrm.hpp"
#include "program_text.hpp"

using namespace imess::programs;
using namespace imess::programs::test;

namespace {
Lines mrm(const char* text, const MrmOptions& o = {}) { return lines(translate_mrm(text, o), o.machine); }
std::string mrm_err(const char* text, const MrmOptions& o = {}) { return error_text(translate_mrm(text, o)); }

const char* kManualExample =
    "N1 F1000\nN2 S600\nN3 X5000\nN4 Y3000\nN5 B900\nN6 M03\nN7 A1800\nN8 M04\nN9 B-900\nN10 Y-3000\nN11 X-5000\nN12 M02\n";
}  // namespace

TEST_CASE("mrm: the manual's example program, item by item") {
  // The default machine X Y C A B: the words A, B, C move its rotary axes in order, C (the
  // rotation about Z), A (U1), B (U2).
  CHECK(mrm(kManualExample) ==
        Lines{"3 LINE X500 Y0 C0 A0 B0 F16.666667", "4 LINE X500 Y300 C0 A0 B0 F16.666667",
              "5 LINE X500 Y300 C0 A90 B0 F10", "6 OUT 0=1", "7 LINE X500 Y300 C180 A90 B0 F10", "8 OUT 0=0",
              "9 LINE X500 Y300 C180 A0 B0 F10", "10 LINE X500 Y0 C180 A0 B0 F16.666667",
              "11 LINE X0 Y0 C180 A0 B0 F16.666667", "12 END"});
}

TEST_CASE("mrm: the manual's example returns X, Y and the tilts, gripper off — the A word's rotation ends at +180°") {
  // BRIEF §5 says the program "returns to the start with the gripper off". Read as printed
  // (all moves incremental, A 0.1°), the sum of the X, Y and B moves is zero and the gripper
  // ends off, but N7 A1800 turns A's joint by 180° and nothing turns it back: the half turn
  // given to the held part (see docs/programs.md).
  const MrmOptions o;
  const auto t = translate_mrm(kManualExample, o);
  REQUIRE(t.ok);
  imess::planner::Pose sum{};
  double gripper = -1;
  for (const auto& it : t.items) {
    if (const auto* l = std::get_if<imess::planner::Line>(&it.step)) sum = l->target;
    if (const auto* out = std::get_if<imess::planner::SetOutput>(&it.step)) {
      CHECK(out->output == o.gripper_output);
      gripper = out->value;
    }
  }
  CHECK(gripper == 0);
  CHECK(sum[0] == 0);    // X
  CHECK(sum[1] == 0);    // Y
  CHECK(sum[3] == 0);    // A, U1: the B word
  CHECK(sum[4] == 0);    // B, U2
  CHECK(sum[2] == 180);  // C, the rotation about Z: the A word
  CHECK(std::holds_alternative<End>(t.items.back().step));
}

TEST_CASE("mrm: units, optional N, blank lines, nothing after M02") {
  CHECK(mrm("F600\n\nN7 X-15\nS60\nC3600\nM2\nX5\n") ==
        Lines{"3 LINE X-1.5 Y0 C0 A0 B0 F10", "5 LINE X-1.5 Y0 C0 A0 B360 F1", "6 END"});
}

TEST_CASE("mrm: A B C go to the configured machine axes") {
  MrmOptions o;
  o.machine = imess::planner::make_machine("XYABC", -1000, 1000, 100, 1000);
  o.a_axis = 'C';
  o.c_axis = 'A';
  CHECK(mrm("S600\nA100\nC200\nB300", o) ==
        Lines{"2 LINE X0 Y0 A0 B0 C10 F10", "3 LINE X0 Y0 A20 B0 C10 F10", "4 LINE X0 Y0 A20 B30 C10 F10"});
}

TEST_CASE("mrm: by default A B C move the machine's rotary axes in its order (the arm: C U V)") {
  MrmOptions o;
  o.machine = imess::planner::make_machine("XYCUV", -1000, 1000, 100, 1000);
  o.machine.axes[3].kind = o.machine.axes[4].kind = imess::planner::AxisKind::Rotary;  // the tilt joints
  CHECK(mrm("S600\nA100\nB200\nC300", o) ==
        Lines{"2 LINE X0 Y0 C10 U0 V0 F10", "3 LINE X0 Y0 C10 U20 V0 F10", "4 LINE X0 Y0 C10 U20 V30 F10"});
  // Fewer rotary axes than words: a word left over has no axis and is refused.
  MrmOptions two;
  two.machine = imess::planner::make_machine("XYCU", -1000, 1000, 100, 1000);
  two.machine.axes[3].kind = imess::planner::AxisKind::Rotary;
  CHECK(mrm("S600\nB10", two) == Lines{"2 LINE X0 Y0 C0 U1 F10"});
  CHECK(mrm_err("S600\nC10", two) == "line 2:1: axis not on this machine: found C10 (the machine has no rotary axis for it), accepted words for the machine's axes");
}

TEST_CASE("mrm errors: every kind with line:column") {
  CHECK(mrm_err("N1 F1000 X5") == "line 1:10: more than one word on a line: found 'X' after F1000, accepted one word per line (after an optional N)");
  CHECK(mrm_err("N1 N2") == "line 1:4: more than one word on a line: found a second N, accepted one N, then one word");
  CHECK(mrm_err("X5000") == "line 1:1: no feed rate: found X5000 before any F, accepted an F word (mm/min) before X/Y moves");
  CHECK(mrm_err("F100\nB5") == "line 2:1: no feed rate: found B5 before any S, accepted an S word (degrees/min) before A/B/C moves");
  CHECK(mrm_err("F100\nZ5") == "line 2:1: unsupported word: found Z, accepted words N F S X Y A B C M");
  CHECK(mrm_err("F100\nX5.5") == "line 2:1: bad number: found X5.5, accepted a whole number of 0.1 mm");
  CHECK(mrm_err("S100\nA-0.5") == "line 2:1: bad number: found A-0.5, accepted a whole number of 0.1 degree");
  CHECK(mrm_err("N1.5 X1") == "line 1:1: bad number: found N1.5, accepted N followed by a whole number >= 0");
  CHECK(mrm_err("M05") == "line 1:1: unsupported code: found M5, accepted M02 (end) M03 (gripper on) M04 (gripper off)");
  CHECK(mrm_err("F0") == "line 1:1: value out of range: found F0, accepted F > 0 (mm/min)");
  CHECK(mrm_err("S-5") == "line 1:1: value out of range: found S-5, accepted S > 0 (degrees/min)");
  CHECK(mrm_err("F") == "line 1:1: bad number: found F followed by end of line, accepted a number after F");
  CHECK(mrm_err("#") == "line 1:1: bad character: found '#', accepted one word N F S X Y A B C M, after an optional N");
  CHECK(mrm_err("F100\nX20000") == "line 2:1: out of travel: found X at 2000, accepted X within -1000 ... 1000");
  MrmOptions o;
  o.machine = imess::planner::make_machine("XYAB", -1000, 1000, 100, 1000);
  CHECK(mrm_err("S600\nC10", o) == "line 2:1: axis not on this machine: found C10 (the machine has no rotary axis for it), accepted words for the machine's axes");
  o.c_axis = 'C';
  CHECK(mrm_err("S600\nC10", o) == "line 2:1: axis not on this machine: found C10 (machine axis C), accepted words for the machine's axes");
}
