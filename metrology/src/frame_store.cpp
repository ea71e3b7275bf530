// JSON persistence of named frames (raw, orthonormalised and inverse 4x4, row-major rows).
#include "imess/metrology/frame_store.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"

namespace imess::metrology {
namespace {

using nlohmann::json;

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
}

[[noreturn]] void fail(std::string_view source, const std::string& key, const std::string& why) {
  std::ostringstream os;
  os << source << ": " << key << ": " << why;
  throw FrameError(os.str());
}

Eigen::Matrix4d read_matrix(const json& obj, std::string_view source, const std::string& key,
                            const char* field) {
  const std::string path = key + "." + field;
  const auto it = obj.find(field);
  if (it == obj.end()) fail(source, path, "missing (expected 4 rows of 4 numbers)");
  const json& rows = *it;
  if (!rows.is_array() || rows.size() != 4) fail(source, path, "expected an array of 4 rows");
  Eigen::Matrix4d m;
  for (std::size_t i = 0; i < 4; ++i) {
    const json& row = rows[i];
    const std::string rkey = path + "[" + std::to_string(i) + "]";
    if (!row.is_array() || row.size() != 4) fail(source, rkey, "expected a row of 4 numbers");
    for (std::size_t j = 0; j < 4; ++j) {
      const json& v = row[j];
      if (!v.is_number()) fail(source, rkey + "[" + std::to_string(j) + "]", "expected a number");
      const double d = v.get<double>();
      if (!std::isfinite(d)) fail(source, rkey + "[" + std::to_string(j) + "]", "expected a finite number");
      m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = d;
    }
  }
  return m;
}

json write_matrix(const Eigen::Matrix4d& m) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < 4; ++i) {
    json row = json::array();
    for (Eigen::Index j = 0; j < 4; ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

std::string refuse_frame_name(std::string_view name) {
  const char* accepted = "a frame name is made of one or more letters, digits, '_', '-' or '.'";
  if (name.empty()) return accepted;
  for (char c : name)
    if (!name_char(c)) return accepted;
  return {};
}

void FrameStore::set(const std::string& name, const Eigen::Matrix4d& raw) {
  if (auto why = refuse_frame_name(name); !why.empty()) throw FrameError("frame '" + name + "': " + why);
  try {
    frames_[name] = NamedFrame{raw, Frame::orthonormalised(raw)};
  } catch (const FrameError& e) {
    throw FrameError("frame '" + name + "': " + e.what());
  }
}

const Frame& FrameStore::get(const std::string& name) const {
  const auto it = frames_.find(name);
  if (it == frames_.end()) {
    std::string held;
    for (const auto& [n, f] : frames_) held += (held.empty() ? "" : ", ") + n;
    throw FrameError("no frame named '" + name + "'; the store holds: " + (held.empty() ? "no frames" : held));
  }
  return it->second.frame;
}

const NamedFrame* FrameStore::find(const std::string& name) const {
  const auto it = frames_.find(name);
  return it == frames_.end() ? nullptr : &it->second;
}

bool FrameStore::erase(const std::string& name) { return frames_.erase(name) > 0; }

std::vector<std::string> FrameStore::names() const {
  std::vector<std::string> out;
  for (const auto& [name, f] : frames_) out.push_back(name);
  return out;
}

FrameStore parse_frame_store(std::string_view json_text, std::string_view source) {
  json doc;
  try {
    doc = jsontext::parse_strict(json_text, source);
  } catch (const jsontext::JsonTextError& e) {
    throw FrameError(e.what());
  }
  if (!doc.is_object()) fail(source, "(document)", "expected a JSON object with a \"frames\" object");
  const auto frames = doc.find("frames");
  if (frames == doc.end() || !frames->is_object())
    fail(source, "frames", "missing or not an object (expected name -> frame)");
  FrameStore store;
  for (const auto& [name, entry] : frames->items()) {
    const std::string key = "frames." + name;
    if (auto why = refuse_frame_name(name); !why.empty()) fail(source, key, why);
    if (!entry.is_object()) fail(source, key, "expected an object with raw, orthonormal, inverse");
    const Eigen::Matrix4d raw = read_matrix(entry, source, key, "raw");
    const Eigen::Matrix4d ortho = read_matrix(entry, source, key, "orthonormal");
    const Eigen::Matrix4d inv = read_matrix(entry, source, key, "inverse");
    Frame frame;
    try {
      frame = Frame::from_matrix(ortho);
    } catch (const FrameError& e) {
      fail(source, key + ".orthonormal", e.what());
    }
    Frame from_raw;
    try {
      from_raw = Frame::orthonormalised(raw);
    } catch (const FrameError& e) {
      fail(source, key + ".raw", e.what());
    }
    const double raw_diff = (from_raw.matrix() - ortho).cwiseAbs().maxCoeff();
    if (!(raw_diff <= kFrameTolerance)) {
      std::ostringstream os;
      os << "does not match the raw matrix orthonormalised (differs by " << raw_diff << ")";
      fail(source, key + ".orthonormal", os.str());
    }
    const double inv_diff = (inv * ortho - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff();
    if (!(inv_diff <= kFrameTolerance)) {
      std::ostringstream os;
      os << "is not the inverse of the orthonormal matrix (inverse * orthonormal - I reaches "
         << inv_diff << ")";
      fail(source, key + ".inverse", os.str());
    }
    store.set(name, raw);
  }
  return store;
}

std::string to_json(const FrameStore& store) {
  json frames = json::object();
  for (const auto& [name, f] : store.entries()) {
    frames[name] = json{{"raw", write_matrix(f.raw)},
                        {"orthonormal", write_matrix(f.frame.matrix())},
                        {"inverse", write_matrix(f.frame.inverse().matrix())}};
  }
  return json{{"frames", frames}}.dump(2) + "\n";
}

FrameStore load_frame_store(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw FrameError(path.string() + ": is a directory; give the path of a frames file (JSON), e.g. " +
                     (path / "frames.json").string());
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FrameError(path.string() + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_frame_store(ss.str(), path.string());
}

void save_frame_store(const std::filesystem::path& path, const FrameStore& store) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw FrameError(tmp.string() + ": cannot open for writing");
    out << to_json(store);
    out.flush();
    if (!out) throw FrameError(tmp.string() + ": write failed");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw FrameError(path.string() + ": cannot replace (" + ec.message() + ")");
}

}  // namespace imess::metrology
