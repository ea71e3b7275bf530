// Readers for plain point files (the NIST .ds layout and simple XYZ/CSV clouds) and for probed
// point files (surface point, approach direction, tip radius per hit): the only I/O helpers of
// the metrology library apart from the frame store.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace imess::metrology {

// Thrown with "<source>:<line>:<column>: <what is wrong, what was expected>" (a count mismatch,
// which belongs to no line, with "<source>: ...").
class PointFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Layout: an optional first line holding only the point count N; then one point per line,
// three numbers separated by blanks, tabs, commas or semicolons. Blank lines and text after
// '#' are ignored. With a count line, exactly N points must follow.
std::vector<Eigen::Vector3d> parse_points(std::string_view text, std::string_view source = "<text>");
std::vector<Eigen::Vector3d> read_points(const std::filesystem::path& path);

// One probe hit as messd reports it (`Hit seq id x y z i j k r t`): the surface point (already
// compensated along the approach), the unit approach (motion) direction of the probe at contact
// and the tip radius that was applied. The ball centre is surface - radius * approach.
// A hit without a direction (messd's ForcePt: i j k = 0 0 0, r = 0) has approach = 0.
struct ProbedPoint {
  Eigen::Vector3d surface = Eigen::Vector3d::Zero();
  Eigen::Vector3d approach = Eigen::Vector3d::Zero();
  double radius = 0.0;
  Eigen::Vector3d centre() const { return surface - radius * approach; }
  bool has_approach() const { return approach.squaredNorm() > 0.0; }
};

// Tolerance on the length of a given approach vector (files print it with a few decimals);
// within it the vector is normalised, outside it the line is an error.
inline constexpr double kApproachLengthTolerance = 1e-3;

// Same layout rules as parse_points (count line, separators, comments) with seven numbers per
// line: x y z i j k r. (i j k) is a unit vector (within kApproachLengthTolerance, stored
// normalised) or 0 0 0 together with r = 0; r is finite and >= 0.
std::vector<ProbedPoint> parse_probed_points(std::string_view text, std::string_view source = "<text>");
std::vector<ProbedPoint> read_probed_points(const std::filesystem::path& path);

// The number of values on the first point line of a point file (after an optional count line):
// 3 for plain points, 7 for probed points, 0 when the text holds no point. Lets a caller choose
// between parse_points and parse_probed_points; throws PointFileError on a malformed number.
std::size_t point_file_columns(std::string_view text, std::string_view source = "<text>");

}  // namespace imess::metrology
