// Reading and writing the hit numbers of capture files: the `hit` and `scan` columns of .csv,
// the "# hit N [scan S]" comments of .xyz/.asc/.hits.
#include "hit_numbers.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "imess/protocol/numbers.hpp"

namespace imess::messcap {
namespace {

std::string extension(const std::string& path) {
  auto dot = path.rfind('.');
  if (dot == std::string::npos) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool is_csv(const std::string& path) { return extension(path) == ".csv"; }

std::string trimmed(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  const auto first = s.find_first_not_of(" \t");
  return first == std::string::npos ? std::string() : s.substr(first);
}

}  // namespace

bool keeps_hit_numbers(const std::string& path) {
  const std::string ext = extension(path);
  return ext == ".csv" || ext == ".xyz" || ext == ".asc" || ext == ".hits";
}

std::string hit_comment(const PointNumber& number) {
  return " # hit " + std::to_string(number.seq) + (number.scan ? " scan " + std::to_string(*number.scan) : std::string());
}

std::string capture_header(const std::string& path, const std::string& format_header) {
  return is_csv(path) ? "hit,x,y,z,scan\n" : format_header;
}

bool csv_has_scan_column(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    line = trimmed(line);
    if (line.empty() || line[0] == '#') continue;
    return line.size() >= 5 && line.compare(line.size() - 5, 5, ",scan") == 0;
  }
  return false;
}

std::string with_hit_number(const std::string& path, std::string line, const std::optional<PointNumber>& number,
                            bool scan_column) {
  if (is_csv(path)) {
    std::string row = (number ? std::to_string(number->seq) : std::string()) + "," + line;
    if (scan_column)
      row.insert(row.size() - 1, "," + (number && number->scan ? std::to_string(*number->scan) : std::string()));
    return row;
  }
  if (number && keeps_hit_numbers(path)) line.insert(line.size() - 1, hit_comment(*number));
  return line;
}

std::optional<std::uint64_t> last_hit_number(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    if (errno == ENOENT) return std::nullopt;
    throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
  }
  const bool csv = is_csv(path);
  bool header_seen = false;
  std::optional<std::uint64_t> last;
  std::string line;
  while (std::getline(in, line)) {
    if (csv) {
      line = trimmed(line);
      if (line.empty() || line[0] == '#') continue;
      if (!header_seen) {
        header_seen = true;
        if (line.rfind("hit,", 0) != 0)
          throw std::runtime_error(
              "'" + path + "' has no 'hit' column (its header is '" + line +
              "': written by messcap convert or an older messcap), so a capture cannot continue it without losing "
              "the points measured since; capture into a new .csv (its header is 'hit,x,y,z,scan'), or continue a "
              "file that keeps hit numbers: a .csv with the header 'hit,x,y,z,scan' or 'hit,x,y,z', .xyz, .asc or .hits");
        continue;
      }
      if (auto n = protocol::parse_sequence_number(std::string_view(line).substr(0, line.find(','))))
        last = std::max(last.value_or(0), *n);
      continue;
    }
    auto at = line.rfind("# hit ");
    if (at == std::string::npos) continue;
    const std::string_view number = std::string_view(line).substr(at + 6);  // "17" or "17 scan 5"
    if (auto n = protocol::parse_sequence_number(number.substr(0, number.find(' '))))
      last = std::max(last.value_or(0), *n);
  }
  return last;
}

}  // namespace imess::messcap
