// .dxf: AutoCAD DXF Release 12 (AC1009) — HEADER with version and extents, TABLES with the
// CONTINUOUS line type and the IMESS_POINTS layer, one POINT entity per point (group codes
// 8 layer, 10/20/30 x/y/z). Written directly: see docs/metrology.md for why not dxflib.
#include "writers.hpp"

namespace imess::exchange::writers {
namespace {

constexpr const char* kLayer = "IMESS_POINTS";

// One group: the code right-aligned in 3 columns, then the value, each on its own line.
void group(std::string& out, int code, const std::string& value) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%3d\n", code);
  out += buf;
  out += value;
  out += '\n';
}

void point3(std::string& out, int base, const Eigen::Vector3d& p, int decimals) {
  group(out, base, fixed(p.x(), decimals));
  group(out, base + 10, fixed(p.y(), decimals));
  group(out, base + 20, fixed(p.z(), decimals));
}

}  // namespace

std::string dxf(const ExportData& d) {
  std::string out;
  group(out, 999, d.source + ", measured points, mm" + (d.frame.empty() ? "" : ", frame " + d.frame));
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  if (!d.points.empty()) lo = hi = d.points.front();
  for (const auto& p : d.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  group(out, 0, "SECTION");
  group(out, 2, "HEADER");
  group(out, 9, "$ACADVER");
  group(out, 1, "AC1009");
  group(out, 9, "$INSBASE");
  point3(out, 10, Eigen::Vector3d::Zero(), d.decimals);
  group(out, 9, "$EXTMIN");
  point3(out, 10, lo, d.decimals);
  group(out, 9, "$EXTMAX");
  point3(out, 10, hi, d.decimals);
  group(out, 0, "ENDSEC");

  group(out, 0, "SECTION");
  group(out, 2, "TABLES");
  group(out, 0, "TABLE");
  group(out, 2, "LTYPE");
  group(out, 70, "1");
  group(out, 0, "LTYPE");
  group(out, 2, "CONTINUOUS");
  group(out, 70, "0");
  group(out, 3, "Solid line");
  group(out, 72, "65");
  group(out, 73, "0");
  group(out, 40, "0.0");
  group(out, 0, "ENDTAB");
  group(out, 0, "TABLE");
  group(out, 2, "LAYER");
  group(out, 70, "1");
  group(out, 0, "LAYER");
  group(out, 2, kLayer);
  group(out, 70, "0");
  group(out, 62, "7");
  group(out, 6, "CONTINUOUS");
  group(out, 0, "ENDTAB");
  group(out, 0, "ENDSEC");

  group(out, 0, "SECTION");
  group(out, 2, "ENTITIES");
  for (const auto& p : d.points) {
    group(out, 0, "POINT");
    group(out, 8, kLayer);
    point3(out, 10, p, d.decimals);
  }
  group(out, 0, "ENDSEC");
  group(out, 0, "EOF");
  return out;
}

}  // namespace imess::exchange::writers
