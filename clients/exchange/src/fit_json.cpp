// to_json(FitReport): the one-line JSON object `messcap fit` prints (key order fixed).
#include <nlohmann/json.hpp>

#include "imess/exchange/fit_report.hpp"

namespace imess::exchange {
namespace {

nlohmann::ordered_json array(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

std::string to_json(const FitReport& r) {
  nlohmann::ordered_json j;
  j["type"] = std::string(to_string(r.kind));
  if (r.point) j["point"] = array(*r.point);
  if (r.direction) j["direction"] = array(*r.direction);
  if (r.normal) j["normal"] = array(*r.normal);
  if (r.center) j["center"] = array(*r.center);
  if (r.axis) j["axis"] = array(*r.axis);
  if (r.diameter) j["diameter"] = *r.diameter;
  if (r.apex) j["apex"] = array(*r.apex);
  if (r.apex_angle_deg) j["apex_angle_deg"] = *r.apex_angle_deg;
  j["rms"] = r.rms;
  j["form_min"] = r.form_min;
  j["form_max"] = r.form_max;
  j["n"] = r.n;
  return j.dump();
}

}  // namespace imess::exchange
