// Named frames persisted as JSON: per name the raw input 4x4, the orthonormalised 4x4 and its
// inverse, each as 4 rows of 4 numbers (row-major). Loading re-checks all three.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "imess/metrology/frame.hpp"

namespace imess::metrology {

struct NamedFrame {
  Eigen::Matrix4d raw;  // as entered (kept so the operator can see what was typed)
  Frame frame;          // orthonormalised
};

// An empty string when `name` may name a frame (letters, digits, '_', '-' and '.'; a name is
// a word on the wire and may become part of a path), else what is accepted.
std::string refuse_frame_name(std::string_view name);

class FrameStore {
 public:
  // Orthonormalises `raw` (Frame::orthonormalised) and stores it; replaces an existing name.
  // Throws FrameError naming the frame when the name is refused or the matrix is unusable.
  void set(const std::string& name, const Eigen::Matrix4d& raw);
  // Throws FrameError when there is no frame of that name (the message lists the names held).
  const Frame& get(const std::string& name) const;
  const NamedFrame* find(const std::string& name) const;
  bool erase(const std::string& name);
  std::size_t size() const noexcept { return frames_.size(); }
  std::vector<std::string> names() const;
  const std::map<std::string, NamedFrame>& entries() const noexcept { return frames_; }

 private:
  std::map<std::string, NamedFrame> frames_;
};

// JSON layout:
//   { "frames": { "<name>": { "raw": [[4 numbers] x 4], "orthonormal": [[..] x 4],
//                             "inverse": [[..] x 4] }, ... } }
// Parsing throws FrameError "<source>: frames.<name>.<key>...: <what was expected>" when a key is
// missing, a name is refused (refuse_frame_name), a value is not a 4x4 array of finite numbers,
// the orthonormal matrix does not match the raw one orthonormalised, or the inverse does not
// invert it (tolerance kFrameTolerance); the JSON text is read by imess::jsontext (a number
// beyond a double, a duplicate key: named with its key). Loading a directory is refused as such.
FrameStore parse_frame_store(std::string_view json_text, std::string_view source = "<json>");
std::string to_json(const FrameStore& store);  // numbers round-trip exactly
FrameStore load_frame_store(const std::filesystem::path& path);
// Writes a temporary file next to `path` and renames it over `path` (no half-written store).
void save_frame_store(const std::filesystem::path& path, const FrameStore& store);

}  // namespace imess::metrology
