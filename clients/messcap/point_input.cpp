// read_point_or_hit_input(): whole input read, a leading "x,y,z"-style header turned into a
// comment (line numbers stay right), then metrology::parse_probed_points or parse_points.
#include "point_input.hpp"

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
  if (first != std::string::npos && std::isalpha(static_cast<unsigned char>(s[first]))) s.insert(first, "#");
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
