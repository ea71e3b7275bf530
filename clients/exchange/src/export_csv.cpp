// .csv: header "x,y,z", then "1.000,2.000,3.000" per point (a line format: appendable).
#include "writers.hpp"

namespace imess::exchange::writers {

std::string csv_header() { return "x,y,z\n"; }

std::string csv_line(const Eigen::Vector3d& p, int decimals) {
  return fixed(p.x(), decimals) + "," + fixed(p.y(), decimals) + "," + fixed(p.z(), decimals) + "\n";
}

std::string csv(const ExportData& d) {
  std::string out = csv_header();
  for (const auto& p : d.points) out += csv_line(p, d.decimals);
  return out;
}

}  // namespace imess::exchange::writers
