// G-code (DIN 66025 / RS274NGC subset, LinuxCNC's modal rules) → program items.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "imess/programs/program.hpp"

namespace imess::programs {

// The work offsets: G54 ... G59, G59.1, G59.2, G59.3 (as LinuxCNC: nine).
inline constexpr int kWorkOffsets = 9;
// Their names, by index (0 = G54 ... 8 = G59.3): the part frames messd keeps them as.
inline constexpr std::array<std::string_view, kWorkOffsets> kWorkOffsetNames = {"G54", "G55", "G56", "G57", "G58",
                                                                              "G59", "G59.1", "G59.2", "G59.3"};

struct GcodeOptions {
  planner::Machine machine = planner::make_machine("XYZ", -1000, 1000, 100, 1000);
  Pose start{};                        // machine pose when the program starts
  std::array<Pose, kWorkOffsets> work_offsets{};  // G54 … G59.3: machine = program + offset (mm, deg)
  int work_offset = 0;                 // active at start: 0 = G54 … 8 = G59.3
  Pose home{};                         // where G28 goes (machine pose)
  Pose g30{};                          // where G30 goes (machine pose)
  bool block_delete = true;            // lines starting with '/' are skipped (the switch on)
  double rapid_feed = 0;               // traverse feed, planner units; 0: the fastest axis' max_velocity
  bool check_travel = true;            // refuse end points outside the axes' travel
  // Outputs (planner SetOutput numbers). M3/M4 set spindle_output to S (1 when no S was
  // given), M5 sets it 0; M3/M4 set spindle_ccw_output 0/1 when configured.
  std::optional<std::uint16_t> spindle_output, spindle_ccw_output;
  // M7 sets mist_output 1, M8 flood_output 1, M9 both (those configured) 0.
  std::optional<std::uint16_t> mist_output, flood_output;
  // M6 (tool change; on a CMM the stylus): stop the spindle when configured, then pause like
  // M0 for the operator ("M6 T<n>"); false: M6 only records the tool.
  bool tool_change_pause = true;
  // M62/M64 P<n> set output digital_output_base + n to 1, M63/M65 to 0; n < digital_output_count.
  std::uint16_t digital_output_base = 0;
  std::uint16_t digital_output_count = 0;
};

Translation translate_gcode(std::string_view text, const GcodeOptions& options = {});

}  // namespace imess::programs
