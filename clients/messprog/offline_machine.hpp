// The generic machine messprog check and plot run a program on: the axes the language needs
// (or --axes), every axis with the same travel (±1000 or --travel), 100 mm/s (deg/s) and
// 1000 mm/s² (deg/s²), starting at 0 on every axis. It is not the machine messd drives:
// `messprog run` leaves the check against the real machine to messd.
#pragma once
#include <string>

#include "imess/planner/axes.hpp"
#include "imess/programs/check.hpp"

namespace imess::messprog {

inline constexpr double kOfflineTravel = 1000;        // ± mm (degrees for rotary axes)
inline constexpr double kOfflineMaxVelocity = 100;    // mm/s, deg/s
inline constexpr double kOfflineMaxAccel = 1000;      // mm/s², deg/s²

struct OfflineSpec {
  std::string letters;  // empty: the language's default
  double travel_min = -kOfflineTravel, travel_max = kOfflineTravel;
};

// "XYZ" for G-code and HPGL; "XYCUV" for MRM (the arm: X Y, C about Z, U V its tilt joints).
std::string default_letters(programs::Language lang);

// The machine: letters of X Y Z A B C U V W, each once; A B C rotary, and for MRM the axes
// its A and B words move (U and V when present) rotary too. Throws client::UsageError naming
// --axes or --travel and what is accepted (HPGL needs X and Y).
planner::Machine offline_machine(programs::Language lang, const OfflineSpec& spec);

// The translators' set-up on that machine: MRM A→U, B→V, C→C (A, B when the machine has no
// U, V); HPGL's pen a Z move (up 5, down 0) when the machine has Z, else output 0; start at
// 0 on every axis, or the travel end nearest to 0.
programs::Setup offline_setup(const planner::Machine& machine);

// "axes XYZ, travel -1000..1000, 100 mm/s and 1000 mm/s² per axis (deg for C U V), start 0"
std::string describe_machine(const planner::Machine& machine, const programs::Setup& setup);

}  // namespace imess::messprog
