// read_point_or_hit_input(): whole input read, a leading "x,y,z"-style header turned into a
// comment and a capture's `hit` and `scan` columns blanked (line and column numbers stay
// right), then metrology::parse_probed_points or parse_points.
#include "point_input.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "imess/metrology/point_file.hpp"

namespace imess::messcap {

std::string input_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

namespace {

// After a "hit,x,y,z" or "hit,x,y,z,scan" header (messcap's capture .csv): the hit number and
// its comma on every point line become blanks, and with the `scan` column the fifth field and
// its comma too, so x y z are read as the points.
void blank_hit_column(std::string& s, std::size_t from, bool scan_column) {
  for (std::size_t at = from; at < s.size();) {
    std::size_t end = s.find('\n', at);
    if (end == std::string::npos) end = s.size();
    const std::size_t first = s.find_first_not_of(" \t\r", at);
    const std::size_t comma = s.find(',', at);
    if (first < end && s[first] != '#' && comma < end) {
      for (std::size_t i = at; i <= comma; ++i) s[i] = ' ';
      std::size_t fourth = comma;  // the comma before the scan column: the 4th of the line
      for (int k = 0; k < 3 && fourth < end; ++k) fourth = s.find(',', fourth + 1);
      if (scan_column && fourth < end) {
        const std::size_t comment = s.find('#', fourth);
        for (std::size_t i = fourth; i < std::min(end, comment); ++i)
          if (s[i] != '\r') s[i] = ' ';
      }
    }
    at = end + 1;
  }
}

bool ends_with_scan_column(std::string_view header) {
  while (!header.empty() && std::isspace(static_cast<unsigned char>(header.back()))) header.remove_suffix(1);
  return header.size() >= 5 && header.substr(header.size() - 5) == ",scan";
}

bool starts_with_hit_column(std::string_view header) {
  if (header.size() < 4) return false;
  for (std::size_t i = 0; i < 3; ++i)
    if (std::tolower(static_cast<unsigned char>(header[i])) != "hit"[i]) return false;
  return header[3] == ',';
}

std::string read_text(const std::string& path) {
  std::ostringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read '" + path + "': " + std::strerror(errno));
    text << in.rdbuf();
  }
  std::string s = text.str();
  // A header of names ("x,y,z" from messcap's .csv) is a comment, not a point.
  auto first = s.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && std::isalpha(static_cast<unsigned char>(s[first]))) {
    const std::size_t end = s.find('\n', first);
    const std::string_view header =
        std::string_view(s).substr(first, end == std::string::npos ? std::string::npos : end - first);
    if (starts_with_hit_column(header) && end != std::string::npos)
      blank_hit_column(s, end + 1, ends_with_scan_column(header));
    s.insert(first, "#");
  }
  return s;
}

}  // namespace

PointInput read_point_or_hit_input(const std::string& path) {
  const std::string s = read_text(path);
  PointInput in;
  if (metrology::point_file_columns(s, input_name(path)) == 7) {
    in.hits = metrology::parse_probed_points(s, input_name(path));
    in.probed = true;
    for (const auto& h : in.hits) in.points.push_back(h.surface);
  } else {
    in.points = metrology::parse_points(s, input_name(path));
  }
  return in;
}

}  // namespace imess::messcap
