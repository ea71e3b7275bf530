// read_point_input(): whole input read, a leading "x,y,z"-style header turned into a comment
// (line numbers stay right), then metrology::parse_points.
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

std::vector<Eigen::Vector3d> read_point_input(const std::string& path) {
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
  return metrology::parse_points(s, input_name(path));
}

}  // namespace imess::messcap
