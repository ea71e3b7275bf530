// The views of the HTML report: nominal geometry in part coordinates projected orthographically,
// the measured points over it, ticks, and placed labels (label_layout.hpp).
#include "inspect_views.hpp"
#include "number_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <vector>

#include <Eigen/Geometry>

#include "label_layout.hpp"

namespace imess::messcap {
namespace view_parts {  // named, not anonymous: the library is built as one unity file

using Vec3 = Eigen::Vector3d;
using metrology::FeatureKind;

// Picture size and the plot area inside it (px); the margins hold the ticks' numbers.
constexpr double kWidth = 360, kHeight = 300;
constexpr double kLeft = 46, kRight = 10, kTop = 10, kBottom = 36;
constexpr double kFont = 10;

std::string fmt(double v, const char* f = "%.1f") { return number_text(v, f); }


struct Box3 {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  bool valid() const { return lo.x() <= hi.x(); }
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void add(const Box3& b) {
    if (b.valid()) {
      add(b.lo);
      add(b.hi);
    }
  }
};

// One nominal feature in 3D: polylines (part coordinates) and where its label goes.
struct Shape {
  std::string feature;
  std::string css;                       // outline, plane, plane-face, round, axis, point
  std::vector<std::vector<Vec3>> lines;  // each a polyline
  bool closed = false;
  std::optional<Vec3> label_at;          // none: not labelled in this view
  Vec3 label_toward = Vec3::Zero();      // the side the label prefers (3D; projected)
};

// The probe targets of a feature, or its measured points when the plan has none (--points).
std::vector<Vec3> targets_of(const metrology::PlanFeature& f, const metrology::InspectionResult& r) {
  std::vector<Vec3> out;
  for (const auto& p : f.probes) out.push_back(p.point);
  if (out.empty())
    for (const auto& p : r.points)
      if (p.feature == f.name) out.push_back(p.part);
  return out;
}

// The part's outline: along each axis, the span between its planes square to that axis, when
// the plan has two such planes on every axis (a block); else none is drawn.
Box3 part_box(const metrology::InspectionPlan& plan) {
  Box3 box;
  for (int a = 0; a < 3; ++a) {
    double lo = 1e300, hi = -1e300;
    for (const auto& f : plan.features)
      if (f.nominal.kind == FeatureKind::Plane && std::abs(std::abs(f.nominal.direction[a]) - 1) < 1e-9) {
        lo = std::min(lo, f.nominal.point[a]);
        hi = std::max(hi, f.nominal.point[a]);
      }
    if (!(hi - lo > 1e-9)) return Box3{};
    box.lo[a] = lo;
    box.hi[a] = hi;
  }
  return box;
}

// Where the plane crosses the region: the polygon of its cuts through the region's edges.
std::vector<Vec3> plane_in_region(const Vec3& p0, const Vec3& n, const Box3& region) {
  std::vector<Vec3> cuts;
  const double eps = 1e-9 * std::max(1.0, (region.hi - region.lo).norm());
  auto add = [&](const Vec3& q) {
    for (const auto& c : cuts)
      if ((c - q).norm() < 1e-7) return;
    cuts.push_back(q);
  };
  auto corner = [&](int i) {
    return Vec3(i & 1 ? region.hi.x() : region.lo.x(), i & 2 ? region.hi.y() : region.lo.y(), i & 4 ? region.hi.z() : region.lo.z());
  };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4}) {
      if (i & bit) continue;
      const Vec3 a = corner(i), b = corner(i | bit);
      const double da = n.dot(a - p0), db = n.dot(b - p0);
      if (std::abs(da) <= eps) add(a);
      if (std::abs(db) <= eps) add(b);
      if ((da < -eps && db > eps) || (da > eps && db < -eps)) add(a + (b - a) * (da / (da - db)));
    }
  if (cuts.size() < 2) return {};
  Vec3 c = Vec3::Zero();
  for (const auto& q : cuts) c += q;
  c /= static_cast<double>(cuts.size());
  const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  std::sort(cuts.begin(), cuts.end(), [&](const Vec3& a, const Vec3& b) {
    return std::atan2((a - c).dot(e2), (a - c).dot(e1)) < std::atan2((b - c).dot(e2), (b - c).dot(e1));
  });
  return cuts;
}

std::vector<Vec3> circle_points(const Vec3& centre, const Vec3& normal, double radius) {
  const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.normalized().cross(e1);
  std::vector<Vec3> out;
  for (int i = 0; i <= 72; ++i) {
    const double t = i * 2 * M_PI / 72;
    out.push_back(centre + radius * (std::cos(t) * e1 + std::sin(t) * e2));
  }
  return out;
}

// The span of points along a direction from p0, [lo, hi].
std::pair<double, double> span_along(const std::vector<Vec3>& pts, const Vec3& p0, const Vec3& d) {
  double lo = 1e300, hi = -1e300;
  for (const auto& q : pts) {
    lo = std::min(lo, d.dot(q - p0));
    hi = std::max(hi, d.dot(q - p0));
  }
  return {lo, hi};
}

std::vector<Vec3> box_corners(const Box3& b) {
  std::vector<Vec3> out;
  for (int i = 0; i < 8; ++i)
    out.emplace_back(i & 1 ? b.hi.x() : b.lo.x(), i & 2 ? b.hi.y() : b.lo.y(), i & 4 ? b.hi.z() : b.lo.z());
  return out;
}

// Every nominal feature as seen from `w` (the view's depth axis).
std::vector<Shape> nominal_shapes(const metrology::InspectionPlan& plan, const metrology::InspectionResult& r, int w) {
  std::vector<Shape> shapes;
  const Box3 box = part_box(plan);
  const Vec3 depth = Vec3::Unit(w);
  if (box.valid()) {
    Shape s;
    s.css = "outline";
    s.closed = true;
    shapes.push_back(s);  // drawn as a rectangle by the caller (its projection)
  }
  for (const auto& f : plan.features) {
    const auto& g = f.nominal;
    const auto pts = targets_of(f, r);
    Shape s;
    s.feature = f.name;
    switch (g.kind) {
      case FeatureKind::Plane: {
        Box3 region = box;
        for (const auto& p : pts) region.add(p);
        if (!region.valid()) continue;
        const Vec3 n = g.direction.normalized();
        auto poly = plane_in_region(g.point, n, region);
        if (poly.empty()) continue;
        const double facing = std::abs(n.dot(depth));
        s.css = facing > 1 - 1e-6 ? "plane-face" : "plane";
        s.closed = true;
        s.lines.push_back(poly);
        if (facing <= 1 - 1e-6) {  // seen edge-on or slanted: labelled beside it, on its outer side
          Vec3 c = Vec3::Zero();
          for (const auto& q : poly) c += q;
          s.label_at = c / static_cast<double>(poly.size());
          s.label_toward = n;
        }
        break;
      }
      case FeatureKind::Circle:
      case FeatureKind::Sphere: {
        const Vec3 normal = g.kind == FeatureKind::Sphere ? depth : g.direction;  // a sphere's outline in every view
        s.css = "round";
        s.lines.push_back(circle_points(g.point, normal, g.diameter / 2));
        s.label_at = g.point;
        break;
      }
      case FeatureKind::Cylinder:
      case FeatureKind::Cone: {
        const Vec3 d = g.direction.normalized();
        auto [t0, t1] = pts.empty() ? std::pair<double, double>{-g.diameter / 2, g.diameter / 2} : span_along(pts, g.point, d);
        if (g.inner && box.valid()) {  // a bore runs through the part
          auto [b0, b1] = span_along(box_corners(box), g.point, d);
          t0 = std::min(t0, b0);
          t1 = std::max(t1, b1);
        }
        const double radius = g.diameter / 2;
        s.css = "round";
        if (g.kind == FeatureKind::Cylinder) {
          s.lines.push_back(circle_points(g.point + t0 * d, d, radius));
          s.lines.push_back(circle_points(g.point + t1 * d, d, radius));
          const Vec3 side = d.cross(depth);
          if (side.norm() > 1e-9)  // the silhouette lines
            for (double k : {-1.0, 1.0}) {
              const Vec3 off = k * radius * side.normalized();
              s.lines.push_back({g.point + t0 * d + off, g.point + t1 * d + off});
            }
        } else {
          s.lines.push_back(circle_points(g.point, d, radius));
        }
        Shape axis;
        axis.feature = f.name;
        axis.css = "axis";
        axis.lines.push_back({g.point + t0 * d, g.point + t1 * d});
        shapes.push_back(axis);
        s.label_at = g.point + 0.5 * (t0 + t1) * d;
        break;
      }
      case FeatureKind::Line: {
        const Vec3 d = g.direction.normalized();
        auto [t0, t1] = pts.empty() ? std::pair<double, double>{-10, 10} : span_along(pts, g.point, d);
        s.css = "axis";
        s.lines.push_back({g.point + t0 * d, g.point + t1 * d});
        s.label_at = g.point + 0.5 * (t0 + t1) * d;
        break;
      }
      case FeatureKind::Point: {
        s.css = "point";
        s.lines.push_back({g.point});
        s.label_at = g.point;
        break;
      }
    }
    shapes.push_back(s);
  }
  return shapes;
}

// Round tick steps: 1, 2 or 5 times a power of ten, about every 60 px.
double tick_step(double mm_per_px) {
  const double raw = 60 * mm_per_px;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

std::string tick_number(double v) {
  if (std::abs(v) < 1e-9) v = 0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace view_parts

std::string deviation_colour(double t) {
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

std::string inspection_view(const metrology::InspectionPlan& plan, const metrology::InspectionResult& result,
                            const ViewAxes& view, double scale) {
  using namespace view_parts;
  const int w = 3 - view.u - view.v;
  const auto shapes = nominal_shapes(plan, result, w);
  const Box3 box = part_box(plan);

  // The extent of everything drawn, in the view's (u, v), and one scale for both directions.
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  auto extend = [&](const Vec3& p) {
    u0 = std::min(u0, p[view.u]);
    u1 = std::max(u1, p[view.u]);
    v0 = std::min(v0, p[view.v]);
    v1 = std::max(v1, p[view.v]);
  };
  for (const auto& p : result.points) extend(p.part);
  for (const auto& s : shapes)
    for (const auto& line : s.lines)
      for (const auto& p : line) extend(p);
  if (box.valid()) {
    extend(box.lo);
    extend(box.hi);
  }
  if (u0 > u1) u0 = u1 = v0 = v1 = 0;
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  const double k = 0.9 * std::min(pw / std::max(u1 - u0, 1e-6), ph / std::max(v1 - v0, 1e-6));
  const double cu = 0.5 * (u0 + u1), cv = 0.5 * (v0 + v1);
  auto X = [&](double u) { return kLeft + pw / 2 + (u - cu) * k; };
  auto Y = [&](double v) { return kTop + ph / 2 - (v - cv) * k; };
  auto path = [&](const std::vector<Vec3>& pts, bool closed) {
    std::string d;
    for (std::size_t i = 0; i < pts.size(); ++i)
      d += (i == 0 ? "M" : "L") + fmt(X(pts[i][view.u]), "%.2f") + " " + fmt(Y(pts[i][view.v]), "%.2f") + " ";
    if (closed) d += "Z";
    return d;
  };

  std::ostringstream s;
  s << "<figure><svg class=\"view\" width=\"" << kWidth << "\" height=\"" << kHeight << "\" viewBox=\"0 0 " << kWidth << " "
    << kHeight << "\" font-family=\"sans-serif\" font-size=\"" << kFont << "\">"
    << "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\" stroke=\"#ccc\"/>";

  // Ticks and a faint grid, every round step, numbered along the bottom and left edges.
  const double step = tick_step(1 / k);
  const double left_mm = cu - (pw / 2) / k, right_mm = cu + (pw / 2) / k;
  const double low_mm = cv - (ph / 2) / k, high_mm = cv + (ph / 2) / k;
  s << "<g class=\"ticks\" fill=\"#555\">";
  for (double t = std::ceil(left_mm / step) * step; t <= right_mm + 1e-9; t += step) {
    const double x = X(t);
    s << "<line x1=\"" << fmt(x) << "\" y1=\"" << kTop << "\" x2=\"" << fmt(x) << "\" y2=\"" << kHeight - kBottom
      << "\" stroke=\"#ececec\"/><line x1=\"" << fmt(x) << "\" y1=\"" << kHeight - kBottom << "\" x2=\"" << fmt(x) << "\" y2=\""
      << kHeight - kBottom + 4 << "\" stroke=\"#555\"/><text class=\"tick\" x=\"" << fmt(x) << "\" y=\"" << kHeight - kBottom + 14
      << "\" text-anchor=\"middle\">" << tick_number(t) << "</text>";
  }
  for (double t = std::ceil(low_mm / step) * step; t <= high_mm + 1e-9; t += step) {
    const double y = Y(t);
    s << "<line x1=\"" << kLeft << "\" y1=\"" << fmt(y) << "\" x2=\"" << kWidth - kRight << "\" y2=\"" << fmt(y)
      << "\" stroke=\"#ececec\"/><line x1=\"" << kLeft - 4 << "\" y1=\"" << fmt(y) << "\" x2=\"" << kLeft << "\" y2=\"" << fmt(y)
      << "\" stroke=\"#555\"/><text class=\"tick\" x=\"" << kLeft - 6 << "\" y=\"" << fmt(y + 3.5) << "\" text-anchor=\"end\">"
      << tick_number(t) << "</text>";
  }
  s << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#bbb\"/>"
    << "<text class=\"axis-name\" x=\"" << kWidth - kRight << "\" y=\"" << kHeight - 6 << "\" text-anchor=\"end\">" << view.u_name
    << " (mm)</text><text class=\"axis-name\" x=\"12\" y=\"" << fmt(kTop + ph / 2) << "\" text-anchor=\"middle\" transform=\"rotate(-90 12 "
    << fmt(kTop + ph / 2) << ")\">" << view.v_name << " (mm)</text></g>";

  // The nominal part: the outline filled, each feature's lines over it.
  s << "<g class=\"nominal\" fill=\"none\">";
  if (box.valid())
    s << "<rect class=\"outline\" x=\"" << fmt(X(box.lo[view.u])) << "\" y=\"" << fmt(Y(box.hi[view.v])) << "\" width=\""
      << fmt((box.hi[view.u] - box.lo[view.u]) * k) << "\" height=\"" << fmt((box.hi[view.v] - box.lo[view.v]) * k)
      << "\" fill=\"#e9eef4\" stroke=\"#4a5866\" stroke-width=\"1.2\"><title>the part's outline (its opposite planes)</title></rect>";
  for (const auto& sh : shapes) {
    if (sh.css == "outline") continue;
    const char* style = sh.css == "plane"        ? "stroke=\"#4a5866\" stroke-width=\"1.4\""
                        : sh.css == "plane-face" ? "stroke=\"#9aa7b4\" stroke-width=\"0.8\" stroke-dasharray=\"4 3\""
                        : sh.css == "round"      ? "stroke=\"#2f6fa8\" stroke-width=\"1.2\""
                        : sh.css == "axis"       ? "stroke=\"#2f6fa8\" stroke-width=\"0.8\" stroke-dasharray=\"6 3 1 3\""
                                                 : "stroke=\"#2f6fa8\" stroke-width=\"1.2\"";
    for (const auto& line : sh.lines) {
      if (sh.css == "point") {
        const double x = X(line[0][view.u]), y = Y(line[0][view.v]);
        s << "<path class=\"point\" d=\"M" << fmt(x - 4) << " " << fmt(y) << " L" << fmt(x + 4) << " " << fmt(y) << " M" << fmt(x)
          << " " << fmt(y - 4) << " L" << fmt(x) << " " << fmt(y + 4) << "\" " << style << "/>";
        continue;
      }
      s << "<path class=\"" << sh.css << "\" d=\"" << path(line, sh.closed) << "\" " << style << "><title>" << html_escaped(sh.feature)
        << " (nominal)</title></path>";
    }
  }
  s << "</g>";

  // The measured points, coloured by their deviation.
  std::vector<LabelRect> obstacles;
  s << "<g class=\"points\">";
  for (const auto& p : result.points) {
    const double px = X(p.part[view.u]), py = Y(p.part[view.v]);
    obstacles.push_back({px - 3.5, py - 3.5, 7, 7});
    s << "<circle cx=\"" << fmt(px) << "\" cy=\"" << fmt(py) << "\" r=\"3.5\" fill=\"" << deviation_colour(p.deviation / scale)
      << "\" stroke=\"#333\" stroke-width=\"0.4\"><title>" << html_escaped(p.feature) << ": " << fmt(p.part.x(), "%.3f") << " "
      << fmt(p.part.y(), "%.3f") << " " << fmt(p.part.z(), "%.3f") << ", deviation " << fmt(p.deviation, "%.4f")
      << "</title></circle>";
  }
  s << "</g>";

  // One label per feature visible in this view, none over another, all inside the plot.
  std::vector<LabelRequest> requests;
  for (const auto& sh : shapes) {
    if (!sh.label_at || sh.feature.empty()) continue;
    const Vec3& a = *sh.label_at;
    LabelRequest r{sh.feature, X(a[view.u]), Y(a[view.v]), sh.label_toward[view.u], -sh.label_toward[view.v]};
    if (sh.css == "round") {  // beside its outline, up and to the right
      double best = -1e300;
      for (const auto& line : sh.lines)
        for (const auto& q : line)
          if (X(q[view.u]) - Y(q[view.v]) > best) {
            best = X(q[view.u]) - Y(q[view.v]);
            r.anchor_x = X(q[view.u]);
            r.anchor_y = Y(q[view.v]);
          }
      r.toward_x = 1;
      r.toward_y = -1;
    }
    requests.push_back(r);
  }
  const LabelRect area{kLeft + 1, kTop + 1, pw - 2, ph - 2};
  s << "<g class=\"labels\" fill=\"#333\">";
  for (const auto& l : place_labels(requests, area, obstacles, kFont)) {
    if (l.far) {
      const double lx = std::clamp(l.anchor_x, l.box.x, l.box.x + l.box.w), ly = std::clamp(l.anchor_y, l.box.y, l.box.y + l.box.h);
      s << "<line x1=\"" << fmt(l.anchor_x) << "\" y1=\"" << fmt(l.anchor_y) << "\" x2=\"" << fmt(lx) << "\" y2=\"" << fmt(ly)
        << "\" stroke=\"#999\" stroke-width=\"0.6\"/>";
    }
    s << "<text class=\"label\" x=\"" << fmt(l.baseline_x) << "\" y=\"" << fmt(l.baseline_y) << "\">" << html_escaped(l.text) << "</text>";
  }
  s << "</g></svg><figcaption>" << view.title << "</figcaption></figure>";
  return s.str();
}

std::string html_escaped(const std::string& s) {
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

}  // namespace imess::messcap
