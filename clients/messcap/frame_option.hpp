// --frame NAME --frames FILE: the frame points are written in, from a metrology FrameStore, and
// how a hit is carried into it.
#pragma once
#include <string>

#include "imess/metrology/frame.hpp"
#include "imess/metrology/point_file.hpp"

namespace imess::messcap {

// The frame NAME of the store FILE. A frame maps its own coordinates to the machine's, so a
// machine point p is written as frame.point_from_parent(p). Throws std::runtime_error naming
// the file and, for a missing name, the names the store holds.
metrology::Frame load_named_frame(const std::string& frames_file, const std::string& name);

// A machine hit in the frame: the surface point by the full map, the approach by the rotation
// only (a direction; a forced point's 0 0 0 stays 0 0 0); the tip radius as it is.
metrology::ProbedPoint hit_from_parent(const metrology::Frame& frame, const metrology::ProbedPoint& hit);

}  // namespace imess::messcap
