// Program items as LinuxCNC's canonical machining calls, printed as `rs274 -g` prints them
// (program coordinates and units, XYZABC, 4 decimals), so anyone can diff IMESS's reading
// of a G-code program against LinuxCNC's (`messprog check --canon`).
#pragma once
#include <string>

#include "imess/programs/program.hpp"

namespace imess::programs {

// One item as one call in `frame`: STRAIGHT_TRAVERSE (G0; G28/G30 and their via point),
// STRAIGHT_FEED, ARC_FEED(first end, second end, first centre, second centre, rotation, axis
// end, A, B, C), STRAIGHT_PROBE, DWELL. Empty for items that are no such call.
std::string canonical(const Item& item, const planner::Machine& machine, const Frame& frame = {});

// The whole translation, one call per line: USE_LENGTH_UNITS first and at each change,
// SELECT_PLANE before an arc in another plane than the last (XY at start), SET_FEED_RATE (program units per minute) before a feed move whose speed changed, the
// motion calls, PROGRAM_STOP for M0, PROGRAM_END for M2/M30. `start` is the machine pose
// the program starts from (to tell a move of rotary axes alone, whose F is deg/min).
std::string canonical_program(const Translation& t, const planner::Machine& machine, const Pose& start = {});

}  // namespace imess::programs
