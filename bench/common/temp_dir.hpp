// A fresh directory under $TMPDIR (or /tmp) for a benchmark's files, removed with everything
// in it when the object dies. Shared by bench_net and bench_rt.
#pragma once

#include <string>

namespace imess::bench {

class TempDir {
 public:
  explicit TempDir(const std::string& prefix);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace imess::bench
