// Reader for plain point files (the NIST .ds layout and simple XYZ/CSV clouds): the only I/O
// helper of the metrology library apart from the frame store.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace imess::metrology {

// Thrown with "<source>:<line>: <what is wrong, what was expected>".
class PointFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Layout: an optional first line holding only the point count N; then one point per line,
// three numbers separated by blanks, tabs, commas or semicolons. Blank lines and text after
// '#' are ignored. With a count line, exactly N points must follow.
std::vector<Eigen::Vector3d> parse_points(std::string_view text, std::string_view source = "<text>");
std::vector<Eigen::Vector3d> read_points(const std::filesystem::path& path);

}  // namespace imess::metrology
