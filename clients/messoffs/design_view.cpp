// Design frames from the frame store; corrections as directions between frames.
#include "design_view.hpp"

#include <numbers>
#include <stdexcept>

#include "imess/metrology/frame_store.hpp"

namespace imess::messoffs {
namespace {

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

}  // namespace

metrology::DesignFrame load_design_frame(const std::string& frames_file, const std::string& name) {
  try {
    const metrology::Frame design_to_machine = metrology::load_frame_store(frames_file).get(name);
    return metrology::DesignFrame(design_to_machine.rotation().transpose(), design_to_machine.translation(),
                                  Eigen::Vector3d::Zero());
  } catch (const metrology::FrameError& e) {
    throw std::runtime_error(std::string("--frames '") + frames_file + "', --frame '" + name + "': " + e.what());
  }
}

Eigen::Vector3d correction_to_offset_axes(const Eigen::Vector3d& typed, const metrology::WorkOffset& offset,
                                          const metrology::DesignFrame* frame) {
  if (!frame) return typed;
  const Eigen::Vector3d at_orientation = frame->correction_to_machine(typed);
  return metrology::rotation_y(rad(offset.b_deg)) * (metrology::rotation_x(rad(offset.a_deg)) * at_orientation);
}

Eigen::Vector3d correction_to_design(const Eigen::Vector3d& kept, const metrology::WorkOffset& offset,
                                     const metrology::DesignFrame& frame) {
  return frame.correction_to_design(metrology::rotate_offset(kept, offset.a_deg, offset.b_deg));
}

}  // namespace imess::messoffs
