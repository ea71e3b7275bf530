// Parallel-port pin maps: which D-sub pin carries which step/dir output, user output or switch input,
// per-pin inversion, the two shipped maps of the SHD family, and the register bits the
// pins live on (data base+0, status base+1 with BUSY inverted by the port hardware,
// control base+2 with STROBE, AUTOFEED and SELECT-IN inverted).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "imess/hal/types.hpp"

namespace imess::hal {

// The pin maps drive three axes, X Y Z (machine axes 0..2): a parallel port's data register
// has room for three step/dir pairs besides the enable.
inline constexpr int kParportAxes = 3;
// User outputs "out 1".."out 4" (MotionBackend::set_output), on free data or control pins.
inline constexpr int kParportOutputs = 4;

enum class PinSignal : std::uint8_t {
  None,
  Step,      // output, per axis: one pulse per step
  Dir,       // output, per axis: level = direction (active = positive)
  Enable,    // output: drives enabled (active while not stopped)
  EndRef,    // input, per axis: the SHD end/reference switch at the home end (limit + home)
  LimitNeg,  // input, per axis
  LimitPos,  // input, per axis
  Home,      // input, per axis: reference switch alone
  Probe,     // input: touch probe (raw switch; TipReversed handles a normally closed probe)
  Stop,      // input: STOP / "enable = stop": stops at once, a reference run is needed
  Output,    // output, numbered: a user output (axis holds number - 1), level = set_output
};

struct PinAssignment {
  PinSignal signal = PinSignal::None;
  std::int8_t axis = -1;  // 0..2 for per-axis signals; Output: its number - 1 (0..3)
  bool invert = false;    // active when the pin is low
};

inline constexpr int kMaxPin = 17;
struct PinMap {
  std::string name = "custom";
  std::array<PinAssignment, kMaxPin + 1> pins{};  // index = D-sub pin number 1..17
};

// Where a pin lives: register offset from the port base, bit mask, and whether the port
// hardware inverts it (register bit = !pin level).
struct PinLocation {
  int offset = -1;  // 0 data, 1 status, 2 control; -1: not a signal pin (ground, 18..25)
  std::uint8_t mask = 0;
  bool hw_inverted = false;
  bool input = false;
};
PinLocation pin_location(int pin) noexcept;

// "shd-adapter" or "3d-step" (BRIEF §4). Pin 15 (the C axis switch, no C axis here) is the
// probe in both. nullopt for another name.
std::optional<PinMap> named_pin_map(std::string_view name);
// "step X", "dir Y", "endref Z", "limit- X", "limit+ X", "home X", "probe", "stop", "enable",
// "out 1".."out 4", "none"; throws std::invalid_argument with the accepted forms.
PinAssignment parse_pin_signal(std::string_view text);
std::string pin_signal_text(const PinAssignment& a);
// Throws std::invalid_argument naming the pin: step/dir on data pins 2..9, inputs on
// status pins, every axis with exactly one step and one dir, at most one probe and stop,
// user outputs on output pins (data 2-9 or control 1, 14, 16, 17), each number on one pin
// and numbered from 1 without gaps.
void validate_pin_map(const PinMap& map);

// The pin map compiled into register masks for the fast path (integer only).
struct CompiledPins {
  AxisArray<std::uint8_t> step_mask{}, dir_mask{};  // data register bits
  std::uint8_t data_invert = 0;   // data bits whose pin is active-low
  std::uint8_t enable_data_mask = 0, enable_control_mask = 0;
  std::uint8_t control_invert = 0;  // control register bits to flip (hardware + per-pin)
  // Inputs: active = ((status ^ status_xor) & mask) != 0.
  std::uint8_t status_xor = 0;
  AxisArray<std::uint8_t> endref{}, limit_neg{}, limit_pos{}, home{};
  std::uint8_t probe = 0, stop = 0;
  // User outputs: per number - 1 its register bit, in the data or the control register;
  // the inversions are in data_invert / control_invert like the other outputs'.
  std::array<std::uint8_t, kParportOutputs> output_data{}, output_control{};
  int output_count = 0;
};
CompiledPins compile_pins(const PinMap& map);

}  // namespace imess::hal
