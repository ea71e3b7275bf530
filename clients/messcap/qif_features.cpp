// QIF features: every plan feature as FeatureDefinition (its kind, inner/outer, diameter),
// FeatureNominal (nominal geometry, part coordinates) and FeatureItem (its name, measured);
// per run a FeatureMeasurement (the fitted geometry, the form) and the MeasuredPointSet of the
// points it was fitted to.
#include <stdexcept>

#include "qif_parts.hpp"

namespace imess::messcap {
namespace {

// "Plane", "Circle", … as QIF spells its feature kinds.
std::string feature_tag(const std::string& type) {
  std::string k = type;
  if (!k.empty()) k[0] = static_cast<char>(k[0] - 'a' + 'A');
  return k;
}

bool has_diameter(const std::string& type) { return type == "circle" || type == "sphere" || type == "cylinder" || type == "cone"; }

// Location / Normal / Axis …, in the order both the nominal and the measurement types take them
// (the measurement's Diameter and Form are written by the caller).
void write_geometry(XmlWriter& w, const SavedGeometry& g) {
  if (g.type == "point" || g.type == "plane" || g.type == "circle") {
    w.leaf("Location", qif_vector(g.point));
    w.leaf("Normal", qif_vector(g.direction, 9));
  } else if (g.type == "line") {
    w.leaf("Location", qif_vector(g.point));
    w.leaf("Direction", qif_vector(g.direction, 9));
  } else if (g.type == "sphere") {
    w.leaf("Location", qif_vector(g.point));
  } else {  // cylinder, cone
    w.open("Axis");
    w.leaf("AxisPoint", qif_vector(g.point));
    w.leaf("Direction", qif_vector(g.direction, 9));
    w.close("Axis");
  }
}

}  // namespace

const SavedFeature& saved_feature(const SavedInspection& run, const std::string& name) {
  for (const auto& f : run.features)
    if (f.name == name) return f;
  throw std::out_of_range("no feature '" + name + "'");
}

void assign_feature_ids(const SavedInspection& plan, QifIds& ids) {
  for (const auto& f : plan.features) {
    QifDefinitionIds& d = ids.features[f.name];
    d.definition = ids.take();
    d.nominal = ids.take();
    d.item = ids.take();
  }
}

void write_features(XmlWriter& w, const SavedInspection& plan, const QifIds& ids) {
  const std::string n = std::to_string(plan.features.size());
  w.open("Features");
  w.open("FeatureDefinitions", {{"n", n}});
  for (const auto& f : plan.features) {
    const std::string tag = feature_tag(f.nominal.type) + "FeatureDefinition";
    const std::string id = std::to_string(ids.features.at(f.name).definition);
    if (!has_diameter(f.nominal.type)) {
      w.empty(tag, {{"id", id}});
      continue;
    }
    w.open(tag, {{"id", id}});
    w.leaf("InternalExternal", f.nominal.inner ? "INTERNAL" : "EXTERNAL");
    w.leaf("Diameter", qif_number(f.nominal.diameter));
    if (f.nominal.type == "cone") w.leaf("FullAngle", qif_number(f.nominal.apex_angle_deg, 9));
    w.close(tag);
  }
  w.close("FeatureDefinitions");
  w.open("FeatureNominals", {{"n", n}});
  for (const auto& f : plan.features) {
    const std::string tag = feature_tag(f.nominal.type) + "FeatureNominal";
    const auto& d = ids.features.at(f.name);
    w.open(tag, {{"id", std::to_string(d.nominal)}});
    w.leaf("FeatureDefinitionId", std::to_string(d.definition));
    write_geometry(w, f.nominal);
    w.close(tag);
  }
  w.close("FeatureNominals");
  w.open("FeatureItems", {{"n", n}});
  for (const auto& f : plan.features) {
    const std::string tag = feature_tag(f.nominal.type) + "FeatureItem";
    const auto& d = ids.features.at(f.name);
    w.open(tag, {{"id", std::to_string(d.item)}});
    w.leaf("FeatureNominalId", std::to_string(d.nominal));
    w.leaf("FeatureName", f.name);
    w.open("DeterminationMode");
    w.open("Checked");
    w.open("CheckDetails");
    w.empty("Measured");
    w.close("CheckDetails");
    w.close("Checked");
    w.close("DeterminationMode");
    w.close(tag);
  }
  w.close("FeatureItems");
  w.close("Features");
}

void write_measured_features(XmlWriter& w, const SavedInspection& run, const QifIds& ids, const QifRunIds& run_ids,
                             unsigned device) {
  w.open("MeasuredFeatures", {{"n", std::to_string(run.features.size())}});
  for (const auto& f : run.features) {
    const std::string tag = feature_tag(f.nominal.type) + "FeatureMeasurement";
    w.open(tag, {{"id", std::to_string(run_ids.feature_measurements.at(f.name))}});
    w.leaf("FeatureItemId", std::to_string(ids.features.at(f.name).item));
    if (!run.time.empty()) w.leaf("TimeStamp", run.time);
    if (device) w.ids("MeasurementDeviceIds", {device});
    if (auto set = run_ids.point_sets.find(f.name); set != run_ids.point_sets.end()) {
      w.open("PointList", {{"n", "1"}});
      w.leaf("WholePointSetId", std::to_string(set->second));
      w.close("PointList");
    }
    if (f.actual) {
      const SavedGeometry& g = *f.actual;
      if (g.type == "cone") {
        write_geometry(w, g);
        w.leaf("Diameter", qif_number(g.diameter));
        w.leaf("FullAngle", qif_number(g.apex_angle_deg, 9));
        w.leaf("Form", qif_number(f.form));
      } else if (g.type == "point") {
        write_geometry(w, g);  // a point has no form
      } else {
        write_geometry(w, g);
        if (has_diameter(g.type)) w.leaf("Diameter", qif_number(g.diameter));
        w.leaf("Form", qif_number(f.form));
      }
    }
    w.close(tag);
  }
  w.close("MeasuredFeatures");
}

void write_measured_point_sets(XmlWriter& w, const SavedInspection& run, const QifRunIds& run_ids) {
  if (run_ids.point_sets.empty()) return;
  w.open("MeasuredPointSets", {{"n", std::to_string(run_ids.point_sets.size())}});
  for (const auto& f : run.features) {
    auto set = run_ids.point_sets.find(f.name);
    if (set == run_ids.point_sets.end()) continue;
    std::vector<const SavedPoint*> points;
    for (const auto& p : run.points)
      if (p.feature == f.name) points.push_back(&p);
    w.open("MeasuredPointSet", {{"id", std::to_string(set->second)}, {"count", std::to_string(points.size())}});
    std::string xyz, deviations;
    for (const SavedPoint* p : points) {
      xyz += (xyz.empty() ? "" : " ") + qif_vector(p->xyz);
      deviations += (deviations.empty() ? "" : " ") + qif_number(p->deviation);
    }
    w.leaf("Points", xyz);
    // The report's points are surface points, corrected for the tip radius when they were hits.
    bool hits = true;
    for (const SavedPoint* p : points) hits = hits && p->radius && *p->radius == *points.front()->radius;
    w.leaf("Compensated", "true");
    if (hits) w.leaf("ProbeRadius", qif_number(*points.front()->radius));
    w.leaf("Deviations", deviations);
    w.close("MeasuredPointSet");
  }
  w.close("MeasuredPointSets");
}

}  // namespace imess::messcap
