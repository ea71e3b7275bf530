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
  // Which machine axis each MRM rotary word moves: a letter, or 0 (the default) for the
  // arm's reading (docs/programs.md, "Choices"): A, B, C move the machine's first, second and
  // third rotary axis in the machine's order — the drive kits after X and Y in port order. On
  // the arm (X Y C U V): A = C, the rotation about Z; B = U (U1); C = V (U2). On the default
  // machine: A = C, B = A, C = B.
  char a_axis = 0, b_axis = 0, c_axis = 0;
  std::uint16_t gripper_output = 0;  // port map B: bit 0 of 0x302
  bool check_travel = true;
};

Translation translate_mrm(std::string_view text, const MrmOptions& options = {});

}  // namespace imess::programs
