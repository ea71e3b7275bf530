// The two measurements of bench_rt. Each adds its figures to the report; false when it could
// not run at all (messd did not start), with the reason on stderr.
#pragma once
#include "options.hpp"
#include "report.hpp"

namespace imess::bench {

bool run_loop(const Options& options, Report& report);  // loop_bench.cpp
bool run_base(const Options& options, Report& report);  // base_bench.cpp

// A temporary directory, removed with everything in it when the object dies.
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
