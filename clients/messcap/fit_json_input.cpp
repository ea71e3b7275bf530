// parse_fit_json(): nlohmann parses, then each field the kind needs is checked to be three
// finite numbers (a direction also non-zero) so a relation never works on half a feature.
#include "fit_json_input.hpp"

#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"

namespace imess::messcap {
namespace {

using Eigen::Vector3d;
using exchange::FitKind;
using nlohmann::json;

struct Reader {
  const json& object;
  const std::string& source;
  std::string_view kind;

  [[noreturn]] void fail(const std::string& what) const { throw FitJsonError(source + ": " + what); }

  Vector3d vector(const char* key) const {
    auto it = object.find(key);
    if (it == object.end())
      fail("a fitted " + std::string(kind) + " needs '" + key + "' (as messcap fit prints it); it is missing");
    const json& v = *it;
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
      fail("'" + std::string(key) + "' must be three numbers [x, y, z], not " + v.dump());
    Vector3d out(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    if (!out.allFinite()) fail("'" + std::string(key) + "' must be finite, not " + v.dump());
    return out;
  }

  Vector3d direction(const char* key) const {
    Vector3d d = vector(key);
    if (!(d.norm() > 1e-12)) fail("'" + std::string(key) + "' must be a direction, not the zero vector");
    return d.normalized();
  }

  std::optional<double> number(const char* key) const {
    auto it = object.find(key);
    if (it == object.end()) return std::nullopt;
    if (!it->is_number() || !std::isfinite(it->get<double>()))
      fail("'" + std::string(key) + "' must be a finite number, not " + it->dump());
    return it->get<double>();
  }
};

}  // namespace

exchange::FitReport parse_fit_json(std::string_view text, const std::string& source) {
  json object;
  try {
    object = jsontext::parse_strict(text, source);
  } catch (const jsontext::JsonTextError& e) {
    throw FitJsonError(std::string(e.what()) + "; expected one object as messcap fit prints it");
  }
  if (!object.is_object())
    throw FitJsonError(source + ": expected one JSON object as messcap fit prints it, not " + std::string(object.type_name()));
  auto type = object.find("type");
  if (type == object.end() || !type->is_string())
    throw FitJsonError(source + ": the object has no \"type\" word; accepted: " + std::string(exchange::kFitKinds));
  exchange::FitReport r;
  try {
    r.kind = exchange::parse_fit_kind(type->get<std::string>());
  } catch (const exchange::FitKindError& e) {
    throw FitJsonError(source + ": " + e.what());
  }
  const Reader in{object, source, exchange::to_string(r.kind)};
  switch (r.kind) {
    case FitKind::Line:
    case FitKind::Line2d:
      r.point = in.vector("point");
      r.direction = in.direction("direction");
      break;
    case FitKind::Plane:
      r.point = in.vector("point");
      r.normal = in.direction("normal");
      break;
    case FitKind::Circle:
    case FitKind::Circle2d:
      r.center = in.vector("center");
      r.normal = in.direction("normal");
      break;
    case FitKind::Sphere:
      r.center = in.vector("center");
      break;
    case FitKind::Cylinder:
    case FitKind::Cone:
      r.point = in.vector("point");
      r.axis = in.direction("axis");
      break;
  }
  r.diameter = in.number("diameter");
  return r;
}

}  // namespace imess::messcap
