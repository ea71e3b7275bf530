// Reading and writing the "# hit N" comments of .xyz/.asc/.hits capture files.
#include "hit_numbers.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "imess/protocol/numbers.hpp"

namespace imess::messcap {

bool keeps_hit_numbers(const std::string& path) {
  auto dot = path.rfind('.');
  if (dot == std::string::npos) return false;
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".xyz" || ext == ".asc" || ext == ".hits";
}

std::string hit_comment(std::uint64_t seq) { return " # hit " + std::to_string(seq); }

std::optional<std::uint64_t> last_hit_number(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    if (errno == ENOENT) return std::nullopt;
    throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
  }
  std::optional<std::uint64_t> last;
  std::string line;
  while (std::getline(in, line)) {
    auto at = line.rfind("# hit ");
    if (at == std::string::npos) continue;
    if (auto n = protocol::parse_sequence_number(std::string_view(line).substr(at + 6)))
      last = std::max(last.value_or(0), *n);
  }
  return last;
}

}  // namespace imess::messcap
