// .xyz / .asc: "1.000 2.000 3.000" per point, no header — the plain point cloud FreeCAD's
// Points module reads as .asc (a line format: appendable).
#include "writers.hpp"

namespace imess::exchange::writers {

std::string xyz_header() { return {}; }

std::string xyz_line(const Eigen::Vector3d& p, int decimals) {
  return fixed(p.x(), decimals) + " " + fixed(p.y(), decimals) + " " + fixed(p.z(), decimals) + "\n";
}

std::string xyz(const ExportData& d) {
  std::string out;
  for (const auto& p : d.points) out += xyz_line(p, d.decimals);
  return out;
}

}  // namespace imess::exchange::writers
