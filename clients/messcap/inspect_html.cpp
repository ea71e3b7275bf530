// The HTML report of messcap inspect: one self-contained page (no scripts, no external files):
// the characteristics with a deviation bar each, three orthographic views of the nominal part
// with the points coloured by their deviation (inspect_views.cpp), the part frame and the fitted
// features.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "inspect_report.hpp"
#include "inspect_views.hpp"
#include "number_text.hpp"

namespace imess::messcap {
namespace {


std::string num(double v, const char* fmt = "%.4f") { return number_text(v, fmt); }

// The deviation against its tolerance: the band in green, a bar from the nominal to the deviation.
std::string deviation_bar(const metrology::CharacteristicResult& c) {
  const double w = 220, h = 20, pad = 6;
  if (!c.evaluated()) return "<svg width=\"220\" height=\"20\"></svg>";
  double lo = c.spec.lower, hi = c.spec.upper;
  const double span = hi - lo;
  double from = std::min(lo, c.deviation), to = std::max(hi, c.deviation);
  if (metrology::is_zone(c.spec.kind)) {
    from = 0;
    to = std::max(hi, c.deviation) * 1.15;
  } else {
    from -= 0.15 * span;
    to += 0.15 * span;
  }
  auto x = [&](double v) { return pad + (v - from) / (to - from) * (w - 2 * pad); };
  std::ostringstream s;
  s << "<svg width=\"" << w << "\" height=\"" << h << "\" viewBox=\"0 0 " << w << " " << h << "\">"
    << "<rect x=\"" << num(x(lo), "%.2f") << "\" y=\"2\" width=\"" << num(x(hi) - x(lo), "%.2f") << "\" height=\"" << h - 4
    << "\" fill=\"#dcf0dc\" stroke=\"#8bbf8b\"/>"
    << "<line x1=\"" << num(x(0), "%.2f") << "\" y1=\"0\" x2=\"" << num(x(0), "%.2f") << "\" y2=\"" << h
    << "\" stroke=\"#555\" stroke-width=\"1\"/>";
  const double a = std::min(x(0), x(c.deviation)), b = std::max(x(0), x(c.deviation));
  s << "<rect x=\"" << num(a, "%.2f") << "\" y=\"6\" width=\"" << num(std::max(b - a, 1.5), "%.2f") << "\" height=\"" << h - 12
    << "\" fill=\"" << (c.in_tolerance ? "#2e8b2e" : "#d02020") << "\"><title>deviation " << num(c.deviation)
    << "</title></rect></svg>";
  return s.str();
}

// The colour scale under the views: its ends and its middle numbered, inside the picture.
std::string legend(double scale) {
  std::ostringstream s;
  s << "<svg class=\"legend\" width=\"360\" height=\"40\" viewBox=\"0 0 360 40\" font-family=\"sans-serif\" font-size=\"11\">";
  for (int i = 0; i < 60; ++i)
    s << "<rect x=\"" << 30 + i * 5 << "\" y=\"4\" width=\"5.5\" height=\"14\" fill=\"" << deviation_colour(-1 + i / 29.5) << "\"/>";
  s << "<text x=\"30\" y=\"34\" text-anchor=\"start\">" << num(-scale, "%+.4f") << "</text><text x=\"180\" y=\"34\" "
    << "text-anchor=\"middle\">0</text><text x=\"330\" y=\"34\" text-anchor=\"end\">" << num(scale, "%+.4f") << " mm</text></svg>";
  return s.str();
}

std::string geometry_text(const metrology::Geometry& g) {
  using metrology::FeatureKind;
  auto v = [](const Eigen::Vector3d& p) { return num(p.x()) + " " + num(p.y()) + " " + num(p.z()); };
  auto d = [](const Eigen::Vector3d& p) { return num(p.x(), "%.6f") + " " + num(p.y(), "%.6f") + " " + num(p.z(), "%.6f"); };
  switch (g.kind) {
    case FeatureKind::Point: return "at " + v(g.point);
    case FeatureKind::Plane: return "through " + v(g.point) + ", normal " + d(g.direction);
    case FeatureKind::Line: return "through " + v(g.point) + ", direction " + d(g.direction);
    case FeatureKind::Circle: return "centre " + v(g.point) + ", normal " + d(g.direction) + ", Ø " + num(g.diameter);
    case FeatureKind::Sphere: return "centre " + v(g.point) + ", Ø " + num(g.diameter);
    case FeatureKind::Cylinder: return "axis through " + v(g.point) + " along " + d(g.direction) + ", Ø " + num(g.diameter);
    case FeatureKind::Cone:
      return "axis through " + v(g.point) + " along " + d(g.direction) + ", Ø " + num(g.diameter) + " there, apex " +
             num(g.apex_angle_deg) + "°";
  }
  return "";
}

}  // namespace

std::string inspection_html(const metrology::InspectionPlan& plan, const metrology::InspectionResult& result,
                            const ReportSource& source) {
  const std::size_t n = result.characteristics.size(), bad = result.out_of_tolerance(), none = result.not_evaluated();
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Inspection of " << html_escaped(plan.part)
    << "</title>\n<style>body{font-family:sans-serif;margin:1.5em;color:#222}table{border-collapse:collapse;margin:.5em 0}"
       "td,th{border-bottom:1px solid #ddd;padding:3px 8px;text-align:left;vertical-align:middle}"
       "td.n{text-align:right;font-family:monospace}.ok{color:#2e8b2e;font-weight:bold}.out{color:#d02020;font-weight:bold}"
       ".none{color:#888}figure{display:inline-block;margin:0 1em 1em 0}figcaption{text-align:center;font-size:90%}"
       ".summary{font-size:115%}</style></head><body>\n";
  s << "<h1>Inspection of " << html_escaped(plan.part) << "</h1>\n<p>Plan <code>" << html_escaped(source.plan) << "</code>; " << html_escaped(source.measured)
    << "; " << result.points.size() << " points.</p>\n<p class=\"summary\">" << n << " characteristics: <span class=\"ok\">"
    << n - bad - none << " in tolerance</span>, <span class=\"" << (bad ? "out" : "ok") << "\">" << bad
    << " out of tolerance</span>" << (none ? ", <span class=\"none\">" + std::to_string(none) + " not evaluated</span>" : "")
    << ".</p>\n";

  s << "<h2>Characteristics</h2>\n<table><tr><th>characteristic</th><th>type</th><th>feature</th><th>nominal</th><th>actual</th>"
       "<th>deviation</th><th>tolerance</th><th>deviation in its tolerance</th><th></th></tr>\n";
  for (const auto& c : result.characteristics) {
    const std::string cls = !c.evaluated() ? "none" : c.in_tolerance ? "ok" : "out";
    s << "<tr><td>" << html_escaped(c.spec.name) << "</td><td>" << metrology::to_string(c.spec.kind) << "</td><td>" << html_escaped(c.spec.feature)
      << (c.spec.other.empty() ? "" : (metrology::is_zone(c.spec.kind) ? " to " : " – ") + html_escaped(c.spec.other)) << "</td>";
    const int d = decimals_for(c);  // enough to see the verdict in the figures
    const std::string plain = "%." + std::to_string(d) + "f", sign = "%+." + std::to_string(d) + "f";
    if (c.evaluated())
      s << "<td class=\"n\">" << num(c.nominal, plain.c_str()) << "</td><td class=\"n\">" << num(c.actual, plain.c_str())
        << "</td><td class=\"n\">" << num(c.deviation, sign.c_str()) << "</td>";
    else
      s << "<td colspan=\"3\" class=\"none\">not evaluated: " << html_escaped(c.error) << "</td>";
    s << "<td class=\"n\">" << tolerance_text(c) << " " << unit_of(c) << "</td><td>" << deviation_bar(c) << "</td><td class=\""
      << cls << "\">" << verdict_text(c) << "</td></tr>\n";
  }
  s << "</table>\n<p>Bars: the tolerance zone in green, the nominal as the grey line, the deviation as the bar (red when "
       "outside). Zones (position, form, orientation) run from 0 to their width.</p>\n";

  double scale = 1e-3;
  for (const auto& p : result.points) scale = std::max(scale, std::abs(p.deviation));
  s << "<h2>Points</h2>\n<p>Part coordinates (mm). Grey and blue: the nominal part from the plan — its outline between "
       "opposite planes, each plane over the part and its probe points (dashed where it faces you), circles, cylinders and "
       "their axes; each point coloured by its deviation from its nominal feature (positive: out of the "
       "material).</p>\n<div>"
    << inspection_view(plan, result, {"top (X–Y)", 0, 1, "X", "Y"}, scale)
    << inspection_view(plan, result, {"front (X–Z)", 0, 2, "X", "Z"}, scale)
    << inspection_view(plan, result, {"right side (Y–Z)", 1, 2, "Y", "Z"}, scale) << "</div>\n" << legend(scale) << "\n";

  const auto& a = result.alignment;
  auto v = [](const Eigen::Vector3d& p, const char* f) { return num(p.x(), f) + " " + num(p.y(), f) + " " + num(p.z(), f); };
  s << "<h2>Part frame</h2>\n<p>"
    << (a.measured ? "3-2-1 alignment from " + html_escaped(plan.alignment->primary) + ", " + html_escaped(plan.alignment->secondary) + ", " +
                         html_escaped(plan.alignment->tertiary)
                   : std::string("The plan's nominal placement (no alignment)."))
    << "</p>\n<table><tr><td>origin (machine)</td><td class=\"n\">" << v(a.part_to_machine.translation(), "%.4f")
    << "</td></tr><tr><td>X axis</td><td class=\"n\">" << v(a.part_to_machine.rotation().col(0), "%.7f")
    << "</td></tr><tr><td>Y axis</td><td class=\"n\">" << v(a.part_to_machine.rotation().col(1), "%.7f")
    << "</td></tr><tr><td>Z axis</td><td class=\"n\">" << v(a.part_to_machine.rotation().col(2), "%.7f")
    << "</td></tr><tr><td>shift from the placement</td><td class=\"n\">" << v(a.shift, "%+.4f")
    << "</td></tr><tr><td>rotation from the placement (deg about X Y Z)</td><td class=\"n\">" << v(a.rotation_deg, "%+.5f")
    << "</td></tr></table>\n";

  s << "<h2>Features</h2>\n<table><tr><th>feature</th><th>type</th><th>points</th><th>fit</th><th>form</th><th>actual (part "
       "coordinates)</th></tr>\n";
  for (std::size_t i = 0; i < result.features.size(); ++i) {
    const auto& f = result.features[i];
    s << "<tr><td>" << html_escaped(f.name) << "</td><td>" << metrology::to_string(plan.features[i].nominal.kind) << "</td><td class=\"n\">"
      << f.point_count << "</td>";
    if (f.actual)
      s << "<td>" << (f.compensated ? "probe compensated" : "points as given") << "</td><td class=\"n\">" << num(f.stats.form())
        << "</td><td>" << geometry_text(*f.actual) << "</td></tr>\n";
    else
      s << "<td colspan=\"3\" class=\"out\">" << html_escaped(f.error) << "</td></tr>\n";
  }
  s << "</table>\n<p>Definitions: docs/metrology.md (least-squares fits; form = the fit's residual range, not minimum "
       "zone).</p>\n</body></html>\n";
  return s.str();
}

}  // namespace imess::messcap
