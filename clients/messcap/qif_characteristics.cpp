// QIF characteristics: the plan's characteristics as CharacteristicDefinition (the tolerance),
// CharacteristicNominal (the target value) and CharacteristicItem (the name, the features), the
// datums they refer to, and per run a CharacteristicMeasurement (value, deviation, status).
#include <algorithm>

#include "qif_parts.hpp"

namespace imess::messcap {
namespace {

// QIF's name of a characteristic kind ("Diameter", "DistanceBetween", …).
std::string characteristic_tag(const SavedCharacteristic& c) {
  if (c.type == "size") return c.radius ? "Radius" : "Diameter";
  if (c.type == "position") return "Position";
  if (c.type == "distance") return "DistanceBetween";
  if (c.type == "angle") return "AngleBetween";
  if (c.type == "flatness") return "Flatness";
  if (c.type == "roundness") return "Circularity";
  if (c.type == "cylindricity") return "Cylindricity";
  if (c.type == "sphericity") return "Sphericity";
  if (c.type == "perpendicularity") return "Perpendicularity";
  return "Parallelism";
}

bool orientation(const SavedCharacteristic& c) { return c.type == "perpendicularity" || c.type == "parallelism"; }
bool axis_kind(const std::string& type) { return type == "line" || type == "cylinder" || type == "cone"; }

// An axis toleranced perpendicular to a plane or parallel to an axis lies in a cylinder
// (diametrical zone); everything else between two planes.
bool diametrical_orientation_zone(const SavedInspection& plan, const SavedCharacteristic& c) {
  if (!axis_kind(saved_feature(plan, c.feature).nominal.type)) return false;
  const std::string& datum = saved_feature(plan, c.other).nominal.type;
  return c.type == "perpendicularity" ? datum == "plane" : datum != "plane";
}

// A datum label: A, B, … Z, AA, AB, … (QIF's DatumLabel is a name token).
std::string datum_label(std::size_t k) {
  std::string label;
  for (std::size_t n = k + 1; n > 0; n = (n - 1) / 26) label.insert(label.begin(), static_cast<char>('A' + (n - 1) % 26));
  return label;
}

const char* const kPrecedence[] = {"PRIMARY", "SECONDARY", "TERTIARY"};

}  // namespace

std::string datum_frame_key(const std::vector<std::string>& datums) {
  std::string key;
  for (const auto& d : datums) key += d + '\n';
  return key;
}

std::vector<std::string> characteristic_datums(const SavedInspection& plan, const SavedCharacteristic& c) {
  if (orientation(c)) return {c.other};
  if (c.type == "position") return plan.datums;
  return {};
}

std::vector<std::vector<std::string>> datum_frames(const SavedInspection& plan) {
  std::vector<std::vector<std::string>> frames;
  auto add = [&](const std::vector<std::string>& d) {
    if (!d.empty() && std::find(frames.begin(), frames.end(), d) == frames.end()) frames.push_back(d);
  };
  add(plan.datums);
  for (const auto& c : plan.characteristics) add(characteristic_datums(plan, c));
  return frames;
}

void assign_characteristic_ids(const SavedInspection& plan, QifIds& ids) {
  for (const auto& frame : datum_frames(plan))
    for (const auto& d : frame)
      if (!ids.datum_definitions.count(d)) ids.datum_definitions[d] = ids.take();
  for (const auto& frame : datum_frames(plan)) ids.datum_frames[datum_frame_key(frame)] = ids.take();
  for (std::size_t i = 0; i < plan.characteristics.size(); ++i) {
    QifDefinitionIds d;
    d.definition = ids.take();
    d.nominal = ids.take();
    d.item = ids.take();
    ids.characteristics.push_back(d);
  }
}

void write_datums(XmlWriter& w, const SavedInspection& plan, const QifIds& ids) {
  const auto frames = datum_frames(plan);
  if (frames.empty()) return;
  // Labelled in the order of their ids (the alignment's first).
  std::vector<std::pair<unsigned, std::string>> defs;
  for (const auto& [name, id] : ids.datum_definitions) defs.emplace_back(id, name);
  std::sort(defs.begin(), defs.end());
  w.open("DatumDefinitions", {{"n", std::to_string(defs.size())}});
  for (std::size_t k = 0; k < defs.size(); ++k) {
    w.open("DatumDefinition", {{"id", std::to_string(defs[k].first)}});
    w.leaf("DatumLabel", datum_label(k));
    w.ids("FeatureNominalIds", {ids.features.at(defs[k].second).nominal});
    w.close("DatumDefinition");
  }
  w.close("DatumDefinitions");
  w.open("DatumReferenceFrames", {{"n", std::to_string(frames.size())}});
  for (const auto& frame : frames) {
    w.open("DatumReferenceFrame", {{"id", std::to_string(ids.datum_frames.at(datum_frame_key(frame)))}});
    w.open("Datums", {{"n", std::to_string(frame.size())}});
    for (std::size_t k = 0; k < frame.size(); ++k) {
      w.open("Datum");
      w.open("SimpleDatum");
      w.leaf("DatumDefinitionId", std::to_string(ids.datum_definitions.at(frame[k])));
      w.leaf("MaterialModifier", "NONE");
      w.leaf("ReferencedComponent", "ACTUAL");
      w.close("SimpleDatum");
      w.open("Precedence");
      w.leaf("PrecedenceEnum", kPrecedence[k]);
      w.close("Precedence");
      w.close("Datum");
    }
    w.close("Datums");
    w.close("DatumReferenceFrame");
  }
  w.close("DatumReferenceFrames");
}

void write_characteristics(XmlWriter& w, const SavedInspection& plan, const QifIds& ids) {
  const std::string n = std::to_string(plan.characteristics.size());
  const auto& cs = plan.characteristics;
  w.open("Characteristics");
  w.leaf("FormalStandardId", std::to_string(ids.standard));
  w.open("CharacteristicDefinitions", {{"n", n}});
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const auto& c = cs[i];
    const std::string tag = characteristic_tag(c) + "CharacteristicDefinition";
    w.open(tag, {{"id", std::to_string(ids.characteristics[i].definition)}});
    if (!c.zone) {  // size, distance, angle: limits of the deviation
      w.open("Tolerance");
      w.leaf("MaxValue", qif_number(c.upper, 9));
      w.leaf("MinValue", qif_number(c.lower, 9));
      w.leaf("DefinedAsLimit", "false");
      w.close("Tolerance");
    } else {
      w.leaf("ToleranceValue", qif_number(c.upper, 9));
      const auto datums = characteristic_datums(plan, c);
      if (!datums.empty()) w.leaf("DatumReferenceFrameId", std::to_string(ids.datum_frames.at(datum_frame_key(datums))));
      if (c.type == "position" || orientation(c)) {
        w.leaf("MaterialCondition", c.type == "position" ? "REGARDLESS" : "NONE");
        w.open("ZoneShape");
        if (c.type == "position" && saved_feature(plan, c.feature).nominal.type == "sphere")
          w.empty("SphericalZone");
        else
          w.empty(c.type == "position" || diametrical_orientation_zone(plan, c) ? "DiametricalZone" : "PlanarZone");
        w.close("ZoneShape");
      }
    }
    w.close(tag);
  }
  w.close("CharacteristicDefinitions");
  w.open("CharacteristicNominals", {{"n", n}});
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const auto& c = cs[i];
    const std::string tag = characteristic_tag(c) + "CharacteristicNominal";
    w.open(tag, {{"id", std::to_string(ids.characteristics[i].nominal)}});
    w.leaf("CharacteristicDefinitionId", std::to_string(ids.characteristics[i].definition));
    if (!c.zone && c.nominal) w.leaf("TargetValue", qif_number(*c.nominal, 9));
    if (c.type == "distance" || c.type == "angle") w.leaf("AnalysisMode", "THREEDIMENSIONAL");
    w.close(tag);
  }
  w.close("CharacteristicNominals");
  w.open("CharacteristicItems", {{"n", n}});
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const auto& c = cs[i];
    const std::string tag = characteristic_tag(c) + "CharacteristicItem";
    w.open(tag, {{"id", std::to_string(ids.characteristics[i].item)}});
    w.leaf("Name", c.name);
    std::vector<unsigned> items{ids.features.at(c.feature).item};
    if (c.type == "distance" || c.type == "angle") items.push_back(ids.features.at(c.other).item);
    w.ids("FeatureItemIds", items);
    w.leaf("CharacteristicNominalId", std::to_string(ids.characteristics[i].nominal));
    w.close(tag);
  }
  w.close("CharacteristicItems");
  w.close("Characteristics");
}

void write_measured_characteristics(XmlWriter& w, const SavedInspection& run, const QifIds& ids,
                                    const QifRunIds& run_ids, unsigned device) {
  if (run.characteristics.empty()) return;
  w.open("MeasuredCharacteristics");
  w.open("CharacteristicMeasurements", {{"n", std::to_string(run.characteristics.size())}});
  for (std::size_t i = 0; i < run.characteristics.size(); ++i) {
    const auto& c = run.characteristics[i];
    const std::string tag = characteristic_tag(c) + "CharacteristicMeasurement";
    w.open(tag, {{"id", std::to_string(run_ids.characteristic_measurements[i])}});
    if (c.deviation) {
      w.open("Attributes", {{"n", "1"}});
      w.empty("AttributeD1", {{"name", "deviation"}, {"value", qif_number(*c.deviation, 9)}});
      w.close("Attributes");
    } else {
      w.leaf("Description", "not evaluated: " + c.error);
    }
    w.open("Status");
    w.leaf("CharacteristicStatusEnum", !c.actual ? "INDETERMINATE" : c.in_tolerance ? "PASS" : "FAIL");
    w.close("Status");
    w.leaf("CharacteristicItemId", std::to_string(ids.characteristics[i].item));
    if (!run.time.empty()) w.leaf("TimeStamp", run.time);
    std::vector<unsigned> measured{run_ids.feature_measurements.at(c.feature)};
    if (c.type == "distance" || c.type == "angle") measured.push_back(run_ids.feature_measurements.at(c.other));
    w.ids("FeatureMeasurementIds", measured);
    if (device) w.ids("MeasurementDeviceIds", {device});
    if (c.actual) w.leaf("Value", qif_number(*c.actual, 9));
    w.close(tag);
  }
  w.close("CharacteristicMeasurements");
  w.close("MeasuredCharacteristics");
}

}  // namespace imess::messcap
