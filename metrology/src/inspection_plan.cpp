// The inspection plan's JSON reader: every key checked, errors naming the key path and what
// was expected (docs/metrology.md §14).
#include "imess/metrology/inspection_plan.hpp"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <set>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"

namespace imess::metrology {
namespace {

using nlohmann::json;

// Reads one JSON value at a key path; every failure names the source and the path.
class Reader {
 public:
  explicit Reader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(const std::string& path, const std::string& why) const {
    throw InspectionPlanError(std::string(source_) + ": " + path + ": " + why);
  }

  // The object's keys must all be among `allowed` (a typo is an error, not silently ignored).
  void only_keys(const json& obj, const std::string& path, std::initializer_list<std::string_view> allowed) const {
    for (const auto& [key, value] : obj.items()) {
      bool known = false;
      for (auto a : allowed) known = known || key == a;
      if (known) continue;
      std::string list;
      for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(join(path, key), "unknown key; accepted here: " + list);
    }
  }

  const json& required(const json& obj, const std::string& path, const char* key, const char* expected) const {
    auto it = obj.find(key);
    if (it == obj.end()) fail(join(path, key), std::string("missing (expected ") + expected + ")");
    return *it;
  }

  double number(const json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, "expected a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "expected a finite number");
    return d;
  }
  double positive(const json& v, const std::string& path) const {
    const double d = number(v, path);
    if (!(d > 0)) fail(path, "expected a number above 0");
    return d;
  }
  std::string text(const json& v, const std::string& path) const {
    if (!v.is_string() || v.get<std::string>().empty()) fail(path, "expected a non-empty string");
    return v.get<std::string>();
  }
  bool boolean(const json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, "expected true or false");
    return v.get<bool>();
  }
  Eigen::Vector3d vector(const json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3) fail(path, "expected [x, y, z] (3 numbers)");
    return {number(v[0], path + "[0]"), number(v[1], path + "[1]"), number(v[2], path + "[2]")};
  }
  Eigen::Vector3d direction(const json& v, const std::string& path) const {
    const Eigen::Vector3d d = vector(v, path);
    if (!(d.norm() > 1e-12)) fail(path, "expected a direction [i, j, k] of non-zero length");
    return d.normalized();
  }

  static std::string join(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
  }
  static std::string index(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

 private:
  std::string_view source_;
};

struct KindKeys {
  FeatureKind kind;
  const char* name;
};
constexpr KindKeys kKinds[] = {{FeatureKind::Point, "point"},       {FeatureKind::Line, "line"},
                               {FeatureKind::Plane, "plane"},       {FeatureKind::Circle, "circle"},
                               {FeatureKind::Sphere, "sphere"},     {FeatureKind::Cylinder, "cylinder"},
                               {FeatureKind::Cone, "cone"}};

struct CharKeys {
  CharacteristicKind kind;
  const char* name;
};
constexpr CharKeys kCharKinds[] = {
    {CharacteristicKind::Size, "size"},
    {CharacteristicKind::Position, "position"},
    {CharacteristicKind::Distance, "distance"},
    {CharacteristicKind::Angle, "angle"},
    {CharacteristicKind::Flatness, "flatness"},
    {CharacteristicKind::Roundness, "roundness"},
    {CharacteristicKind::Cylindricity, "cylindricity"},
    {CharacteristicKind::Perpendicularity, "perpendicularity"},
    {CharacteristicKind::Parallelism, "parallelism"},
    {CharacteristicKind::Sphericity, "sphericity"}};

std::string kind_list() {
  std::string s;
  for (const auto& k : kKinds) s += (s.empty() ? "" : ", ") + std::string(k.name);
  return s;
}
std::string char_kind_list() {
  std::string s;
  for (const auto& k : kCharKinds) s += (s.empty() ? "" : ", ") + std::string(k.name);
  return s;
}

Geometry read_geometry(const Reader& r, const json& f, const std::string& path, FeatureKind kind) {
  Geometry g;
  g.kind = kind;
  auto inner = [&] {
    if (auto it = f.find("inner"); it != f.end()) g.inner = r.boolean(*it, Reader::join(path, "inner"));
  };
  switch (kind) {
    case FeatureKind::Point:
    case FeatureKind::Plane:
      r.only_keys(f, path, {"name", "type", "point", "normal", "probe", "scan", "moves"});
      g.point = r.vector(r.required(f, path, "point", "[x, y, z]"), Reader::join(path, "point"));
      g.direction = r.direction(r.required(f, path, "normal", "the outward normal [i, j, k]"), Reader::join(path, "normal"));
      break;
    case FeatureKind::Line:
      r.only_keys(f, path, {"name", "type", "point", "direction", "probe", "scan", "moves"});
      g.point = r.vector(r.required(f, path, "point", "[x, y, z]"), Reader::join(path, "point"));
      g.direction = r.direction(r.required(f, path, "direction", "[i, j, k]"), Reader::join(path, "direction"));
      break;
    case FeatureKind::Circle:
      r.only_keys(f, path, {"name", "type", "center", "normal", "diameter", "inner", "probe", "scan", "moves"});
      g.point = r.vector(r.required(f, path, "center", "[x, y, z]"), Reader::join(path, "center"));
      g.direction = r.direction(r.required(f, path, "normal", "the normal of the circle's plane [i, j, k]"),
                                Reader::join(path, "normal"));
      g.diameter = r.positive(r.required(f, path, "diameter", "a number above 0"), Reader::join(path, "diameter"));
      inner();
      break;
    case FeatureKind::Sphere:
      r.only_keys(f, path, {"name", "type", "center", "diameter", "inner", "probe", "scan", "moves"});
      g.point = r.vector(r.required(f, path, "center", "[x, y, z]"), Reader::join(path, "center"));
      g.diameter = r.positive(r.required(f, path, "diameter", "a number above 0"), Reader::join(path, "diameter"));
      inner();
      break;
    case FeatureKind::Cylinder:
    case FeatureKind::Cone:
      if (kind == FeatureKind::Cylinder)
        r.only_keys(f, path, {"name", "type", "point", "axis", "diameter", "inner", "probe", "scan", "moves"});
      else
        r.only_keys(f, path, {"name", "type", "point", "axis", "diameter", "apex_angle_deg", "inner", "probe", "scan", "moves"});
      g.point = r.vector(r.required(f, path, "point", "a point on the axis [x, y, z]"), Reader::join(path, "point"));
      g.direction = r.direction(r.required(f, path, "axis", "the axis direction [i, j, k]"), Reader::join(path, "axis"));
      g.diameter = r.positive(r.required(f, path, "diameter", "a number above 0"), Reader::join(path, "diameter"));
      if (kind == FeatureKind::Cone) {
        const std::string p = Reader::join(path, "apex_angle_deg");
        g.apex_angle_deg = r.number(r.required(f, path, "apex_angle_deg", "the full apex angle in degrees"), p);
        if (!(g.apex_angle_deg > 0 && g.apex_angle_deg < 180)) r.fail(p, "expected a full apex angle between 0 and 180 degrees");
      }
      inner();
      break;
  }
  return g;
}

ProbeTarget read_probe(const Reader& r, const json& v, const std::string& path) {
  ProbeTarget t;
  if (v.is_array()) {
    if (v.size() != 6) r.fail(path, "expected [x, y, z, i, j, k] (surface point and approach) or {\"point\", \"approach\"}");
    for (int k = 0; k < 3; ++k) t.point[k] = r.number(v[k], Reader::index(path, static_cast<std::size_t>(k)));
    Eigen::Vector3d a;
    for (int k = 0; k < 3; ++k) a[k] = r.number(v[k + 3], Reader::index(path, static_cast<std::size_t>(k + 3)));
    if (!(a.norm() > 1e-12)) r.fail(path, "the approach [i, j, k] (the last three numbers) must have non-zero length");
    t.approach = a.normalized();
    return t;
  }
  if (!v.is_object()) r.fail(path, "expected [x, y, z, i, j, k] or {\"point\": [x, y, z], \"approach\": [i, j, k]}");
  r.only_keys(v, path, {"point", "approach"});
  t.point = r.vector(r.required(v, path, "point", "[x, y, z]"), Reader::join(path, "point"));
  t.approach = r.direction(r.required(v, path, "approach", "the probing direction [i, j, k]"), Reader::join(path, "approach"));
  return t;
}

std::string plan_number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A number in [lo, hi], the range messd accepts for the same parameter.
double in_range(const Reader& r, const json& v, const std::string& path, double lo, double hi, const char* unit) {
  const double d = r.number(v, path);
  if (!(d >= lo && d <= hi))
    r.fail(path, "expected " + plan_number_text(lo) + " … " + plan_number_text(hi) + " " + unit);
  return d;
}

bool is_round(FeatureKind k) {
  return k == FeatureKind::Circle || k == FeatureKind::Sphere || k == FeatureKind::Cylinder || k == FeatureKind::Cone;
}

// `"circle": {center, axis, start, sweep, surface}`: the centre, axis and side default to a
// round feature's own.
void read_scan_circle(const Reader& r, const json& c, const std::string& path, const Geometry& g, ScanPath& s) {
  if (!c.is_object()) r.fail(path, "expected {\"start\": [x, y, z], \"center\", \"axis\", \"sweep\", \"surface\"}");
  r.only_keys(c, path, {"center", "axis", "start", "sweep", "surface"});
  s.kind = ScanPath::Kind::Circle;
  const bool round = is_round(g.kind);
  const bool has_axis = g.kind == FeatureKind::Circle || g.kind == FeatureKind::Cylinder || g.kind == FeatureKind::Cone;
  if (auto it = c.find("center"); it != c.end()) s.center = r.vector(*it, Reader::join(path, "center"));
  else if (round) s.center = g.point;
  else r.fail(Reader::join(path, "center"), "missing (expected a point on the scan's axis [x, y, z]; only a circle, sphere, cylinder or cone gives its own)");
  if (auto it = c.find("axis"); it != c.end()) s.axis = r.direction(*it, Reader::join(path, "axis"));
  else if (has_axis) s.axis = g.direction;
  else r.fail(Reader::join(path, "axis"), "missing (expected the axis [i, j, k] the scan goes round; only a circle, cylinder or cone gives its own)");
  s.start = r.vector(r.required(c, path, "start", "the surface point the scan starts at [x, y, z]"), Reader::join(path, "start"));
  const Eigen::Vector3d off = s.start - s.center;
  if (!((off - off.dot(s.axis) * s.axis).norm() > 1e-6))
    r.fail(Reader::join(path, "start"), "the start lies on the scan's axis; expected a surface point off it (its distance from the axis is the scan's radius)");
  if (auto it = c.find("sweep"); it != c.end()) {
    s.sweep_deg = in_range(r, *it, Reader::join(path, "sweep"), -36000, 36000, "degrees (right hand about the axis)");
    if (s.sweep_deg == 0) r.fail(Reader::join(path, "sweep"), "expected a sweep other than 0 degrees");
  }
  if (auto it = c.find("surface"); it != c.end()) {
    const std::string side = r.text(*it, Reader::join(path, "surface"));
    if (side != "bore" && side != "boss")
      r.fail(Reader::join(path, "surface"), "expected \"bore\" (the surface faces the axis) or \"boss\" (it faces away)");
    s.bore = side == "bore";
  } else if (round) {
    s.bore = g.inner;
  } else {
    r.fail(Reader::join(path, "surface"), "missing (expected \"bore\" or \"boss\"; a circle, sphere, cylinder or cone gives its own by inner)");
  }
}

// `"line": {from, to, normal}`: the normal defaults to a plane's or point's own.
void read_scan_line(const Reader& r, const json& l, const std::string& path, const Geometry& g, ScanPath& s) {
  if (!l.is_object()) r.fail(path, "expected {\"from\": [x, y, z], \"to\": [x, y, z], \"normal\": [i, j, k]}");
  r.only_keys(l, path, {"from", "to", "normal"});
  s.kind = ScanPath::Kind::Line;
  s.start = r.vector(r.required(l, path, "from", "the surface point the scan starts at [x, y, z]"), Reader::join(path, "from"));
  s.end = r.vector(r.required(l, path, "to", "the surface point the scan ends at [x, y, z]"), Reader::join(path, "to"));
  if (!((s.end - s.start).norm() > 1e-6)) r.fail(Reader::join(path, "to"), "expected an end other than the start");
  if (auto it = l.find("normal"); it != l.end()) s.normal = r.direction(*it, Reader::join(path, "normal"));
  else if (g.kind == FeatureKind::Plane || g.kind == FeatureKind::Point) s.normal = g.direction;
  else r.fail(Reader::join(path, "normal"), "missing (expected the surface's outward normal [i, j, k]; only a plane or point gives its own)");
  const Eigen::Vector3d along = (s.end - s.start).normalized();
  const Eigen::Vector3d across = s.normal - s.normal.dot(along) * along;
  if (!(across.norm() > 1e-6)) r.fail(Reader::join(path, "normal"), "the normal runs along the line; expected the outward normal of the surface the line lies on");
  s.normal = across.normalized();
}

ScanPath read_scan(const Reader& r, const json& v, const std::string& path, const Geometry& g) {
  const char* expected = "expected {\"circle\": {…}} or {\"line\": {…}}, with optional \"step\" and \"speed\"";
  if (!v.is_object()) r.fail(path, expected);
  r.only_keys(v, path, {"circle", "line", "step", "speed"});
  ScanPath s;
  const auto circle = v.find("circle"), line = v.find("line");
  if ((circle == v.end()) == (line == v.end())) r.fail(path, std::string(expected) + " (one of circle and line)");
  if (circle != v.end()) read_scan_circle(r, *circle, Reader::join(path, "circle"), g, s);
  else read_scan_line(r, *line, Reader::join(path, "line"), g, s);
  if (auto it = v.find("step"); it != v.end()) s.step = in_range(r, *it, Reader::join(path, "step"), 0.001, 100, "mm between points");
  if (auto it = v.find("speed"); it != v.end()) s.speed = in_range(r, *it, Reader::join(path, "speed"), 0.1, 100, "mm/s");
  return s;
}

PlanFeature read_feature(const Reader& r, const json& f, const std::string& path) {
  if (!f.is_object()) r.fail(path, "expected an object with name, type and the feature's geometry");
  PlanFeature out;
  out.name = r.text(r.required(f, path, "name", "a string"), Reader::join(path, "name"));
  const std::string type = r.text(r.required(f, path, "type", kind_list().c_str()), Reader::join(path, "type"));
  const KindKeys* kind = nullptr;
  for (const auto& k : kKinds)
    if (type == k.name) kind = &k;
  if (!kind) r.fail(Reader::join(path, "type"), "'" + type + "' is not a feature type; expected one of " + kind_list());
  out.nominal = read_geometry(r, f, path, kind->kind);
  if (auto it = f.find("probe"); it != f.end()) {
    const std::string p = Reader::join(path, "probe");
    if (!it->is_array()) r.fail(p, "expected an array of probe points");
    for (std::size_t i = 0; i < it->size(); ++i) out.probes.push_back(read_probe(r, (*it)[i], Reader::index(p, i)));
  }
  if (auto it = f.find("scan"); it != f.end()) {
    const std::string p = Reader::join(path, "scan");
    if (it->is_array()) {
      if (it->empty()) r.fail(p, "expected a scan or a non-empty array of scans");
      for (std::size_t i = 0; i < it->size(); ++i) out.scans.push_back(read_scan(r, (*it)[i], Reader::index(p, i), out.nominal));
    } else {
      out.scans.push_back(read_scan(r, *it, p, out.nominal));
    }
  }
  if (auto it = f.find("moves"); it != f.end()) {
    const std::string m = r.text(*it, Reader::join(path, "moves"));
    if (m != "direct" && m != "lift") r.fail(Reader::join(path, "moves"), "expected \"direct\" or \"lift\"");
    out.lift_between = m == "lift";
  }
  return out;
}

// Which feature kinds each characteristic applies to (for the feature; the datum / second feature
// is checked separately).
bool applies(CharacteristicKind c, FeatureKind f) {
  using C = CharacteristicKind;
  using F = FeatureKind;
  switch (c) {
    case C::Size: return f == F::Circle || f == F::Sphere || f == F::Cylinder || f == F::Cone;
    case C::Position: return f != F::Plane;
    case C::Distance: return true;
    case C::Angle: return f != F::Point && f != F::Sphere;
    case C::Flatness: return f == F::Plane;
    case C::Roundness: return f == F::Circle;
    case C::Cylindricity: return f == F::Cylinder;
    case C::Sphericity: return f == F::Sphere;
    case C::Perpendicularity:
    case C::Parallelism: return f == F::Plane || f == F::Line || f == F::Cylinder || f == F::Cone;
  }
  return false;
}
const char* applies_text(CharacteristicKind c) {
  using C = CharacteristicKind;
  switch (c) {
    case C::Size: return "a circle, sphere, cylinder or cone";
    case C::Position: return "a point, line, circle, sphere, cylinder or cone";
    case C::Distance: return "any feature";
    case C::Angle: return "a line, plane, circle, cylinder or cone";
    case C::Flatness: return "a plane";
    case C::Roundness: return "a circle";
    case C::Cylindricity: return "a cylinder";
    case C::Sphericity: return "a sphere";
    case C::Perpendicularity:
    case C::Parallelism: return "a plane, line, cylinder or cone";
  }
  return "";
}

Characteristic read_characteristic(const Reader& r, const json& c, const std::string& path, const InspectionPlan& plan) {
  using C = CharacteristicKind;
  if (!c.is_object()) r.fail(path, "expected an object with name, type, the feature(s) and a tolerance");
  Characteristic out;
  out.name = r.text(r.required(c, path, "name", "a string"), Reader::join(path, "name"));
  const std::string type = r.text(r.required(c, path, "type", char_kind_list().c_str()), Reader::join(path, "type"));
  const CharKeys* kind = nullptr;
  for (const auto& k : kCharKinds)
    if (type == k.name) kind = &k;
  if (!kind) r.fail(Reader::join(path, "type"), "'" + type + "' is not a characteristic type; expected one of " + char_kind_list());
  out.kind = kind->kind;

  auto known_feature = [&](const std::string& name, const std::string& at) -> const PlanFeature& {
    const PlanFeature* f = plan.find(name);
    if (!f) r.fail(at, "no feature named '" + name + "' in the plan");
    return *f;
  };
  const bool pair = out.kind == C::Distance || out.kind == C::Angle;
  const bool datum = out.kind == C::Perpendicularity || out.kind == C::Parallelism;
  if (pair) {
    r.only_keys(c, path, {"name", "type", "features", "nominal", "tolerance"});
    const std::string p = Reader::join(path, "features");
    const json& fs = r.required(c, path, "features", "[\"first\", \"second\"] (two feature names)");
    if (!fs.is_array() || fs.size() != 2) r.fail(p, "expected [\"first\", \"second\"] (two feature names)");
    out.feature = r.text(fs[0], p + "[0]");
    out.other = r.text(fs[1], p + "[1]");
    if (out.feature == out.other) r.fail(p, "expected two different features");
  } else {
    if (datum)
      r.only_keys(c, path, {"name", "type", "feature", "datum", "tolerance"});
    else if (out.kind == C::Size)
      r.only_keys(c, path, {"name", "type", "feature", "nominal", "radius", "tolerance"});
    else
      r.only_keys(c, path, {"name", "type", "feature", "tolerance"});
    out.feature = r.text(r.required(c, path, "feature", "a feature name"), Reader::join(path, "feature"));
    if (datum) {
      out.other = r.text(r.required(c, path, "datum", "the datum feature's name"), Reader::join(path, "datum"));
      if (out.other == out.feature) r.fail(Reader::join(path, "datum"), "the datum must be another feature");
    }
  }
  const std::string fpath = Reader::join(path, pair ? "features[0]" : "feature");
  const PlanFeature& f = known_feature(out.feature, fpath);
  if (!applies(out.kind, f.nominal.kind))
    r.fail(fpath, type + " applies to " + applies_text(out.kind) + ", and '" + f.name + "' is a " +
                      std::string(to_string(f.nominal.kind)));
  if (!out.other.empty()) {
    const std::string opath = Reader::join(path, pair ? "features[1]" : "datum");
    const PlanFeature& o = known_feature(out.other, opath);
    const FeatureKind k = o.nominal.kind;
    const bool ok = out.kind == C::Distance ? true
                    : out.kind == C::Angle  ? applies(C::Angle, k)
                                            : (applies(C::Parallelism, k) || k == FeatureKind::Circle);
    if (!ok)
      r.fail(opath, "'" + o.name + "' is a " + std::string(to_string(k)) + "; " + type + " needs " +
                        (out.kind == C::Angle ? "a line, plane, circle, cylinder or cone"
                                              : "a datum plane, line, circle, cylinder or cone"));
  }
  if (auto it = c.find("radius"); it != c.end()) {
    out.radius = r.boolean(*it, Reader::join(path, "radius"));
    if (out.radius && f.nominal.kind == FeatureKind::Cone)
      r.fail(Reader::join(path, "radius"), "a cone's size is its diameter; radius is for circles, spheres and cylinders");
  }
  if (auto it = c.find("nominal"); it != c.end()) out.nominal = r.number(*it, Reader::join(path, "nominal"));

  const std::string tpath = Reader::join(path, "tolerance");
  const json& t = r.required(c, path, "tolerance", is_zone(out.kind) ? "the zone width, a number above 0"
                                                                      : "t (for ±t) or [lower, upper]");
  if (is_zone(out.kind)) {
    if (!t.is_number()) r.fail(tpath, "a " + type + " tolerance is one zone width, a number above 0");
    out.upper = r.positive(t, tpath);
  } else if (t.is_array()) {
    if (t.size() != 2) r.fail(tpath, "expected [lower, upper] (limits of the deviation)");
    out.lower = r.number(t[0], tpath + "[0]");
    out.upper = r.number(t[1], tpath + "[1]");
    if (!(out.lower < out.upper)) r.fail(tpath, "expected lower < upper");
  } else {
    const double v = r.positive(t, tpath);
    out.lower = -v;
    out.upper = v;
  }
  return out;
}

bool feature_is(const InspectionPlan& plan, const std::string& name, std::initializer_list<FeatureKind> kinds) {
  const PlanFeature* f = plan.find(name);
  if (!f) return false;
  for (auto k : kinds)
    if (f->nominal.kind == k) return true;
  return false;
}

Alignment321 read_alignment(const Reader& r, const json& a, const InspectionPlan& plan) {
  const std::string path = "alignment";
  if (!a.is_object()) r.fail(path, "expected {\"primary\": plane, \"secondary\": plane or line, \"tertiary\": point, plane, circle or sphere}");
  r.only_keys(a, path, {"primary", "secondary", "tertiary"});
  Alignment321 out;
  out.primary = r.text(r.required(a, path, "primary", "a plane feature's name"), "alignment.primary");
  out.secondary = r.text(r.required(a, path, "secondary", "a plane or line feature's name"), "alignment.secondary");
  out.tertiary = r.text(r.required(a, path, "tertiary", "a point, plane, circle or sphere feature's name"), "alignment.tertiary");
  using F = FeatureKind;
  if (!feature_is(plan, out.primary, {F::Plane})) r.fail("alignment.primary", "expected the name of a plane feature");
  if (!feature_is(plan, out.secondary, {F::Plane, F::Line}))
    r.fail("alignment.secondary", "expected the name of a plane or line feature");
  if (!feature_is(plan, out.tertiary, {F::Point, F::Plane, F::Circle, F::Sphere}))
    r.fail("alignment.tertiary", "expected the name of a point, plane, circle or sphere feature");
  if (out.primary == out.secondary || out.primary == out.tertiary || out.secondary == out.tertiary)
    r.fail("alignment", "primary, secondary and tertiary must be three different features");
  return out;
}

Frame read_placement(const Reader& r, const json& p) {
  const std::string path = "placement";
  if (!p.is_object()) r.fail(path, "expected {\"origin\": [x, y, z], \"x_axis\": [i, j, k], \"z_axis\": [i, j, k]}");
  r.only_keys(p, path, {"origin", "x_axis", "z_axis"});
  const Eigen::Vector3d origin = r.vector(r.required(p, path, "origin", "[x, y, z] in machine coordinates"), "placement.origin");
  Eigen::Vector3d x = Eigen::Vector3d::UnitX(), z = Eigen::Vector3d::UnitZ();
  if (auto it = p.find("x_axis"); it != p.end()) x = r.direction(*it, "placement.x_axis");
  if (auto it = p.find("z_axis"); it != p.end()) z = r.direction(*it, "placement.z_axis");
  if (std::abs(x.dot(z)) > 1e-6) r.fail(path, "x_axis and z_axis must be perpendicular (their cosine is " + std::to_string(x.dot(z)) + ")");
  Eigen::Matrix3d rot;
  rot.col(0) = x;
  rot.col(1) = z.cross(x);
  rot.col(2) = z;
  return Frame::orthonormalised(rot, origin);
}

ProbingSettings read_probing(const Reader& r, const json& p) {
  const std::string path = "probing";
  if (!p.is_object()) r.fail(path, "expected an object (clearance, safe_z, feed, tip_radius, search)");
  r.only_keys(p, path, {"clearance", "safe_z", "feed", "tip_radius", "search"});
  ProbingSettings s;
  if (auto it = p.find("clearance"); it != p.end()) s.clearance = r.positive(*it, "probing.clearance");
  if (auto it = p.find("safe_z"); it != p.end()) s.safe_z = r.number(*it, "probing.safe_z");
  if (auto it = p.find("feed"); it != p.end()) s.feed = r.positive(*it, "probing.feed");
  if (auto it = p.find("search"); it != p.end()) s.search = r.positive(*it, "probing.search");
  if (auto it = p.find("tip_radius"); it != p.end()) {
    const double v = r.number(*it, "probing.tip_radius");
    if (v < 0 || v > 50) r.fail("probing.tip_radius", "expected a radius of 0 … 50 mm");
    s.tip_radius = v;
  }
  return s;
}

}  // namespace

std::string_view to_string(FeatureKind kind) noexcept {
  for (const auto& k : kKinds)
    if (k.kind == kind) return k.name;
  return "?";
}

std::string_view to_string(CharacteristicKind kind) noexcept {
  for (const auto& k : kCharKinds)
    if (k.kind == kind) return k.name;
  return "?";
}

bool is_zone(CharacteristicKind kind) noexcept {
  using C = CharacteristicKind;
  return !(kind == C::Size || kind == C::Distance || kind == C::Angle);
}

const PlanFeature* InspectionPlan::find(std::string_view name) const {
  for (const auto& f : features)
    if (f.name == name) return &f;
  return nullptr;
}

const PlanFeature& InspectionPlan::feature(std::string_view name) const {
  if (const PlanFeature* f = find(name)) return *f;
  throw std::out_of_range("no feature named '" + std::string(name) + "'");
}

InspectionPlan parse_inspection_plan(std::string_view json_text, std::string_view source) {
  const Reader r(source);
  json doc;
  try {
    doc = jsontext::parse_strict(json_text, source);
  } catch (const jsontext::JsonTextError& e) {
    throw InspectionPlanError(e.what());
  }
  if (!doc.is_object()) r.fail("(top level)", "expected an object with part, features and characteristics");
  r.only_keys(doc, "", {"part", "placement", "probing", "alignment", "features", "characteristics", "_comment"});
  InspectionPlan plan;
  plan.part = r.text(r.required(doc, "", "part", "the part's name"), "part");
  if (auto it = doc.find("placement"); it != doc.end()) plan.placement = read_placement(r, *it);
  if (auto it = doc.find("probing"); it != doc.end()) plan.probing = read_probing(r, *it);

  const json& fs = r.required(doc, "", "features", "an array of features");
  if (!fs.is_array() || fs.empty()) r.fail("features", "expected a non-empty array of features");
  std::set<std::string> names;
  for (std::size_t i = 0; i < fs.size(); ++i) {
    PlanFeature f = read_feature(r, fs[i], Reader::index("features", i));
    if (!names.insert(f.name).second) r.fail(Reader::index("features", i) + ".name", "'" + f.name + "' is used twice");
    plan.features.push_back(std::move(f));
  }
  if (auto it = doc.find("alignment"); it != doc.end()) plan.alignment = read_alignment(r, *it, plan);

  const json& cs = r.required(doc, "", "characteristics", "an array of characteristics");
  if (!cs.is_array()) r.fail("characteristics", "expected an array of characteristics");
  std::set<std::string> char_names;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    Characteristic c = read_characteristic(r, cs[i], Reader::index("characteristics", i), plan);
    if (!char_names.insert(c.name).second)
      r.fail(Reader::index("characteristics", i) + ".name", "'" + c.name + "' is used twice");
    plan.characteristics.push_back(std::move(c));
  }
  return plan;
}

}  // namespace imess::metrology
