// .ply: ASCII PLY 1.0, one element "vertex" with double x y z per point.
#include "writers.hpp"

namespace imess::exchange::writers {

std::string ply(const ExportData& d) {
  std::string out = "ply\nformat ascii 1.0\ncomment " + d.source + ", measured points, mm\n";
  if (!d.frame.empty()) out += "comment frame " + d.frame + "\n";
  out += "element vertex " + std::to_string(d.points.size()) +
         "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  for (const auto& p : d.points) out += xyz_line(p, d.decimals);
  return out;
}

}  // namespace imess::exchange::writers
