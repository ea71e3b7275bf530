// Point file parsers: optional count line, then one point per line — "x y z" (plain) or
// "x y z i j k r" (probed) — blank/tab/comma/semicolon separated, '#' comments.
#include "imess/metrology/point_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <system_error>

namespace imess::metrology {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r'; }

struct Field {
  double value = 0.0;
  std::size_t column = 0;  // 1-based
};

using Fail = std::function<void(std::size_t column, const std::string& why)>;

// Splits a line into numeric fields; a field that is not a finite number fails at its column.
void split_numbers(std::string_view line, std::vector<Field>& out, const Fail& fail) {
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
    if (ec != std::errc() || ptr != field.data() + field.size() || !std::isfinite(v))
      fail(i + 1, "'" + std::string(field) + "' is not a finite number");
    out.push_back({v, i + 1});
    i = j;
  }
}

// Walks the point lines of a file: the optional count line is checked here, every other
// non-empty line goes to `row` (fields, fail), which returns false to stop early (the count
// is then not checked).
void for_each_row(std::string_view text, std::string_view source,
                  const std::function<bool(const std::vector<Field>&, const Fail&)>& row) {
  std::vector<Field> fields;
  long long expected = -1;
  long long rows = 0;
  bool first_data_line = true;
  std::size_t line_no = 0;
  std::size_t pos = 0;
  const Fail fail = [&](std::size_t column, const std::string& why) {
    std::ostringstream os;
    os << source << ":" << line_no << ":" << column << ": " << why;
    throw PointFileError(os.str());
  };
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    split_numbers(line, fields, fail);
    if (!fields.empty()) {
      if (first_data_line && fields.size() == 1) {
        const double n = fields[0].value;
        if (n < 0.0 || n != std::floor(n) || n > 1e15)
          fail(fields[0].column, "the count line must hold a non-negative integer");
        expected = static_cast<long long>(n);
      } else {
        ++rows;
        if (!row(fields, fail)) return;
      }
      first_data_line = false;
    }
    if (end == text.size()) break;
  }
  if (expected >= 0 && rows != expected) {
    std::ostringstream os;
    os << source << ": the count line says " << expected << " points, the file holds " << rows;
    throw PointFileError(os.str());
  }
}

void require_count(const std::vector<Field>& f, std::size_t n, std::string_view layout, const Fail& fail) {
  if (f.size() == n) return;
  std::ostringstream os;
  os << "expected " << n << " numbers (" << layout << "), got " << f.size();
  fail(f.size() > n ? f[n].column : 1, os.str());
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PointFileError(path.string() + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

std::vector<Eigen::Vector3d> parse_points(std::string_view text, std::string_view source) {
  std::vector<Eigen::Vector3d> pts;
  for_each_row(text, source, [&](const std::vector<Field>& f, const Fail& fail) {
    require_count(f, 3, "x y z", fail);
    pts.emplace_back(f[0].value, f[1].value, f[2].value);
    return true;
  });
  return pts;
}

std::vector<Eigen::Vector3d> read_points(const std::filesystem::path& path) {
  return parse_points(read_file(path), path.string());
}

std::vector<ProbedPoint> parse_probed_points(std::string_view text, std::string_view source) {
  std::vector<ProbedPoint> hits;
  for_each_row(text, source, [&](const std::vector<Field>& f, const Fail& fail) {
    require_count(f, 7, "x y z i j k r: surface point, unit approach direction, tip radius", fail);
    ProbedPoint h;
    h.surface = Eigen::Vector3d(f[0].value, f[1].value, f[2].value);
    h.approach = Eigen::Vector3d(f[3].value, f[4].value, f[5].value);
    h.radius = f[6].value;
    if (h.radius < 0.0) fail(f[6].column, "the tip radius must be >= 0");
    const double len = h.approach.norm();
    if (len == 0.0) {
      if (h.radius != 0.0)
        fail(f[3].column, "the approach direction is 0 0 0 but the tip radius is not 0; a hit "
                          "with a radius needs the unit direction it was compensated along");
    } else if (!(std::abs(len - 1.0) <= kApproachLengthTolerance)) {
      std::ostringstream os;
      os << "the approach direction (i j k) must be a unit vector, its length is " << len;
      fail(f[3].column, os.str());
    } else {
      h.approach /= len;
    }
    hits.push_back(h);
    return true;
  });
  return hits;
}

std::vector<ProbedPoint> read_probed_points(const std::filesystem::path& path) {
  return parse_probed_points(read_file(path), path.string());
}

std::size_t point_file_columns(std::string_view text, std::string_view source) {
  std::size_t columns = 0;
  for_each_row(text, source, [&](const std::vector<Field>& f, const Fail&) {
    columns = f.size();
    return false;
  });
  return columns;
}

}  // namespace imess::metrology
