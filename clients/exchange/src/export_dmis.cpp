// .dmi: DMIS (ANSI/DMSC, 05.2 syntax). Without a fit: one POINT feature per point — nominal
// F(PTn), a MEAS block with its PTMEAS, ENDMES. With a fit: the fitted feature with its own
// vector (plane/circle normal, cylinder/cone axis, the normal of a line's plane) — nominal F(...)
// (the fitted values: there is no CAD nominal), MEAS/<kind> with every point, ENDMES, actual FA(...).
#include <cmath>
#include <limits>

#include "writers.hpp"

namespace imess::exchange::writers {
namespace {

using Eigen::Vector3d;

std::string xyz(const Vector3d& v, int decimals) {
  return fixed(v.x(), decimals) + "," + fixed(v.y(), decimals) + "," + fixed(v.z(), decimals);
}
std::string ijk(const Vector3d& v) { return xyz(v, 9); }

// A line's end points: the extreme projections of the points onto it.
std::pair<Vector3d, Vector3d> line_ends(const FitReport& f, const std::vector<Vector3d>& points) {
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (const auto& p : points) {
    double t = (p - *f.point).dot(*f.direction);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  if (points.empty()) lo = hi = 0.0;
  return {*f.point + lo * *f.direction, *f.point + hi * *f.direction};
}

// The normal of the plane the line lies in: line2d's coordinate plane, else the part of +Z (or
// +X for a vertical line) perpendicular to the line.
Vector3d line_plane_normal(const FitReport& f) {
  if (f.normal) return *f.normal;
  Vector3d up = std::abs(f.direction->z()) < 0.9 ? Vector3d::UnitZ() : Vector3d::UnitX();
  return (up - up.dot(*f.direction) * *f.direction).normalized();
}

struct Feature {
  std::string label, word, body;  // "CIR1", "CIRCLE", "INNER,CART,..."
};

Feature feature(const FitReport& f, const ExportData& d) {
  const std::string side = d.outer ? "OUTER," : "INNER,";  // surface points do not tell: --outer
  constexpr int kLen = 6;             // fitted lengths: 6 decimals (nm), whatever the points had
  switch (f.kind) {
    case FitKind::Line:
    case FitKind::Line2d: {
      auto [a, b] = line_ends(f, d.points);
      return {"LIN1", "LINE", "BND,CART," + xyz(a, kLen) + "," + xyz(b, kLen) + "," + ijk(line_plane_normal(f))};
    }
    case FitKind::Plane:
      return {"PLN1", "PLANE", "CART," + xyz(*f.point, kLen) + "," + ijk(*f.normal)};
    case FitKind::Circle:
    case FitKind::Circle2d:
      return {"CIR1", "CIRCLE",
              side + "CART," + xyz(*f.center, kLen) + "," + ijk(*f.normal) + "," + fixed(*f.diameter, kLen)};
    case FitKind::Sphere:
      return {"SPH1", "SPHERE", side + "CART," + xyz(*f.center, kLen) + "," + fixed(*f.diameter, kLen)};
    case FitKind::Cylinder:
      return {"CYL1", "CYLNDR",
              side + "CART," + xyz(*f.point, kLen) + "," + ijk(*f.axis) + "," + fixed(*f.diameter, kLen)};
    case FitKind::Cone:
      return {"CON1", "CONE",
              side + "CART," + xyz(*f.apex, kLen) + "," + ijk(*f.axis) + "," + fixed(*f.apex_angle_deg, kLen)};
  }
  return {};
}

}  // namespace

std::string dmis(const ExportData& d) {
  std::string out = "DMISMN/'" + d.source + " " + d.file_name + "',05.2\n";
  out += "$$ " + std::to_string(d.points.size()) + " measured points" +
         (d.frame.empty() ? std::string(" in machine coordinates") : ", frame " + d.frame) + ", " +
         local_timestamp() + "\n";
  out += "UNITS/MM,ANGDEC\n";
  if (!d.fit) {
    // DMIS wants a vector with every FEAT/POINT; a bare point has none (see docs/metrology.md §13).
    if (!d.points.empty()) out += "$$ point vectors 0,0,1 are placeholders: the points carry no surface normal\n";
    for (std::size_t i = 0; i < d.points.size(); ++i) {
      const std::string label = "PT" + std::to_string(i + 1);
      const std::string where = xyz(d.points[i], d.decimals);
      out += "F(" + label + ")=FEAT/POINT,CART," + where + ",0,0,1\n";
      out += "MEAS/POINT,F(" + label + "),1\n";
      out += "PTMEAS/CART," + where + "\n";
      out += "ENDMES\n";
    }
  } else {
    const Feature f = feature(*d.fit, d);
    char stats[160];
    std::snprintf(stats, sizeof stats, "$$ least-squares %s of %zu points: rms %.6f, form %.6f .. %.6f\n",
                  std::string(to_string(d.fit->kind)).c_str(), d.fit->n, d.fit->rms, d.fit->form_min,
                  d.fit->form_max);
    out += stats;
    out += "F(" + f.label + ")=FEAT/" + f.word + "," + f.body + "\n";
    out += "MEAS/" + f.word + ",F(" + f.label + ")," + std::to_string(d.points.size()) + "\n";
    for (const auto& p : d.points) out += "PTMEAS/CART," + xyz(p, d.decimals) + "\n";
    out += "ENDMES\n";
    out += "FA(" + f.label + ")=FEAT/" + f.word + "," + f.body + "\n";
  }
  out += "ENDFIL\n";
  return out;
}

}  // namespace imess::exchange::writers
