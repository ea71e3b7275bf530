// The chosen design frame (--frame NAME --frames FILE) and the two ways a correction crosses
// between it and an offset's own axes, where the [base, correction] pairs are kept.
#pragma once
#include <string>

#include <Eigen/Core>

#include "imess/metrology/five_axis.hpp"

namespace imess::messoffs {

// The frame NAME of the metrology frame store FILE. A stored frame maps design coordinates to
// machine coordinates (as for messcap --frame): its rotation's columns are the design axes in
// machine coordinates, its translation the design origin in the machine. Throws
// std::runtime_error naming the file and, for a missing name, the names the store holds.
metrology::DesignFrame load_design_frame(const std::string& frames_file, const std::string& name);

// A correction typed in the design frame, as it is kept: design -> machine axes at the
// clamping's orientation (T^T, a direction: no translation) -> the offset's own axes (the
// inverse of Rx(-A)·Ry(-B), i.e. Ry(B)·Rx(A)). Without a frame it is typed in the offset's axes.
Eigen::Vector3d correction_to_offset_axes(const Eigen::Vector3d& typed, const metrology::WorkOffset& offset,
                                          const metrology::DesignFrame* frame);
// The way back: a correction kept in the offset's axes as seen in the design frame.
Eigen::Vector3d correction_to_design(const Eigen::Vector3d& kept, const metrology::WorkOffset& offset,
                                     const metrology::DesignFrame& frame);

}  // namespace imess::messoffs
