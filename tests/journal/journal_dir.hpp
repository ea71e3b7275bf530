// TempDir: a fresh directory under /tmp for one test, removed with everything in it; hit_at:
// the measured point the journal tests write (430 330 z, approached along -Z).
#pragma once
#include <stdlib.h>

#include <filesystem>
#include <string>

#include "imess/protocol/messages.hpp"

namespace imess::test {

class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "imess-journal-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

inline protocol::HitMsg hit_at(double z) { return protocol::HitMsg{0, 0, {430, 330, z}, {0, 0, -1}, 2, 17.25}; }

}  // namespace imess::test
