// The terminal table of messcap inspect, and the verdict / tolerance texts all reports share.
#include <cstdio>
#include <string>

#include "inspect_report.hpp"
#include "number_text.hpp"

namespace imess::messcap {
namespace {

std::string fixed(double v, int decimals, bool sign = false) { return fixed_text(v, decimals, sign); }

// v as printed with `decimals` decimals, read back.
double printed(double v, int decimals) { return std::stod(fixed(v, decimals)); }

}  // namespace

int decimals_for(const metrology::CharacteristicResult& c) {
  if (!c.evaluated()) return 4;
  for (int d = 4; d < 9; ++d) {
    const double dev = printed(c.deviation, d), lo = printed(c.spec.lower, d), hi = printed(c.spec.upper, d);
    const bool inside = dev >= lo && dev <= hi;
    if (inside == c.in_tolerance) return d;  // what the reader sees is what was decided
  }
  return 9;
}

std::string verdict_text(const metrology::CharacteristicResult& c) {
  if (!c.evaluated()) return "--";
  return c.in_tolerance ? "ok" : "OUT";
}

std::string tolerance_text(const metrology::CharacteristicResult& c) {
  const int d = decimals_for(c);
  if (metrology::is_zone(c.spec.kind)) return "<= " + fixed(c.spec.upper, d);
  return fixed(c.spec.lower, d, true) + "/" + fixed(c.spec.upper, d, true);
}

const char* unit_of(const metrology::CharacteristicResult& c) {
  return c.spec.kind == metrology::CharacteristicKind::Angle ? "deg" : "mm";
}

void print_inspection_table(std::ostream& out, const metrology::InspectionPlan& plan,
                            const metrology::InspectionResult& result, const ReportSource& source) {
  const auto& a = result.alignment;
  char line[256];
  out << plan.part << ": " << source.measured << ", " << result.points.size() << " points\n";
  if (a.measured) {
    std::snprintf(line, sizeof line,
                  "part frame from %s, %s, %s: origin %.4f %.4f %.4f (placement %+.4f %+.4f %+.4f), turned %+.4f %+.4f %+.4f deg\n",
                  plan.alignment->primary.c_str(), plan.alignment->secondary.c_str(), plan.alignment->tertiary.c_str(),
                  a.part_to_machine.translation().x(), a.part_to_machine.translation().y(),
                  a.part_to_machine.translation().z(), a.shift.x(), a.shift.y(), a.shift.z(), a.rotation_deg.x(),
                  a.rotation_deg.y(), a.rotation_deg.z());
    out << line;
  } else {
    out << "part frame: the plan's placement (no alignment)\n";
  }
  std::snprintf(line, sizeof line, "%-28s %-16s %11s %11s %10s %17s  %s\n", "characteristic", "type", "nominal", "actual",
                "deviation", "tolerance", "");
  out << line;
  for (const auto& c : result.characteristics) {
    const std::string type(metrology::to_string(c.spec.kind));
    if (!c.evaluated()) {
      std::snprintf(line, sizeof line, "%-28s %-16s %11s %11s %10s %17s  --\n", c.spec.name.c_str(), type.c_str(), "", "", "",
                    tolerance_text(c).c_str());
      out << line << "    not evaluated: " << c.error << "\n";
      continue;
    }
    const int d = decimals_for(c);
    std::snprintf(line, sizeof line, "%-28s %-16s %11.*f %11.*f %+10.*f %17s  %s%s\n", c.spec.name.c_str(), type.c_str(), d,
                  c.nominal, d, c.actual, d, c.deviation, tolerance_text(c).c_str(), verdict_text(c).c_str(),
                  c.spec.kind == metrology::CharacteristicKind::Angle ? "  (deg)" : "");
    out << line;
  }
  for (const auto& f : result.features)
    if (!f.error.empty()) out << "feature " << f.name << ": " << f.error << "\n";
  const std::size_t n = result.characteristics.size(), bad = result.out_of_tolerance(), none = result.not_evaluated();
  out << n << " characteristics: " << (n - bad - none) << " in tolerance, " << bad << " out of tolerance";
  if (none) out << ", " << none << " not evaluated";
  out << "\n";
}

}  // namespace imess::messcap
