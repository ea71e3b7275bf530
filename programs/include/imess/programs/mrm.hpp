// MRM robot-arm program language (BRIEF §5, 2013 teaching manual) → program items: one word
// per line, all moves incremental, X Y in 0.1 mm, A B C in 0.1°, F mm/min, S °/min,
// M03/M04 gripper on/off, M02 end. See docs/programs.md for the choices made.
#pragma once
#include <cstdint>
#include <string_view>

#include "imess/programs/program.hpp"

namespace imess::programs {

struct MrmOptions {
  // The arm: base X Y, rotation C about Z, tilt joints U1 U2 (here A B, rotary), gripper.
  planner::Machine machine = planner::make_machine("XYCAB", -1000, 1000, 100, 1000);
  Pose start{};
  // Which machine axis letter each MRM rotary word moves. The defaults take the word's own
  // letter (a machine with axes named A, B, C); on the arm use_rotary_order() sets them.
  // 0: the word has no axis.
  char a_axis = 'A', b_axis = 'B', c_axis = 'C';
  std::uint16_t gripper_output = 0;  // port map B: bit 0 of 0x302
  bool check_travel = true;
};

Translation translate_mrm(std::string_view text, const MrmOptions& options = {});

// The arm's reading (docs/programs.md, "Choices"): the words A, B, C move the machine's first,
// second and third rotary axes in the machine's order — the drive kits after X and Y in port
// order. On the arm (X Y C U V): A = C, the rotation about Z; B = U (U1); C = V (U2). A word
// with no rotary axis left is set to 0: using it is refused (axis not on this machine).
void use_rotary_order(MrmOptions& options, const planner::Machine& machine);

}  // namespace imess::programs
