// HPGL (HP-GL/1 subset: IN SP PU PD PA PR VS) → program items for a pen plotter or a mill
// drawing with a tool: plotter units 40 per mm, the pen a Z move or a digital output.
#pragma once
#include <cstdint>
#include <string_view>

#include "imess/programs/program.hpp"

namespace imess::programs {

struct HpglOptions {
  planner::Machine machine = planner::make_machine("XYZ", -1000, 1000, 100, 1000);
  Pose start{};                 // machine pose when the program starts
  double origin_x = 0, origin_y = 0;  // machine X, Y (mm) of plotter point 0,0
  double units_per_mm = 40;     // plotter units per mm
  double feed = 20;             // mm/s for pen-down moves until VS sets one
  double rapid_feed = 0;        // mm/s for pen-up moves; 0: the fastest axis' max_velocity
  enum class Pen : std::uint8_t { ZMove, Output } pen = Pen::ZMove;
  double pen_up_z = 5, pen_down_z = 0;  // Pen::ZMove: machine Z (mm)
  double pen_feed = 10;                 // Pen::ZMove: mm/s lowering the pen (raising is rapid)
  std::uint16_t pen_output = 0;         // Pen::Output: the output set 1 for down, 0 for up
  bool check_travel = true;
};

Translation translate_hpgl(std::string_view text, const HpglOptions& options = {});

}  // namespace imess::programs
