// The HTML report of messcap inspect: one self-contained page (no scripts, no external files):
// the characteristics with a deviation bar each, the points in three orthographic views
// coloured by their deviation from the nominal feature, the part frame and the fitted features.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "inspect_report.hpp"

namespace imess::messcap {
namespace {

std::string esc(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string num(double v, const char* fmt = "%.4f") {
  char buf[48];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

// Blue (-1) through green (0) to red (+1).
std::string colour(double t) {
  t = std::clamp(t, -1.0, 1.0);
  int r, g, b;
  if (t < 0) {
    r = 0;
    g = static_cast<int>(160 - 80 * -t);
    b = static_cast<int>(255 * -t);
  } else {
    r = static_cast<int>(220 * t);
    g = static_cast<int>(160 * (1 - t));
    b = 0;
  }
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r, g, b);
  return buf;
}

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

struct View {
  const char* title;
  int u, v;  // coordinate indices shown across and up
  const char* u_name;
  const char* v_name;
};

std::string point_view(const metrology::InspectionResult& r, const View& view, double scale) {
  const double w = 330, h = 250, m = 28;
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (const auto& p : r.points) {
    u0 = std::min(u0, p.part[view.u]);
    u1 = std::max(u1, p.part[view.u]);
    v0 = std::min(v0, p.part[view.v]);
    v1 = std::max(v1, p.part[view.v]);
  }
  const double k = std::min((w - 2 * m) / std::max(u1 - u0, 1e-9), (h - 2 * m) / std::max(v1 - v0, 1e-9));
  const double cu = 0.5 * (u0 + u1), cv = 0.5 * (v0 + v1);
  auto X = [&](double u) { return w / 2 + (u - cu) * k; };
  auto Y = [&](double v) { return h / 2 - (v - cv) * k; };
  std::ostringstream s;
  s << "<figure><svg width=\"" << w << "\" height=\"" << h << "\" viewBox=\"0 0 " << w << " " << h
    << "\"><rect width=\"100%\" height=\"100%\" fill=\"#fafafa\" stroke=\"#ccc\"/>";
  // Axes through the part origin, when it is in view.
  s << "<line x1=\"" << num(X(0), "%.1f") << "\" y1=\"0\" x2=\"" << num(X(0), "%.1f") << "\" y2=\"" << h
    << "\" stroke=\"#e0e0e0\"/><line x1=\"0\" y1=\"" << num(Y(0), "%.1f") << "\" x2=\"" << w << "\" y2=\"" << num(Y(0), "%.1f")
    << "\" stroke=\"#e0e0e0\"/>";
  std::map<std::string, std::pair<Eigen::Vector2d, int>> centres;
  for (const auto& p : r.points) {
    const double px = X(p.part[view.u]), py = Y(p.part[view.v]);
    s << "<circle cx=\"" << num(px, "%.1f") << "\" cy=\"" << num(py, "%.1f") << "\" r=\"3.5\" fill=\""
      << colour(p.deviation / scale) << "\" stroke=\"#333\" stroke-width=\"0.4\"><title>" << esc(p.feature) << ": "
      << num(p.part.x(), "%.3f") << " " << num(p.part.y(), "%.3f") << " " << num(p.part.z(), "%.3f") << ", deviation "
      << num(p.deviation) << "</title></circle>";
    auto& c = centres[p.feature];
    c.first += Eigen::Vector2d(px, py);
    ++c.second;
  }
  for (const auto& [name, c] : centres) {
    const Eigen::Vector2d at = c.first / c.second;
    s << "<text x=\"" << num(at.x() + 6, "%.1f") << "\" y=\"" << num(at.y() - 6, "%.1f")
      << "\" font-size=\"10\" fill=\"#666\">" << esc(name) << "</text>";
  }
  s << "<text x=\"" << w - 14 << "\" y=\"" << h - 6 << "\" font-size=\"11\">" << view.u_name << "</text><text x=\"6\" y=\"14\" font-size=\"11\">"
    << view.v_name << "</text></svg><figcaption>" << view.title << "</figcaption></figure>";
  return s.str();
}

std::string legend(double scale) {
  std::ostringstream s;
  s << "<svg width=\"330\" height=\"40\" viewBox=\"0 0 330 40\">";
  for (int i = 0; i < 60; ++i)
    s << "<rect x=\"" << 15 + i * 5 << "\" y=\"4\" width=\"5.5\" height=\"14\" fill=\"" << colour(-1 + i / 29.5) << "\"/>";
  s << "<text x=\"15\" y=\"34\" font-size=\"11\">" << num(-scale) << "</text><text x=\"160\" y=\"34\" font-size=\"11\">0</text>"
    << "<text x=\"270\" y=\"34\" font-size=\"11\">" << num(scale, "%+.4f") << " mm</text></svg>";
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
  s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Inspection of " << esc(plan.part)
    << "</title>\n<style>body{font-family:sans-serif;margin:1.5em;color:#222}table{border-collapse:collapse;margin:.5em 0}"
       "td,th{border-bottom:1px solid #ddd;padding:3px 8px;text-align:left;vertical-align:middle}"
       "td.n{text-align:right;font-family:monospace}.ok{color:#2e8b2e;font-weight:bold}.out{color:#d02020;font-weight:bold}"
       ".none{color:#888}figure{display:inline-block;margin:0 1em 1em 0}figcaption{text-align:center;font-size:90%}"
       ".summary{font-size:115%}</style></head><body>\n";
  s << "<h1>Inspection of " << esc(plan.part) << "</h1>\n<p>Plan <code>" << esc(source.plan) << "</code>; " << esc(source.measured)
    << "; " << result.points.size() << " points.</p>\n<p class=\"summary\">" << n << " characteristics: <span class=\"ok\">"
    << n - bad - none << " in tolerance</span>, <span class=\"" << (bad ? "out" : "ok") << "\">" << bad
    << " out of tolerance</span>" << (none ? ", <span class=\"none\">" + std::to_string(none) + " not evaluated</span>" : "")
    << ".</p>\n";

  s << "<h2>Characteristics</h2>\n<table><tr><th>characteristic</th><th>type</th><th>feature</th><th>nominal</th><th>actual</th>"
       "<th>deviation</th><th>tolerance</th><th>deviation in its tolerance</th><th></th></tr>\n";
  for (const auto& c : result.characteristics) {
    const std::string cls = !c.evaluated() ? "none" : c.in_tolerance ? "ok" : "out";
    s << "<tr><td>" << esc(c.spec.name) << "</td><td>" << metrology::to_string(c.spec.kind) << "</td><td>" << esc(c.spec.feature)
      << (c.spec.other.empty() ? "" : (metrology::is_zone(c.spec.kind) ? " to " : " – ") + esc(c.spec.other)) << "</td>";
    if (c.evaluated())
      s << "<td class=\"n\">" << num(c.nominal) << "</td><td class=\"n\">" << num(c.actual) << "</td><td class=\"n\">"
        << num(c.deviation, "%+.4f") << "</td>";
    else
      s << "<td colspan=\"3\" class=\"none\">not evaluated: " << esc(c.error) << "</td>";
    s << "<td class=\"n\">" << tolerance_text(c) << " " << unit_of(c) << "</td><td>" << deviation_bar(c) << "</td><td class=\""
      << cls << "\">" << verdict_text(c) << "</td></tr>\n";
  }
  s << "</table>\n<p>Bars: the tolerance zone in green, the nominal as the grey line, the deviation as the bar (red when "
       "outside). Zones (position, form, orientation) run from 0 to their width.</p>\n";

  double scale = 1e-3;
  for (const auto& p : result.points) scale = std::max(scale, std::abs(p.deviation));
  s << "<h2>Points</h2>\n<p>Part coordinates (mm), each point coloured by its deviation from its nominal feature "
       "(positive: out of the material).</p>\n<div>"
    << point_view(result, {"top (X–Y)", 0, 1, "X", "Y"}, scale) << point_view(result, {"front (X–Z)", 0, 2, "X", "Z"}, scale)
    << point_view(result, {"side (Y–Z)", 1, 2, "Y", "Z"}, scale) << "</div>\n" << legend(scale) << "\n";

  const auto& a = result.alignment;
  auto v = [](const Eigen::Vector3d& p, const char* f) { return num(p.x(), f) + " " + num(p.y(), f) + " " + num(p.z(), f); };
  s << "<h2>Part frame</h2>\n<p>"
    << (a.measured ? "3-2-1 alignment from " + esc(plan.alignment->primary) + ", " + esc(plan.alignment->secondary) + ", " +
                         esc(plan.alignment->tertiary)
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
    s << "<tr><td>" << esc(f.name) << "</td><td>" << metrology::to_string(plan.features[i].nominal.kind) << "</td><td class=\"n\">"
      << f.point_count << "</td>";
    if (f.actual)
      s << "<td>" << (f.compensated ? "probe compensated" : "points as given") << "</td><td class=\"n\">" << num(f.stats.form())
        << "</td><td>" << geometry_text(*f.actual) << "</td></tr>\n";
    else
      s << "<td colspan=\"3\" class=\"out\">" << esc(f.error) << "</td></tr>\n";
  }
  s << "</table>\n<p>Definitions: docs/metrology.md (least-squares fits; form = the fit's residual range, not minimum "
       "zone).</p>\n</body></html>\n";
  return s.str();
}

}  // namespace imess::messcap
