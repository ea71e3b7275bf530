// Part frames: the frame store on the controller's disk and the active frame.
#include "imess/net/part_frames.hpp"

#include <system_error>

namespace imess::net {

PartFrames::PartFrames(std::filesystem::path file) : file_(std::move(file)) {
  std::error_code ec;
  if (file_.empty() || !std::filesystem::exists(file_, ec)) return;
  store_ = metrology::load_frame_store(file_);
  // The rules SetFrame keeps, for a file written by hand or by an older messd.
  for (const auto& [name, f] : store_.entries()) {
    const std::string where = file_.string() + ": frames." + name + ": ";
    if (auto why = refuse_name(name); !why.empty()) throw metrology::FrameError(where + "accepted " + why);
    if (!(f.frame.translation().cwiseAbs().maxCoeff() <= kMaxFrameOrigin))
      throw metrology::FrameError(where + "the origin's coordinates go from -1000000 to 1000000 mm");
  }
}

const metrology::Frame* PartFrames::find(std::string_view name) const {
  if (name == kMachineFrame) return &identity_;
  const auto* f = store_.find(std::string(name));
  return f ? &f->frame : nullptr;
}

std::vector<std::string> PartFrames::names() const {
  std::vector<std::string> out{std::string(kMachineFrame)};
  for (auto& n : store_.names()) out.push_back(n);
  return out;
}

std::string PartFrames::refuse_name(std::string_view name) {
  const char* accepted = "a frame name of 1 to 24 letters, digits, '_', '-' or '.', other than 'machine'";
  if (name.empty() || name.size() > 24 || name == kMachineFrame) return accepted;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    if (!ok) return accepted;
  }
  return {};
}

std::string PartFrames::put(const std::string& name, const metrology::Frame& frame, bool activate) {
  store_.set(name, frame.matrix());
  if (activate) active_ = name;
  return save();
}

bool PartFrames::use(std::string_view name) {
  if (!find(name)) return false;
  active_ = std::string(name);
  return true;
}

bool PartFrames::remove(std::string_view name, std::string& save_error) {
  if (!store_.erase(std::string(name))) return false;
  if (active_ == name) active_ = std::string(kMachineFrame);
  save_error = save();
  return true;
}

std::string PartFrames::save() {
  if (file_.empty()) return {};
  try {
    metrology::save_frame_store(file_, store_);
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

}  // namespace imess::net
