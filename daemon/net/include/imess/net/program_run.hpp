// Programs in messd: what the configuration says about running them (the folder, G28's pose,
// which outputs M3/M62/the HPGL pen/the MRM gripper switch, the MRM axis letters) and the
// state of the one program loaded or running. The io thread owns both (programs.cpp).
#pragma once
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "imess/core/core_types.hpp"
#include "imess/metrology/frame.hpp"
#include "imess/programs/check.hpp"

namespace imess::net {

struct ProgramConfig {
  std::string folder;                 // absolute; empty: no folder (Load and Programs say so)
  std::vector<double> home;           // G28 pose in machine coordinates (axis order); empty: all 0
  std::vector<double> g30;            // G30 pose likewise; empty: all 0
  bool block_delete = true;           // G-code lines starting with '/' are skipped
  std::string spindle;                // output switched by M3/M4 (on) and M5 (off); empty: none
  std::string mist, flood;            // outputs M7 / M8 switch on and M9 off; empty: none
  bool tool_change_pause = true;      // M6 pauses like M0 (else it only records the tool)
  std::vector<std::string> outputs;   // M62–M65 P0, P1 … switch these outputs
  std::string pen = "z";              // HPGL pen: "z" (a Z move) or an output's name
  double pen_up_z = 5, pen_down_z = 0, pen_feed = 10;  // mm, mm, mm/s
  double origin_x = 0, origin_y = 0;  // machine X Y of plotter point 0,0
  double hpgl_feed = 20;              // mm/s pen-down until VS sets one
  char mrm_a = 0, mrm_b = 0, mrm_c = 0;  // machine axes the MRM words A B C move (0: the rotary axes in order)
  std::string gripper = "gripper";    // output of MRM M03/M04 (when the machine has it)
  std::size_t max_lines = 1000000, max_bytes = 16u << 20;  // a program larger is refused
};

// A program that translated and passed the whole check.
struct LoadedProgram {
  std::string name;
  programs::Language lang = programs::Language::Gcode;
  std::string text;
  programs::Check check;
};

// A program being sent over the connection (Upload … then a line '.').
struct ProgramUpload {
  std::string name;
  std::string text;
  std::size_t lines = 0;
  std::string refused;  // the first limit exceeded ("line 7: longer than 200 characters"); empty: none
};

enum class ProgramState : std::uint8_t { None, Loaded, Running, Paused, Ended };
enum class ProgramOutcome : std::uint8_t { Ok, Failed, Aborted };

struct ProgramRun {
  std::optional<LoadedProgram> loaded;
  ProgramState state = ProgramState::None;
  std::vector<programs::Item> items;  // of the run, translated from where it started
  std::size_t next = 0;               // the next item to plan
  std::size_t next_write = 0;         // the next of loaded->check.offset_writes to store
  bool detached = false;
  bool feeding_done = false;          // End reached or every item planned
  std::optional<std::uint32_t> probe;  // a probe planned whose end has not come: nothing after it is planned
  std::optional<std::size_t> pause_at;  // an M0 reached: planning waits until everything before it is done
  bool tail = false;  // the loop still holds segments of a program that ended: their Done/Failed are not broadcast
  std::size_t done_block = 0;         // the last item whose Done came (1-based)
  std::size_t shown_block = 0;        // the last Block event's item (1-based; 0: none yet)
  std::chrono::nanoseconds shown_at{-1000000000};  // its time on the motion loop's clock
  bool running() const noexcept { return state == ProgramState::Running || state == ProgramState::Paused; }
};

// The translators' set-up for this machine from the configuration: the machine, where it
// stands, G28's pose, the HPGL pen and origin, the MRM axes; outputs by the tags that
// resolve_program_outputs() turns into the machine's output numbers.
programs::Setup program_setup(const ProgramConfig& pc, const core::CoreConfig& core, const planner::Machine& machine,
                              const planner::Pose& start);
// Every SetOutput of `items` gets the machine's output number and its settle time; false
// (with `error` naming the line) when a program switches an output the machine lacks.
// The stored part frames G54 ... G59.3 as the G-code work offsets on the machine's X Y Z (the
// active one, if it is one of them, is active at the start). A turned frame is refused:
// false with `error` in Err 213's form.
class PartFrames;
bool work_offsets_from_frames(const PartFrames& frames, const hal::AxisLayout& layout, programs::GcodeOptions& g,
                              std::string& error);
// The part frame a program's G10 writes: its origin on the machine's X Y Z (other axes' offsets
// last for the program only).
metrology::Frame frame_of_offset_write(const programs::OffsetWrite& w, const hal::AxisLayout& layout);
// False (with `error` in Err 213's form, naming the G10's line) when a write cannot be stored
// as a part frame (an origin beyond kMaxFrameOrigin).
bool offset_writes_storable(const std::vector<programs::OffsetWrite>& writes, const hal::AxisLayout& layout,
                            std::string& error);
bool resolve_program_outputs(std::vector<programs::Item>& items, const ProgramConfig& pc, const core::CoreConfig& core,
                             std::string& error);

// Empty when `name` may name a program in the folder (one printable file name, no path, a
// language's extension), else what is accepted.
std::string program_name_problem(const std::string& name);

const char* state_name(ProgramState s);
const char* outcome_name(ProgramOutcome o);

}  // namespace imess::net
