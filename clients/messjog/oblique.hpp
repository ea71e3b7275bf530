// Oblique move ("Schraegfahrt") arithmetic: unit directions and the StartMv speeds along them.
#pragma once
#include <optional>

#include "imess/protocol/commands.hpp"

namespace imess::messjog {

using protocol::Xyz;

// Positions closer than this (mm) count as the same point: the wire carries 3 decimals.
inline constexpr double kSamePointMm = 0.001;

// unit(to - from), or nothing when the points coincide (closer than kSamePointMm).
std::optional<Xyz> unit_direction(const Xyz& from, const Xyz& to);

// Per-axis StartMv speeds: the unit direction scaled by the speed percent.
Xyz jog_speeds(const Xyz& unit, double percent);

double dot(const Xyz& a, const Xyz& b);

}  // namespace imess::messjog
