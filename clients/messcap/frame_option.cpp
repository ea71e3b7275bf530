// load_named_frame(): FrameStore errors passed on as they are (they name file and key), a
// missing frame named together with the frames that are there; hit_from_parent().
#include "frame_option.hpp"

#include <stdexcept>

#include "imess/metrology/frame_store.hpp"

namespace imess::messcap {

metrology::Frame load_named_frame(const std::string& frames_file, const std::string& name) {
  metrology::FrameStore store;
  try {
    store = metrology::load_frame_store(frames_file);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("--frames: ") + e.what());
  }
  if (const auto* entry = store.find(name)) return entry->frame;
  std::string names;
  for (const auto& n : store.names()) names += (names.empty() ? "" : ", ") + n;
  throw std::runtime_error("--frame: no frame '" + name + "' in '" + frames_file + "'; it holds: " +
                           (names.empty() ? std::string("no frames") : names));
}

metrology::ProbedPoint hit_from_parent(const metrology::Frame& frame, const metrology::ProbedPoint& hit) {
  metrology::ProbedPoint out = hit;
  out.surface = frame.point_from_parent(hit.surface);
  out.approach = frame.direction_from_parent(hit.approach);
  return out;
}

}  // namespace imess::messcap
