// Strict configuration reading.
#include "json_object.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace imess::app {

std::string compact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

JsonObject::JsonObject(const nlohmann::json& j, std::string file, std::string path)
    : j_(j), file_(std::move(file)), path_(std::move(path)) {
  if (!j_.is_object())
    throw ConfigError(file_ + ": '" + (path_.empty() ? std::string("the top level") : path_) +
                      "' must be a JSON object { ... }");
}

void JsonObject::fail(const std::string& key, const std::string& expected) const {
  std::string got = j_.contains(key) ? j_.at(key).dump() : "nothing";
  if (got.size() > 60) got = got.substr(0, 57) + "...";
  throw ConfigError(file_ + ": key '" + where(key) + "' must be " + expected + ", got " + got);
}

double JsonObject::number(const std::string& key, double def, double min, double max) {
  read_.insert(key);
  if (!j_.contains(key)) return def;
  const auto& v = j_.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < min || v.get<double>() > max)
    fail(key, "a number from " + compact(min) + " to " + compact(max));
  return v.get<double>();
}

long long JsonObject::whole(const std::string& key, long long def, long long min, long long max) {
  read_.insert(key);
  if (!j_.contains(key)) return def;
  const auto& v = j_.at(key);
  const double d = v.is_number() ? v.get<double>() : 0;
  if (!v.is_number() || !std::isfinite(d) || d < double(min) || d > double(max) || d != std::floor(d))
    fail(key, "a whole number from " + std::to_string(min) + " to " + std::to_string(max));
  return static_cast<long long>(d);
}

bool JsonObject::boolean(const std::string& key, bool def) {
  read_.insert(key);
  if (!j_.contains(key)) return def;
  if (!j_.at(key).is_boolean()) fail(key, "true or false");
  return j_.at(key).get<bool>();
}

std::string JsonObject::text(const std::string& key, const std::string& def, const std::vector<std::string>& allowed) {
  read_.insert(key);
  if (!j_.contains(key)) return def;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
  if (!j_.at(key).is_string()) fail(key, allowed.empty() ? "a string" : "one of " + list);
  auto s = j_.at(key).get<std::string>();
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end()) fail(key, "one of " + list);
  return s;
}

hal::Vec3 JsonObject::vec3(const std::string& key, const hal::Vec3& def, double limit) {
  read_.insert(key);
  if (!j_.contains(key)) return def;
  const auto& v = j_.at(key);
  const std::string expected = "an array of three numbers [x, y, z], each from " + compact(-limit) + " to " + compact(limit);
  if (!v.is_array() || v.size() != 3) fail(key, expected);
  hal::Vec3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!v[i].is_number()) fail(key, expected);
    out[static_cast<int>(i)] = v[i].get<double>();
    if (!std::isfinite(out[static_cast<int>(i)]) || std::abs(out[static_cast<int>(i)]) > limit) fail(key, expected);
  }
  return out;
}

hal::AxisVec JsonObject::axis_values(const std::string& key, const hal::AxisVec& def, const hal::AxisLayout& layout,
                                     double limit) {
  if (layout.is_xyz()) {
    hal::AxisVec out = def;
    out.head<3>() = vec3(key, def.head<3>(), limit);
    return out;
  }
  read_.insert(key);
  if (!j_.contains(key)) return def;
  const auto& v = j_.at(key);
  const auto n = static_cast<std::size_t>(layout.count);
  std::string names;
  for (std::size_t i = 0; i < n; ++i) names += std::string(i ? ", " : "") + layout.letters[i];
  const std::string expected = "an array of " + std::to_string(n) + " numbers [" + names + "] (the axes' order), each from " +
                               compact(-limit) + " to " + compact(limit);
  if (!v.is_array() || v.size() != n) fail(key, expected);
  hal::AxisVec out = hal::AxisVec::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    if (!v[i].is_number()) fail(key, expected);
    const double x = v[i].get<double>();
    if (!std::isfinite(x) || std::abs(x) > limit) fail(key, expected);
    out[static_cast<int>(i)] = x;
  }
  return out;
}

std::optional<std::vector<std::string>> JsonObject::texts(const std::string& key, const std::string& expected) {
  read_.insert(key);
  if (!j_.contains(key)) return std::nullopt;
  const auto& v = j_.at(key);
  if (!v.is_array()) fail(key, "an array of strings, each " + expected);
  std::vector<std::string> out;
  for (const auto& e : v) {
    if (!e.is_string()) fail(key, "an array of strings, each " + expected);
    out.push_back(e.get<std::string>());
  }
  return out;
}

std::optional<JsonObject> JsonObject::object(const std::string& key) {
  read_.insert(key);
  if (!j_.contains(key)) return std::nullopt;
  if (!j_.at(key).is_object()) fail(key, "an object { ... }");
  return JsonObject(j_.at(key), file_, where(key));
}

std::optional<std::vector<JsonObject>> JsonObject::objects(const std::string& key) {
  read_.insert(key);
  if (!j_.contains(key)) return std::nullopt;
  if (!j_.at(key).is_array()) fail(key, "an array of objects [ {...}, ... ]");
  std::vector<JsonObject> out;
  for (std::size_t i = 0; i < j_.at(key).size(); ++i)
    out.emplace_back(j_.at(key)[i], file_, where(key) + "[" + std::to_string(i) + "]");
  return out;
}

std::vector<std::string> JsonObject::keys() const {
  std::vector<std::string> out;
  for (auto it = j_.begin(); it != j_.end(); ++it) out.push_back(it.key());
  return out;
}

void JsonObject::finish(const std::string& accepted) const {
  for (auto it = j_.begin(); it != j_.end(); ++it) {
    if (read_.count(it.key())) continue;
    std::string known = accepted;
    for (const auto& k : read_)
      if (accepted.empty() && k != "_comment") known += (known.empty() ? "" : ", ") + k;
    std::string key = where(it.key());
    if (key.size() > 80) key = key.substr(0, 77) + "...";
    throw ConfigError(file_ + ": unknown key '" + key + "'; accepted here: " + (known.empty() ? "none" : known) +
                      " (docs/configuration.md)");
  }
}

}  // namespace imess::app
