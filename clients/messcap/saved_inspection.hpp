// A run of messcap inspect as its JSON report holds it (docs/metrology.md §17): what the QIF
// writer needs — part, time, machine, operator, the features (nominal and fitted geometry, part
// coordinates), the characteristics (limits, nominal, actual, deviation, verdict) and the points.
// `messcap inspect --qif` reads back the report it has just made, `messcap convert` a saved one,
// so both QIF documents come from the same figures as the JSON.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace imess::messcap {

// "<source>: <key path>: <what was expected>" (e.g. "cube.json: characteristics[3].actual:
// expected a number").
class SavedInspectionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SavedGeometry {
  std::string type;  // point, line, plane, circle, sphere, cylinder, cone
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      // point / centre / point on the axis
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ(); // normal / direction / axis (sphere: unused)
  double diameter = 0.0;
  double apex_angle_deg = 0.0;                           // cone
  bool inner = false;
};

struct SavedFeature {
  std::string name;
  std::size_t points = 0;
  SavedGeometry nominal;
  std::optional<SavedGeometry> actual;  // none: the fit failed
  bool compensated = false;
  double form = 0.0;
};

struct SavedCharacteristic {
  std::string name, type;          // type: size, position, distance, angle, flatness, ...
  std::string feature, other;      // other: the second feature (distance, angle) or the datum
  std::string unit;                // mm or deg
  bool zone = false, radius = false;
  double lower = 0.0, upper = 0.0;
  std::optional<double> nominal, actual, deviation;  // none: not evaluated
  bool in_tolerance = false;
  std::string error;
};

struct SavedPoint {
  std::string feature;
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();  // part coordinates, compensated
  double deviation = 0.0;
  std::optional<double> radius;                   // the tip radius, when the point was a hit
};

struct SavedInspection {
  std::string part, plan, measured;
  std::string time;      // ISO 8601 UTC; empty in reports written before it was recorded
  std::string machine;   // "messd at HOST:PORT" when measured live
  std::string operator_name;
  std::vector<std::string> datums;  // the 3-2-1 alignment's features, empty: nominal placement
  std::vector<SavedFeature> features;
  std::vector<SavedCharacteristic> characteristics;
  std::vector<SavedPoint> points;
};

// Parses and checks a report: every key the QIF needs present with its type, features and
// characteristics named uniquely, every referenced feature present. Throws SavedInspectionError.
SavedInspection parse_saved_inspection(std::string_view json_text, std::string_view source = "<report>");

}  // namespace imess::messcap
