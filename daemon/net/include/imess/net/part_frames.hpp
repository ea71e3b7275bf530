// The controller's part frames: named frames (part -> machine coordinates) kept in the
// metrology frame store's JSON file, and the one active now. `machine` is the identity and
// always there. Frames G54 ... G59 are the work offsets of G-code programs; I++ DME's PartCsy
// is the active frame. Io thread only; never touched by the motion loop.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "imess/metrology/frame.hpp"
#include "imess/metrology/frame_store.hpp"

namespace imess::net {

inline constexpr std::string_view kMachineFrame = "machine";
inline constexpr double kMaxFrameOrigin = 1e6;  // mm: a kilometre; beyond it a typo, not a part

class PartFrames {
 public:
  // file empty: the frames live for this run only. Otherwise the file is read when it exists
  // (throws metrology::FrameError naming it, the key and what is accepted — also for a name
  // refuse_name refuses or an origin beyond kMaxFrameOrigin) and written on every change.
  explicit PartFrames(std::filesystem::path file = {});

  const std::string& active() const noexcept { return active_; }
  const metrology::Frame& active_frame() const { return *find(active_); }
  // The frame of that name (machine: the identity), nullptr when there is none.
  const metrology::Frame* find(std::string_view name) const;
  std::vector<std::string> names() const;  // machine first, then the stored ones sorted
  const std::filesystem::path& file() const noexcept { return file_; }

  // An empty string when `name` may name a stored frame, else what is accepted.
  static std::string refuse_name(std::string_view name);
  // Stores (replacing one of the same name) and, with `activate`, makes it active. Returns an
  // empty string, or why the file could not be written (the frame is then kept for this run only).
  std::string put(const std::string& name, const metrology::Frame& frame, bool activate = true);
  bool use(std::string_view name);      // false: no such frame
  // false: no such stored frame; the active one removed makes machine active. `save_error`
  // as for put.
  bool remove(std::string_view name, std::string& save_error);

 private:
  std::string save();
  std::filesystem::path file_;
  metrology::FrameStore store_;
  std::string active_{kMachineFrame};
  metrology::Frame identity_;
};

}  // namespace imess::net
