// --frame NAME --frames FILE: the frame points are written in, from a metrology FrameStore.
#pragma once
#include <string>

#include "imess/metrology/frame.hpp"

namespace imess::messcap {

// The frame NAME of the store FILE. A frame maps its own coordinates to the machine's, so a
// machine point p is written as frame.point_from_parent(p). Throws std::runtime_error naming
// the file and, for a missing name, the names the store holds.
metrology::Frame load_named_frame(const std::string& frames_file, const std::string& name);

}  // namespace imess::messcap
