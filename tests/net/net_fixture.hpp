// Helpers for the end-to-end control tests: a configuration file written for one test, and
// waiting for a client to see a line.
#pragma once
#include <unistd.h>

#include <fstream>
#include <string>

#include "daemon_process.hpp"

namespace imess::test {

// Writes `json` to a file of its own and returns the path (removed when the object dies).
class TempConfig {
 public:
  explicit TempConfig(const std::string& json) {
    static int counter = 0;
    path_ = "/tmp/imess-net-test-" + std::to_string(getpid()) + "-" + std::to_string(++counter) + ".json";
    std::ofstream(path_) << json;
  }
  ~TempConfig() { std::remove(path_.c_str()); }
  TempConfig(const TempConfig&) = delete;
  TempConfig& operator=(const TempConfig&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

inline bool starts_with(const std::optional<std::string>& line, const std::string& prefix) {
  return line && line->rfind(prefix, 0) == 0;
}

// The value after `name` in an "Ok Status ..." line ("" when absent).
inline std::string status_field(const std::string& status, const std::string& name) {
  auto at = status.find(" " + name + " ");
  if (at == std::string::npos) return "";
  auto start = at + name.size() + 2;
  return status.substr(start, status.find(' ', start) - start);
}

}  // namespace imess::test
