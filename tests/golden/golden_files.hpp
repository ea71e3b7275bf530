// The golden transcripts on disk: tests/golden/*.txt (but CMakeLists.txt), in name order.
#pragma once
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace imess::golden {

inline std::filesystem::path golden_dir() { return std::filesystem::path(IMESS_SOURCE_DIR) / "tests" / "golden"; }

inline std::vector<std::filesystem::path> golden_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& f : std::filesystem::directory_iterator(golden_dir()))
    if (f.path().extension() == ".txt" && f.path().filename() != "CMakeLists.txt") files.push_back(f.path());
  std::sort(files.begin(), files.end());
  return files;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace imess::golden
