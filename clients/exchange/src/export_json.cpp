// .json: {"units":"mm","frame":...,"points":[[x,y,z],...],"fit":{...}} — coordinates rounded
// to the export's decimals, the fit object exactly as `messcap fit` prints it.
#include <cmath>

#include <nlohmann/json.hpp>

#include "writers.hpp"

namespace imess::exchange::writers {

std::string json(const ExportData& d) {
  nlohmann::ordered_json j;
  j["units"] = "mm";
  j["frame"] = d.frame.empty() ? std::string("machine") : d.frame;
  const double scale = std::pow(10.0, d.decimals);
  auto round = [&](double v) {
    double r = std::round(v * scale) / scale;
    return r == 0.0 ? 0.0 : r;
  };
  auto points = nlohmann::ordered_json::array();
  for (const auto& p : d.points) points.push_back({round(p.x()), round(p.y()), round(p.z())});
  j["points"] = std::move(points);
  if (d.fit) j["fit"] = nlohmann::ordered_json::parse(to_json(*d.fit));
  return j.dump(1) + "\n";
}

}  // namespace imess::exchange::writers
