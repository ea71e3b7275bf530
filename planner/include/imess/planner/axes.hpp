// The machine as the planner sees it: up to nine axes (letters X Y Z A B C U V W), each
// linear (mm) or rotary (degrees) with its travel and its own velocity and acceleration.
// Poses are fixed-size arrays, so nothing allocates when they are copied or sampled.
#pragma once
#include <array>
#include <cstdint>

namespace imess::planner {

inline constexpr int kMaxAxes = 9;
inline constexpr std::array<char, kMaxAxes> kAxisLetters{'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'};

// A position (or a velocity) of every axis: index i is machine axis i (Machine::axes[i]);
// entries at and beyond Machine::count are unused and stay 0.
using Pose = std::array<double, kMaxAxes>;

enum class AxisKind : std::uint8_t { Linear, Rotary };

// Which group an axis belongs to for the feed rule (LinuxCNC "Feed Rate"): F is the path
// speed of XYZ if any of them moves, else of UVW, else degrees per second over ABC. A
// rotary axis of another letter (the MRM arm's U and V) counts with the rotary group.
enum class AxisGroup : std::uint8_t { Primary, Secondary, Rotary };  // XYZ, UVW, ABC

struct Axis {
  char letter = 'X';
  AxisKind kind = AxisKind::Linear;
  double travel_min = 0, travel_max = 1000;  // mm or degrees
  double max_velocity = 100;                 // mm/s or deg/s, > 0
  double max_accel = 1000;                   // mm/s² or deg/s², > 0
};

struct Machine {
  int count = 3;  // 1..kMaxAxes
  std::array<Axis, kMaxAxes> axes{};
};

// The group of a letter (X Y Z primary, U V W secondary, A B C rotary); throws
// std::invalid_argument for any other letter.
AxisGroup group_of(char letter);
// The usual kind of a letter: A B C rotary, the others linear.
AxisKind default_kind(char letter);
// A machine with the given letters ("XYZ", "XYZC", "XYCUV"), each axis with the given
// travel and limits (rotary axes in degrees: the same numbers). Throws std::invalid_argument.
Machine make_machine(const char* letters, double travel_min, double travel_max, double max_velocity,
                     double max_accel);
// Throws std::invalid_argument naming the axis and the field when the machine is not
// usable: count outside 1..9, unknown or repeated letter, travel_min > travel_max,
// non-positive or non-finite limits.
void validate(const Machine& m);

}  // namespace imess::planner
