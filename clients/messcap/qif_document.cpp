// The QIF document around the features and characteristics: header, units, the machines, the
// part, and the results of every run; the ids are all given out before anything is written.
#include "qif_document.hpp"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>

#include "qif_parts.hpp"

namespace imess::messcap {
namespace {

// The plan of `run` must be the first run's: same part, features and characteristics.
void check_same_plan(const QifRunSource& first, const QifRunSource& run) {
  auto differ = [&](const std::string& what) {
    throw QifError(run.name + " is not a run of the plan of " + first.name + ": " + what +
                   "; one QIF document holds runs of one plan");
  };
  const SavedInspection& a = first.run;
  const SavedInspection& b = run.run;
  if (a.part != b.part) differ("part '" + b.part + "', not '" + a.part + "'");
  if (a.features.size() != b.features.size()) differ("another number of features");
  for (std::size_t i = 0; i < a.features.size(); ++i) {
    const SavedGeometry& x = a.features[i].nominal;
    const SavedGeometry& y = b.features[i].nominal;
    if (a.features[i].name != b.features[i].name || x.type != y.type)
      differ("feature " + std::to_string(i + 1) + " is the " + y.type + " '" + b.features[i].name + "', not the " +
             x.type + " '" + a.features[i].name + "'");
    const double nm = 1e-6;  // the reports' resolution
    if ((x.point - y.point).norm() > nm || (x.direction - y.direction).norm() > 1e-9 ||
        std::abs(x.diameter - y.diameter) > nm || std::abs(x.apex_angle_deg - y.apex_angle_deg) > 1e-9 ||
        x.inner != y.inner)
      differ("feature '" + b.features[i].name + "' has another nominal geometry");
  }
  if (a.characteristics.size() != b.characteristics.size()) differ("another number of characteristics");
  for (std::size_t i = 0; i < a.characteristics.size(); ++i) {
    const auto& x = a.characteristics[i];
    const auto& y = b.characteristics[i];
    if (x.name != y.name || x.type != y.type || x.feature != y.feature || x.other != y.other || x.radius != y.radius ||
        x.lower != y.lower || x.upper != y.upper || (x.nominal && y.nominal && std::abs(*x.nominal - *y.nominal) > 1e-6))
      differ("characteristic " + std::to_string(i + 1) + " ('" + y.name +
             "') differs in name, type, features, nominal or tolerance");
  }
  if (a.datums != b.datums) differ("another alignment");
}

const char* inspection_status(const SavedInspection& run) {
  bool out = false, unknown = false;
  for (const auto& c : run.characteristics) {
    if (!c.actual) unknown = true;
    else if (!c.in_tolerance) out = true;
  }
  return out ? "FAIL" : unknown ? "NOT_CALCULATED" : "PASS";
}

void write_units(XmlWriter& w) {
  w.open("FileUnits");
  w.open("PrimaryUnits");
  w.open("AngularUnit");
  w.leaf("SIUnitName", "radian");
  w.leaf("UnitName", "degree");
  w.open("UnitConversion");
  w.leaf("Factor", "0.0174532925199433");
  w.close("UnitConversion");
  w.close("AngularUnit");
  w.open("LinearUnit");
  w.leaf("SIUnitName", "meter");
  w.leaf("UnitName", "mm");
  w.open("UnitConversion");
  w.leaf("Factor", "0.001");
  w.close("UnitConversion");
  w.close("LinearUnit");
  w.close("PrimaryUnits");
  w.close("FileUnits");
}

void write_results(XmlWriter& w, const QifRunSource& source, const QifIds& ids, const QifRunIds& run_ids) {
  const SavedInspection& run = source.run;
  const unsigned device = run.machine.empty() ? 0 : ids.devices.at(run.machine);
  w.open("MeasurementResults", {{"id", std::to_string(run_ids.results)}});
  w.open("Attributes", {{"n", "2"}});
  w.empty("AttributeStr", {{"name", "plan"}, {"value", run.plan}});
  w.empty("AttributeStr", {{"name", "measured"}, {"value", run.measured}});
  w.close("Attributes");
  if (!run.time.empty() || !run.operator_name.empty()) {
    w.open("InspectionTraceability");
    if (!run.time.empty()) w.leaf("InspectionStart", run.time);
    if (!run.operator_name.empty()) {
      w.open("InspectionOperator");
      w.leaf("Name", run.operator_name);
      w.close("InspectionOperator");
    }
    w.close("InspectionTraceability");
  }
  if (!run.features.empty()) write_measured_features(w, run, ids, run_ids, device);
  write_measured_point_sets(w, run, run_ids);
  write_measured_characteristics(w, run, ids, run_ids, device);
  w.open("InspectionStatus");
  w.leaf("InspectionStatusEnum", inspection_status(run));
  w.close("InspectionStatus");
  w.close("MeasurementResults");
}

}  // namespace

QifRunIds assign_run_ids(const SavedInspection& run, QifIds& ids) {
  QifRunIds r;
  r.results = ids.take();
  for (const auto& f : run.features) r.feature_measurements[f.name] = ids.take();
  for (const auto& f : run.features)
    for (const auto& p : run.points)
      if (p.feature == f.name) {
        r.point_sets[f.name] = ids.take();
        break;
      }
  for (std::size_t i = 0; i < run.characteristics.size(); ++i) r.characteristic_measurements.push_back(ids.take());
  return r;
}

std::string new_qpid() {
  std::random_device rd;
  std::uniform_int_distribution<unsigned> byte(0, 255);
  unsigned char b[16];
  for (auto& x : b) x = static_cast<unsigned char>(byte(rd));
  b[6] = static_cast<unsigned char>((b[6] & 0x0f) | 0x40);  // version 4
  b[8] = static_cast<unsigned char>((b[8] & 0x3f) | 0x80);  // variant 1
  char text[37];
  std::snprintf(text, sizeof text, "%02x%02x%02x%02x-%02x%02x-%02x%02x-%02x%02x-%02x%02x%02x%02x%02x%02x", b[0], b[1],
                b[2], b[3], b[4], b[5], b[6], b[7], b[8], b[9], b[10], b[11], b[12], b[13], b[14], b[15]);
  return text;
}

std::string utc_time_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string qif_document(const std::vector<QifRunSource>& runs, const std::string& created, const std::string& qpid) {
  if (runs.empty()) throw QifError("no inspection run to write");
  for (std::size_t i = 1; i < runs.size(); ++i) check_same_plan(runs.front(), runs[i]);
  const SavedInspection& plan = runs.front().run;

  QifIds ids;
  const unsigned part_id = ids.take();
  ids.standard = ids.take();
  for (const auto& r : runs)
    if (!r.run.machine.empty() && !ids.devices.count(r.run.machine)) ids.devices[r.run.machine] = ids.take();
  assign_feature_ids(plan, ids);
  assign_characteristic_ids(plan, ids);
  std::vector<QifRunIds> run_ids;
  for (const auto& r : runs) run_ids.push_back(assign_run_ids(r.run, ids));

  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  XmlWriter w(out);
  w.open("QIFDocument", {{"xmlns", "http://qifstandards.org/xsd/qif3"},
                         {"xmlns:xsi", "http://www.w3.org/2001/XMLSchema-instance"},
                         {"xsi:schemaLocation", "http://qifstandards.org/xsd/qif3 QIFApplications/QIFDocument.xsd"},
                         {"versionQIF", "3.0.0"},
                         {"idMax", std::to_string(ids.next - 1)}});
  w.leaf("QPId", qpid.empty() ? new_qpid() : qpid);
  if (!created.empty()) {
    w.open("Version");
    w.leaf("TimeCreated", created);
    w.close("Version");
  }
  w.open("Header");
  w.open("Application");
  w.leaf("Name", "messcap");
  w.leaf("Organization", "IMESS");
  w.close("Application");
  w.leaf("Description", "Inspection of " + plan.part + " by the plan " + plan.plan);
  w.close("Header");
  if (!plan.characteristics.empty()) {  // the standard the characteristics are defined by
    w.open("StandardsDefinitions", {{"n", "1"}});
    w.open("Standard", {{"id", std::to_string(ids.standard)}});
    w.open("Organization");
    w.leaf("StandardsOrganizationEnum", "ISO");
    w.close("Organization");
    w.leaf("Designator", "1101");
    w.leaf("Title", "Geometrical product specifications (GPS) - Geometrical tolerancing");
    w.close("Standard");
    w.close("StandardsDefinitions");
  }
  write_units(w);
  write_datums(w, plan, ids);
  if (!ids.devices.empty()) {
    w.open("MeasurementResources");
    w.open("MeasurementDevices", {{"n", std::to_string(ids.devices.size())}});
    for (const auto& [machine, id] : ids.devices) {
      w.open("MeasurementDevice", {{"id", std::to_string(id)}});
      w.leaf("Name", machine);
      w.close("MeasurementDevice");
    }
    w.close("MeasurementDevices");
    w.close("MeasurementResources");
  }
  w.open("Product");
  w.open("PartSet", {{"n", "1"}});
  w.open("Part", {{"id", std::to_string(part_id)}});
  w.open("Header");
  w.leaf("Name", plan.part);
  w.close("Header");
  w.close("Part");
  w.close("PartSet");
  w.close("Product");
  if (!plan.features.empty()) write_features(w, plan, ids);
  if (!plan.characteristics.empty()) write_characteristics(w, plan, ids);
  w.open("Results");
  w.open("MeasurementResultsSet", {{"n", std::to_string(runs.size())}});
  for (std::size_t i = 0; i < runs.size(); ++i) write_results(w, runs[i], ids, run_ids[i]);
  w.close("MeasurementResultsSet");
  w.close("Results");
  w.close("QIFDocument");
  return out;
}

}  // namespace imess::messcap
