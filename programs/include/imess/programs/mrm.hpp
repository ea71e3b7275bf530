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
  // Which machine axis letter each MRM rotary word moves: on the arm model A = U1 and
  // B = U2 (the two tilt joints), C = the rotation about Z. The defaults need a machine
  // with axes named A, B, C.
  char a_axis = 'A', b_axis = 'B', c_axis = 'C';
  std::uint16_t gripper_output = 0;  // port map B: bit 0 of 0x302
  bool check_travel = true;
};

Translation translate_mrm(std::string_view text, const MrmOptions& options = {});

}  // namespace imess::programs
