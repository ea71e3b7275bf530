// Points for `messcap fit` and `messcap convert`: a file or stdin, read by the metrology
// library's point reader ('x y z' lines, NIST .ds), also accepting messcap's own .csv header.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "imess/metrology/point_file.hpp"

namespace imess::messcap {

// A point file as `messcap fit` and `convert` read it: probed hits when its lines hold 7
// numbers (x y z i j k r, see metrology::parse_probed_points), plain points when they hold 3.
struct PointInput {
  std::vector<Eigen::Vector3d> points;             // the surface points (both layouts)
  std::vector<metrology::ProbedPoint> hits;        // only for the 7-column layout
  bool probed = false;
};
// path "-" = stdin. Throws std::runtime_error / metrology::PointFileError naming the source
// and line ("pts.xyz:4: ...").
PointInput read_point_or_hit_input(const std::string& path);

// The name errors use for `path` ("<stdin>" for "-").
std::string input_name(const std::string& path);

}  // namespace imess::messcap
