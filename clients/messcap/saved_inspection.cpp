// Reading a saved messcap inspect JSON report back, checked key by key.
#include "saved_inspection.hpp"

#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"

namespace imess::messcap {
namespace {

using nlohmann::json;

class ReportReader {
 public:
  explicit ReportReader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw SavedInspectionError(source_ + ": " + path + ": " + what);
  }
  const json& member(const json& obj, const std::string& path, const char* key) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(join(path, key), "missing");
    return *it;
  }
  const json* optional_member(const json& obj, const char* key) const {
    auto it = obj.find(key);
    return it == obj.end() || it->is_null() ? nullptr : &*it;
  }
  std::string text(const json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, "expected a string");
    return v.get<std::string>();
  }
  double number(const json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, "expected a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "expected a finite number");
    return d;
  }
  bool boolean(const json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, "expected true or false");
    return v.get<bool>();
  }
  Eigen::Vector3d vector(const json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3) fail(path, "expected [x, y, z]");
    return {number(v[0], path + "[0]"), number(v[1], path + "[1]"), number(v[2], path + "[2]")};
  }
  Eigen::Vector3d unit(const json& v, const std::string& path) const {
    const Eigen::Vector3d u = vector(v, path);
    if (std::abs(u.norm() - 1.0) > 1e-6) fail(path, "expected a unit vector");
    return u;
  }
  const json& array(const json& obj, const std::string& path, const char* key) const {
    const json& a = member(obj, path, key);
    if (!a.is_array()) fail(join(path, key), "expected an array");
    return a;
  }
  static std::string join(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }
  static std::string index(const char* key, std::size_t i) { return std::string(key) + "[" + std::to_string(i) + "]"; }

 private:
  std::string source_;
};

SavedGeometry read_geometry(const ReportReader& r, const json& j, const std::string& path) {
  SavedGeometry g;
  g.type = r.text(r.member(j, path, "type"), ReportReader::join(path, "type"));
  auto at = [&](const char* key) { return ReportReader::join(path, key); };
  if (g.type == "point" || g.type == "plane") {
    g.point = r.vector(r.member(j, path, "point"), at("point"));
    g.direction = r.unit(r.member(j, path, "normal"), at("normal"));
  } else if (g.type == "line") {
    g.point = r.vector(r.member(j, path, "point"), at("point"));
    g.direction = r.unit(r.member(j, path, "direction"), at("direction"));
  } else if (g.type == "circle" || g.type == "sphere") {
    g.point = r.vector(r.member(j, path, "center"), at("center"));
    if (g.type == "circle") g.direction = r.unit(r.member(j, path, "normal"), at("normal"));
  } else if (g.type == "cylinder" || g.type == "cone") {
    g.point = r.vector(r.member(j, path, "point"), at("point"));
    g.direction = r.unit(r.member(j, path, "axis"), at("axis"));
    if (g.type == "cone") g.apex_angle_deg = r.number(r.member(j, path, "apex_angle_deg"), at("apex_angle_deg"));
  } else {
    r.fail(at("type"), "'" + g.type + "': expected point, line, plane, circle, sphere, cylinder or cone");
  }
  if (g.type != "point" && g.type != "line" && g.type != "plane") {
    g.diameter = r.number(r.member(j, path, "diameter"), at("diameter"));
    if (!(g.diameter > 0)) r.fail(at("diameter"), "expected a diameter above 0");
    g.inner = r.boolean(r.member(j, path, "inner"), at("inner"));
  }
  return g;
}

const char* const kCharacteristicTypes[] = {"size",        "position",         "distance",    "angle",
                                            "flatness",    "roundness",        "cylindricity", "sphericity",
                                            "perpendicularity", "parallelism"};

SavedCharacteristic read_characteristic(const ReportReader& r, const json& j, const std::string& path) {
  SavedCharacteristic c;
  auto at = [&](const char* key) { return ReportReader::join(path, key); };
  c.name = r.text(r.member(j, path, "name"), at("name"));
  if (c.name.empty()) r.fail(at("name"), "expected a name");
  c.type = r.text(r.member(j, path, "type"), at("type"));
  bool known = false;
  for (const char* t : kCharacteristicTypes) known = known || c.type == t;
  if (!known)
    r.fail(at("type"), "'" + c.type + "': expected size, position, distance, angle, flatness, roundness, "
                                      "cylindricity, sphericity, perpendicularity or parallelism");
  c.feature = r.text(r.member(j, path, "feature"), at("feature"));
  if (const json* o = r.optional_member(j, "other")) c.other = r.text(*o, at("other"));
  if (const json* d = r.optional_member(j, "datum")) c.other = r.text(*d, at("datum"));
  if ((c.type == "distance" || c.type == "angle" || c.type == "perpendicularity" || c.type == "parallelism") &&
      c.other.empty())
    r.fail(path, c.type == "distance" || c.type == "angle" ? "a " + c.type + " needs its second feature (\"other\")"
                                                           : "a " + c.type + " needs its datum (\"datum\")");
  c.unit = r.text(r.member(j, path, "unit"), at("unit"));
  if (c.unit != "mm" && c.unit != "deg") r.fail(at("unit"), "'" + c.unit + "': expected mm or deg");
  c.zone = r.boolean(r.member(j, path, "zone"), at("zone"));
  if (const json* rad = r.optional_member(j, "radius")) c.radius = r.boolean(*rad, at("radius"));
  c.lower = r.number(r.member(j, path, "lower"), at("lower"));
  c.upper = r.number(r.member(j, path, "upper"), at("upper"));
  if (c.lower > c.upper) r.fail(path, "lower above upper");
  if (const json* e = r.optional_member(j, "error")) {
    c.error = r.text(*e, at("error"));
  } else {
    c.nominal = r.number(r.member(j, path, "nominal"), at("nominal"));
    c.actual = r.number(r.member(j, path, "actual"), at("actual"));
    c.deviation = r.number(r.member(j, path, "deviation"), at("deviation"));
    c.in_tolerance = r.boolean(r.member(j, path, "in_tolerance"), at("in_tolerance"));
  }
  return c;
}

}  // namespace

SavedInspection parse_saved_inspection(std::string_view json_text, std::string_view source) {
  const ReportReader r(source);
  json doc;
  try {
    doc = jsontext::parse_strict(json_text, source);
  } catch (const jsontext::JsonTextError& e) {  // a syntax error, a duplicate key, a number beyond a double
    throw SavedInspectionError(std::string(e.what()) + " (expected a report of messcap inspect --json)");
  }
  if (!doc.is_object()) r.fail("(document)", "expected the JSON object messcap inspect --json writes");
  SavedInspection s;
  s.part = r.text(r.member(doc, "", "part"), "part");
  s.plan = r.text(r.member(doc, "", "plan"), "plan");
  s.measured = r.text(r.member(doc, "", "measured"), "measured");
  if (const json* t = r.optional_member(doc, "time")) s.time = r.text(*t, "time");
  if (const json* m = r.optional_member(doc, "machine")) s.machine = r.text(*m, "machine");
  if (const json* o = r.optional_member(doc, "operator")) s.operator_name = r.text(*o, "operator");
  const json& al = r.member(doc, "", "alignment");
  if (const json* d = r.optional_member(al, "datums")) {
    if (!d->is_array() || d->size() != 3) r.fail("alignment.datums", "expected [primary, secondary, tertiary]");
    for (std::size_t i = 0; i < 3; ++i) s.datums.push_back(r.text((*d)[i], ReportReader::index("alignment.datums", i)));
  }

  std::set<std::string> names;
  const json& features = r.array(doc, "", "features");
  for (std::size_t i = 0; i < features.size(); ++i) {
    const std::string path = ReportReader::index("features", i);
    const json& j = features[i];
    SavedFeature f;
    f.name = r.text(r.member(j, path, "name"), path + ".name");
    if (f.name.empty()) r.fail(path + ".name", "expected a name");
    if (!names.insert(f.name).second) r.fail(path + ".name", "'" + f.name + "' named twice");
    const double n = r.number(r.member(j, path, "points"), path + ".points");
    if (n < 0 || n != std::floor(n) || n > 1e9) r.fail(path + ".points", "expected a count of points");
    f.points = static_cast<std::size_t>(n);
    f.nominal = read_geometry(r, r.member(j, path, "nominal"), path + ".nominal");
    if (const json* a = r.optional_member(j, "actual")) {
      f.actual = read_geometry(r, *a, path + ".actual");
      if (f.actual->type != f.nominal.type) r.fail(path + ".actual.type", "expected '" + f.nominal.type + "' as the nominal");
      f.compensated = r.boolean(r.member(j, path, "compensated"), path + ".compensated");
      f.form = r.number(r.member(j, path, "form"), path + ".form");
    }
    s.features.push_back(std::move(f));
  }
  for (std::size_t k = 0; k < s.datums.size(); ++k)
    if (!names.count(s.datums[k]))
      r.fail(ReportReader::index("alignment.datums", k), "no feature '" + s.datums[k] + "' in \"features\"");

  std::set<std::string> char_names;
  const json& chars = r.array(doc, "", "characteristics");
  for (std::size_t i = 0; i < chars.size(); ++i) {
    const std::string path = ReportReader::index("characteristics", i);
    auto c = read_characteristic(r, chars[i], path);
    if (!char_names.insert(c.name).second) r.fail(path + ".name", "'" + c.name + "' named twice");
    if (!names.count(c.feature)) r.fail(path + ".feature", "no feature '" + c.feature + "' in \"features\"");
    if (!c.other.empty() && !names.count(c.other)) r.fail(path, "no feature '" + c.other + "' in \"features\"");
    s.characteristics.push_back(std::move(c));
  }

  const json& points = r.array(doc, "", "points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string path = ReportReader::index("points", i);
    const json& j = points[i];
    SavedPoint p;
    p.feature = r.text(r.member(j, path, "feature"), path + ".feature");
    if (!names.count(p.feature)) r.fail(path + ".feature", "no feature '" + p.feature + "' in \"features\"");
    p.xyz = r.vector(r.member(j, path, "xyz"), path + ".xyz");
    p.deviation = r.number(r.member(j, path, "deviation"), path + ".deviation");
    if (const json* rad = r.optional_member(j, "radius")) p.radius = r.number(*rad, path + ".radius");
    s.points.push_back(p);
  }
  return s;
}

}  // namespace imess::messcap
