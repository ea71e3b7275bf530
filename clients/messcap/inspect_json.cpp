// The JSON report of messcap inspect: alignment, per characteristic, per feature and per point
// (the FreeCAD plugin colours points from "points"; `messcap inspect --points` reads them back).
#include <cmath>

#include <nlohmann/json.hpp>

#include "inspect_report.hpp"

namespace imess::messcap {
namespace {

using nlohmann::json;

// Nanometre resolution: enough for any measurement, short enough to read.
double nm(double v) { return std::round(v * 1e6) / 1e6; }
json vec(const Eigen::Vector3d& v) { return json::array({nm(v.x()), nm(v.y()), nm(v.z())}); }
json unit(const Eigen::Vector3d& v) {
  return json::array({std::round(v.x() * 1e9) / 1e9, std::round(v.y() * 1e9) / 1e9, std::round(v.z() * 1e9) / 1e9});
}

json geometry_json(const metrology::Geometry& g) {
  using metrology::FeatureKind;
  json j;
  j["type"] = std::string(metrology::to_string(g.kind));
  switch (g.kind) {
    case FeatureKind::Point:
    case FeatureKind::Plane:
      j["point"] = vec(g.point);
      j["normal"] = unit(g.direction);
      break;
    case FeatureKind::Line:
      j["point"] = vec(g.point);
      j["direction"] = unit(g.direction);
      break;
    case FeatureKind::Circle:
      j["center"] = vec(g.point);
      j["normal"] = unit(g.direction);
      j["diameter"] = nm(g.diameter);
      j["inner"] = g.inner;
      break;
    case FeatureKind::Sphere:
      j["center"] = vec(g.point);
      j["diameter"] = nm(g.diameter);
      j["inner"] = g.inner;
      break;
    case FeatureKind::Cylinder:
    case FeatureKind::Cone:
      j["point"] = vec(g.point);
      j["axis"] = unit(g.direction);
      j["diameter"] = nm(g.diameter);
      if (g.kind == FeatureKind::Cone) j["apex_angle_deg"] = std::round(g.apex_angle_deg * 1e9) / 1e9;
      j["inner"] = g.inner;
      break;
  }
  return j;
}

}  // namespace

std::string inspection_json(const metrology::InspectionPlan& plan, const metrology::InspectionResult& result,
                            const ReportSource& source) {
  json doc;
  doc["part"] = plan.part;
  doc["plan"] = source.plan;
  doc["measured"] = source.measured;
  if (!source.time.empty()) doc["time"] = source.time;
  if (!source.machine.empty()) doc["machine"] = source.machine;
  if (!source.operator_name.empty()) doc["operator"] = source.operator_name;
  doc["units"] = {{"length", "mm"}, {"angle", "deg"}};
  const auto& a = result.alignment;
  json al;
  al["from"] = a.measured ? "alignment" : "placement";
  if (a.measured) al["datums"] = {plan.alignment->primary, plan.alignment->secondary, plan.alignment->tertiary};
  al["origin"] = vec(a.part_to_machine.translation());
  al["x_axis"] = unit(a.part_to_machine.rotation().col(0));
  al["y_axis"] = unit(a.part_to_machine.rotation().col(1));
  al["z_axis"] = unit(a.part_to_machine.rotation().col(2));
  al["shift"] = vec(a.shift);
  al["rotation_deg"] = json::array({std::round(a.rotation_deg.x() * 1e9) / 1e9, std::round(a.rotation_deg.y() * 1e9) / 1e9,
                                    std::round(a.rotation_deg.z() * 1e9) / 1e9});
  doc["alignment"] = al;

  json chars = json::array();
  for (const auto& c : result.characteristics) {
    json j;
    j["name"] = c.spec.name;
    j["type"] = std::string(metrology::to_string(c.spec.kind));
    j["feature"] = c.spec.feature;
    if (!c.spec.other.empty()) {
      const bool datum = c.spec.kind == metrology::CharacteristicKind::Perpendicularity ||
                         c.spec.kind == metrology::CharacteristicKind::Parallelism;
      j[datum ? "datum" : "other"] = c.spec.other;
    }
    j["unit"] = unit_of(c);
    j["zone"] = metrology::is_zone(c.spec.kind);
    if (c.spec.radius) j["radius"] = true;  // a size given as a radius (the plugin's point scale needs to know)
    j["lower"] = c.spec.lower;
    j["upper"] = c.spec.upper;
    if (c.evaluated()) {
      j["nominal"] = nm(c.nominal);
      j["actual"] = nm(c.actual);
      j["deviation"] = nm(c.deviation);
      j["in_tolerance"] = c.in_tolerance;
      if (c.nominal_location) j["nominal_location"] = vec(*c.nominal_location);
      if (c.actual_location) j["actual_location"] = vec(*c.actual_location);
    } else {
      j["error"] = c.error;
    }
    chars.push_back(j);
  }
  doc["characteristics"] = chars;

  json features = json::array();
  for (std::size_t i = 0; i < result.features.size(); ++i) {
    const auto& f = result.features[i];
    json j;
    j["name"] = f.name;
    j["points"] = f.point_count;
    j["nominal"] = geometry_json(plan.features[i].nominal);
    if (f.actual) {
      j["actual"] = geometry_json(*f.actual);
      j["compensated"] = f.compensated;
      j["form"] = nm(f.stats.form());
      j["rms"] = nm(f.stats.rms);
    } else {
      j["error"] = f.error;
    }
    features.push_back(j);
  }
  doc["features"] = features;

  json points = json::array();
  for (const auto& p : result.points) {
    json j;
    j["feature"] = p.feature;
    j["xyz"] = vec(p.part);
    j["deviation"] = nm(p.deviation);
    if (p.form) j["form"] = nm(*p.form);
    j["machine"] = vec(p.measured.point);
    if (p.measured.approach) {
      j["approach"] = unit(*p.measured.approach);
      j["radius"] = nm(p.measured.radius);
    }
    points.push_back(j);
  }
  doc["points"] = points;
  doc["summary"] = {{"characteristics", result.characteristics.size()},
                    {"in_tolerance", result.characteristics.size() - result.out_of_tolerance() - result.not_evaluated()},
                    {"out_of_tolerance", result.out_of_tolerance()},
                    {"not_evaluated", result.not_evaluated()}};
  return doc.dump(2) + "\n";
}

}  // namespace imess::messcap
