// The runtime parameter registry behind Get and Set (and the configuration's keys for the
// same values): one entry per parameter — wire name, unit, range, default, read-only, help,
// and where its value lives. A motion-loop parameter is one row of the core's table
// (imess/core/core_params.hpp); any other, one entry in params.cpp (+ its home).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "imess/core/core_types.hpp"

namespace imess::net {

class MotionGateway;

// Where a parameter's value lives.
enum class ParamHome : std::uint8_t {
  Core,        // core::CoreParams, set through the motion loop's parameter lane (core_id)
  ReportHz,    // the io thread's CurrCor rate
  LoopPeriod,  // the motion loop's period, us (fixed at start)
  AxisCount,   // axes the core drives
  Backend,     // the backend type (a word)
  ProbeOffset, // the io thread's probe offset, component `axis` (added to every measured point)
};

struct ParamSpec {
  std::string_view name;           // wire name, matched case-insensitively
  std::string_view unit;           // ASCII, as in error texts ("mm/s2")
  double min = 0, max = 0;         // accepted by Set and by the configuration key
  double initial = 0;              // the default (numbers)
  bool read_only = false;          // Set answers Err 301
  bool text = false;               // the value is a word, not a number
  int decimals = 3;                // Get prints this many
  ParamHome home = ParamHome::Core;
  core::ParamId core_id = core::ParamId::TipRadius;  // home == Core
  int axis = 0;                    // home == ProbeOffset: 0 x, 1 y, 2 z
  std::string_view config;         // the configuration key setting it at start ("motion.tip_radius"); empty: none
  std::string_view help;           // one line
};

inline constexpr double kUnbounded = core::kUnbounded;  // a max this large reads "any" in messages and docs

std::span<const ParamSpec> param_table();
const ParamSpec* find_param(std::string_view name);  // case-insensitive

// Parses a Set value for spec; on failure returns a message saying what is accepted.
std::optional<double> parse_param_value(const ParamSpec& spec, std::string_view text, std::string& error);

// The places the values live, as the io thread sees them for one Get or Set.
struct ParamPlaces {
  MotionGateway& motion;  // core parameters: read from and set through it
  double& report_hz;
  double period_us;
  std::string_view backend;
  std::array<double, 3>& probe_offset;
};

// The value as Get prints it ("2.000", "1000", "sim-servo-card").
std::string param_text(const ParamSpec& spec, const ParamPlaces& at);
// Stores a checked value (spec not read-only); core parameters go through the parameter lane.
void store_param(const ParamSpec& spec, ParamPlaces& at, double value);

}  // namespace imess::net
