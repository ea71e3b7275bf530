// The frame service: keeping, using and removing part frames, and announcing the active one.
#include "imess/net/frame_service.hpp"

#include <spdlog/spdlog.h>

namespace imess::net {

std::string FrameService::keep(const std::string& name, const metrology::Frame& frame) { return put(name, frame, true); }

std::string FrameService::store(const std::string& name, const metrology::Frame& frame) {
  std::string save_error = put(name, frame, false);
  if (frames_.active() == name) changed();
  return save_error;
}

std::string FrameService::put(const std::string& name, const metrology::Frame& frame, bool activate) {
  std::string save_error = frames_.put(name, frame, activate);
  if (!save_error.empty())
    log_limited(log_, spdlog::level::err, "frames", "part frame " + name + " kept for this run only: " + save_error);
  return save_error;
}

bool FrameService::remove(const std::string& name, std::string& save_error) {
  if (!frames_.remove(name, save_error)) return false;
  if (!save_error.empty()) log_limited(log_, spdlog::level::err, "frames", "deleting part frame " + name + ": " + save_error);
  return true;
}

void FrameService::changed() {
  const std::string active = frames_.active();
  observers_.each("PartFrameChanged", [&](MotionObserver& o) { o.frame_changed(active); });
}

}  // namespace imess::net
