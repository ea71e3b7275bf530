// Points for `messcap fit` and `messcap convert`: a file or stdin, read by the metrology
// library's point reader ('x y z' lines, NIST .ds), also accepting messcap's own .csv header.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

namespace imess::messcap {

// path "-" = stdin. Throws std::runtime_error / metrology::PointFileError naming the source
// and line ("pts.xyz:4: ...").
std::vector<Eigen::Vector3d> read_point_input(const std::string& path);

// The name errors use for `path` ("<stdin>" for "-").
std::string input_name(const std::string& path);

}  // namespace imess::messcap
