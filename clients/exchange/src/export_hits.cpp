// .hits: one "x y z i j k r" line per hit — surface point, unit approach direction, tip radius,
// as messd's Hit carries them and metrology::parse_probed_points reads them (a line format:
// appendable). A forced point keeps its "0 0 0" direction and r = 0.
#include "imess/exchange/export_format.hpp"
#include "writers.hpp"

namespace imess::exchange::writers {

std::string hits_header() { return "# x y z i j k r: surface point, unit approach direction, tip radius (mm)\n"; }

std::string hits_line(const metrology::ProbedPoint& h, int decimals) {
  std::string line;
  for (double v : {h.surface.x(), h.surface.y(), h.surface.z()}) line += fixed(v, decimals) + " ";
  for (double v : {h.approach.x(), h.approach.y(), h.approach.z()}) line += fixed(v, kApproachDecimals) + " ";
  return line + fixed(h.radius, decimals) + "\n";
}

std::string hits(const ExportData& d) {
  if (d.hits.size() != d.points.size())
    throw FormatError("a .hits file needs each point's approach direction and tip radius; these " +
                      std::to_string(d.points.size()) + " points came without them");
  std::string out = hits_header();
  for (const auto& h : d.hits) out += hits_line(h, d.decimals);
  return out;
}

}  // namespace imess::exchange::writers
