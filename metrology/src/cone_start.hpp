// Internal: the starting cones of the cone fit. Every direction of the search grid (and the
// candidate axes) gives a cone by the closed form for a fixed direction; each takes a few
// Gauss–Newton steps with all six parameters free, the best ones go on until they settle, and
// the best distinct ends go to the solver (docs/metrology.md 2.5).
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "cone_problem.hpp"
#include "fit_common.hpp"

namespace imess::metrology::detail {

// Gauss–Newton steps each start takes before the starts are compared (the screen).
inline constexpr int kConeScreenSteps = 6;
// The best this many screened starts go on for up to kConeRaceSteps more steps (the race): the
// ends of one basin then coincide and count once, and a start whose descent is slow (a long
// curved valley) still reaches the bottom of its basin before the comparison.
inline constexpr std::size_t kConeRaceKeep = 32;
inline constexpr int kConeRaceSteps = 30;
// Starts handed to the solver: the best this many distinct ends of the race.
inline constexpr std::size_t kConeScreenKeep = 8;
// Two ends closer than this (directions and angles in rad, lengths relative to the data size)
// are one start.
inline constexpr double kConeScreenSame = 1e-3;
// A descent stops when the rms residual is below this fraction of the data size (the points
// lie on the cone), when a step lowered the sum of squares by no more than kConeScreenSettled
// of it, or when the damping of rejected steps has grown to kConeScreenStall.
inline constexpr double kConeScreenExact = 1e-12;
inline constexpr double kConeScreenSettled = 1e-12;
inline constexpr double kConeScreenStall = 1e8;

// The starting cones for centred points qs (a subsample of at most kStartSample), best first.
std::vector<ConeProblem::State> cone_starts(const Eigen::Matrix3Xd& qs, const PrincipalAxes<3>& pa);

}  // namespace imess::metrology::detail
