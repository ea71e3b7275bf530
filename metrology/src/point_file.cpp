// Point file parser: optional count line, then "x y z" per line (blank/tab/comma separated).
#include "imess/metrology/point_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace imess::metrology {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r'; }

// Splits a line into numeric fields; false (with `bad` set) when a field is not a number.
bool split_numbers(std::string_view line, std::vector<double>& out, std::string& bad) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_separator(line[i])) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && !is_separator(line[j])) ++j;
    const std::string_view field = line.substr(i, j - i);
    const char* first = field.data();
    if (!field.empty() && field.front() == '+') ++first;  // from_chars rejects a leading '+'
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(first, field.data() + field.size(), v);
    if (ec != std::errc() || ptr != field.data() + field.size() || !std::isfinite(v)) {
      bad = std::string(field);
      return false;
    }
    out.push_back(v);
    i = j;
  }
  return true;
}

}  // namespace

std::vector<Eigen::Vector3d> parse_points(std::string_view text, std::string_view source) {
  std::vector<Eigen::Vector3d> pts;
  std::vector<double> fields;
  std::string bad;
  long long expected = -1;
  bool first_data_line = true;
  std::size_t line_no = 0;
  std::size_t pos = 0;
  auto fail = [&](const std::string& why) {
    std::ostringstream os;
    os << source << ":" << line_no << ": " << why;
    throw PointFileError(os.str());
  };
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    if (!split_numbers(line, fields, bad)) fail("'" + bad + "' is not a finite number");
    if (fields.empty()) {
      if (end == text.size()) break;
      continue;
    }
    if (first_data_line && fields.size() == 1) {
      const double n = fields[0];
      if (n < 0.0 || n != std::floor(n)) fail("the count line must hold a non-negative integer");
      expected = static_cast<long long>(n);
      first_data_line = false;
      continue;
    }
    first_data_line = false;
    if (fields.size() != 3) {
      std::ostringstream os;
      os << "expected 3 coordinates (x y z), got " << fields.size();
      fail(os.str());
    }
    pts.emplace_back(fields[0], fields[1], fields[2]);
    if (end == text.size()) break;
  }
  if (expected >= 0 && static_cast<long long>(pts.size()) != expected) {
    std::ostringstream os;
    os << source << ": the count line says " << expected << " points, the file holds " << pts.size();
    throw PointFileError(os.str());
  }
  return pts;
}

std::vector<Eigen::Vector3d> read_points(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PointFileError(path.string() + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_points(ss.str(), path.string());
}

}  // namespace imess::metrology
