// JsonObject: strict reading of one configuration object — typed getters with defaults and
// ranges, and finish() rejecting any key that was not read. Errors name file, key and form.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "imess/hal/types.hpp"

namespace imess::app {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A number as people write it in messages: %g ("0.1", "1000", "1e+06").
std::string compact(double v);

class JsonObject {
 public:
  JsonObject(const nlohmann::json& j, std::string file, std::string path);

  double number(const std::string& key, double def, double min, double max);
  // A whole number (1066 or 1066.0) from min to max.
  long long whole(const std::string& key, long long def, long long min, long long max);
  bool boolean(const std::string& key, bool def);
  std::string text(const std::string& key, const std::string& def, const std::vector<std::string>& allowed = {});
  // Three numbers [x, y, z], each from -limit to limit.
  hal::Vec3 vec3(const std::string& key, const hal::Vec3& def, double limit = 1e6);
  // One number per axis of the layout, in its order ([x, y, z] on the X Y Z machine: vec3's
  // form and message), each from -limit to limit.
  hal::AxisVec axis_values(const std::string& key, const hal::AxisVec& def, const hal::AxisLayout& layout, double limit = 1e6);
  // Array of strings (may be absent: nullopt); `expected` describes an entry for the error.
  std::optional<std::vector<std::string>> texts(const std::string& key, const std::string& expected);
  std::optional<JsonObject> object(const std::string& key);
  // Array of objects (may be absent: nullopt).
  std::optional<std::vector<JsonObject>> objects(const std::string& key);
  bool has(const std::string& key) const { return j_.contains(key); }
  // Every key of the object, in the file's order as the JSON library keeps it (sorted).
  std::vector<std::string> keys() const;
  // Marks a key read by hand (has / is_*) rather than by a typed getter: accepted here.
  void accept(const std::string& key) { read_.insert(key); }
  bool is_string(const std::string& key) const { return has(key) && j_.at(key).is_string(); }
  bool is_number(const std::string& key) const { return has(key) && j_.at(key).is_number(); }
  bool is_object(const std::string& key) const { return has(key) && j_.at(key).is_object(); }
  // Throws for keys present but never read, listing the keys read here (those accepted) or,
  // when given, `accepted` (for objects whose keys are not all read by name).
  void finish(const std::string& accepted = "") const;
  [[noreturn]] void fail(const std::string& key, const std::string& expected) const;
  std::string where(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

 private:
  const nlohmann::json& j_;
  std::string file_, path_;
  std::set<std::string> read_;
};

}  // namespace imess::app
