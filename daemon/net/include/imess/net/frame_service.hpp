// FrameService: the controller's part frames for every front end — the store (PartFrames)
// and the active frame; a change is announced through the observer fan-out (MESSD's `Frame`
// event, I++ DME's PartCsy). Fitting a frame to hits is metrology's (pure functions).
#pragma once
#include <filesystem>
#include <string>

#include "imess/net/log_limiter.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/part_frames.hpp"

namespace imess::net {

class FrameService {
 public:
  FrameService(Observers& observers, LogLimiter& log) : observers_(observers), log_(log) {}
  // Reads the store (a file that does not load is a start-up error naming it).
  void open(const std::filesystem::path& file) { frames_ = PartFrames(file); }

  const PartFrames& frames() const noexcept { return frames_; }
  const std::string& active() const noexcept { return frames_.active(); }
  const metrology::Frame& active_frame() const { return frames_.active_frame(); }
  // Stores and activates (without announcing); returns why the file was not written.
  std::string keep(const std::string& name, const metrology::Frame& frame);
  // Stores without changing which frame is active; announces when the active one was written
  // (a program's G10). Returns why the file was not written.
  std::string store(const std::string& name, const metrology::Frame& frame);
  bool use(const std::string& name) { return frames_.use(name); }
  bool remove(const std::string& name, std::string& save_error);
  void changed();  // the active frame changed: every observer hears it

 private:
  std::string put(const std::string& name, const metrology::Frame& frame, bool activate);

  Observers& observers_;
  LogLimiter& log_;
  PartFrames frames_;
};

}  // namespace imess::net
