// Terminal lines and JSON of messcap qualify (qualify_report.hpp).
#include "qualify_report.hpp"

#include "number_text.hpp"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace imess::messcap {
namespace {

using nlohmann::json;

std::string fixed(double v, int decimals) { return fixed_text(v, decimals); }
std::string triple(const Eigen::Vector3d& v, int decimals) {
  return fixed(v.x(), decimals) + " " + fixed(v.y(), decimals) + " " + fixed(v.z(), decimals);
}

double nm(double v) { return std::round(v * 1e6) / 1e6; }
json vec(const Eigen::Vector3d& v) { return json::array({nm(v.x()), nm(v.y()), nm(v.z())}); }

}  // namespace

void print_qualify_report(std::ostream& out, const QualifyReport& r) {
  const Qualification& q = r.result;
  out << "sphere        " << triple(r.sphere.centre, 4) << "  diameter " << fixed(r.sphere.diameter, 4) << " mm\n"
      << "touches       " << q.centres.size() << " (" << q.centres.size() - 1 << " on the ring, the pole)\n"
      << "tip radius    " << fixed(q.tip_radius, 6) << " mm   (was " << fixed(r.touches.tip_radius, 6) << ")\n"
      << "offset        " << triple(q.offset, 6) << " mm   (was " << triple(r.touches.offset, 6) << ")\n"
      << "centre        " << triple(q.centre_fit.center, 6) << " mm   (fitted; nominal - fitted "
      << triple(q.shift, 6) << ")\n"
      << "form          " << fixed(q.form, 6) << " mm   (limit " << fixed(r.limits.max_form, 6) << ", rms "
      << fixed(q.centre_fit.stats.rms, 6) << ")\n"
      << "residuals um ";
  for (double e : q.residuals) out << " " << fixed(e * 1000, 2);
  out << "\n";
}

std::string qualify_json(const QualifyReport& r) {
  const Qualification& q = r.result;
  json touches = json::array();
  for (std::size_t i = 0; i < q.centres.size(); ++i) {
    const auto& h = r.touches.hits[i];
    touches.push_back({{"surface", vec(h.surface)},
                       {"approach", json::array({h.approach.x(), h.approach.y(), h.approach.z()})},
                       {"radius", nm(h.radius)},
                       {"centre", vec(q.centres[i])},
                       {"residual", nm(q.residuals[i])}});
  }
  json j = {{"units", "mm"},
            {"sphere", {{"centre", vec(r.sphere.centre)}, {"diameter", nm(r.sphere.diameter)}}},
            {"touches", touches},
            {"fit", {{"centre", vec(q.centre_fit.center)}, {"diameter", nm(q.centre_fit.diameter)},
                     {"rms", nm(q.centre_fit.stats.rms)}}},
            {"tip_radius", nm(q.tip_radius)},
            {"offset", vec(q.offset)},
            {"form", nm(q.form)},
            {"max_form", nm(r.limits.max_form)},
            {"previous", {{"tip_radius", nm(r.touches.tip_radius)}, {"offset", vec(r.touches.offset)}}},
            {"qualified", !r.refused.has_value()}};
  if (r.refused) j["refused"] = *r.refused;
  return j.dump(2) + "\n";
}

}  // namespace imess::messcap
