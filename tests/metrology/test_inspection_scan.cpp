// Form from scans: an inspection plan's roundness, flatness, cylindricity and sphericity on dense
// scanned point sets (thousands of plain surface points, as a scanning probe reports them after
// compensation along its measured normal). The form put on the surfaces is known — a bore with
// 3-lobe lobing, a face with a waviness, a bore axis scanned as a helix with lobing — and each
// characteristic must be its peak-to-valley: the roundness to 0.01 nm, the flatness to 0.01 µm
// (the least-squares plane of the sampled waviness leans a little), the cylindricity to 0.1 µm
// (so does the helix's least-squares axis) — the same number the inspection's fit statistics give.
#include <cmath>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "imess/metrology/fit.hpp"
#include "imess/metrology/inspection.hpp"
#include "imess/metrology/inspection_plan.hpp"

using namespace imess::metrology;

namespace {

constexpr const char* kScanPlan = R"({
  "part": "scanned-cube",
  "placement": {"origin": [400, 300, 0]},
  "features": [
    {"name": "top", "type": "plane", "point": [0, 0, 80], "normal": [0, 0, 1]},
    {"name": "bore", "type": "circle", "center": [60, 50, 40], "normal": [0, 0, 1], "diameter": 30, "inner": true},
    {"name": "bore_axis", "type": "cylinder", "point": [60, 50, 40], "axis": [0, 0, 1], "diameter": 30, "inner": true},
    {"name": "ball", "type": "sphere", "center": [350, 350, 60], "diameter": 25}
  ],
  "characteristics": [
    {"name": "top flatness", "type": "flatness", "feature": "top", "tolerance": 0.01},
    {"name": "bore roundness", "type": "roundness", "feature": "bore", "tolerance": 0.01},
    {"name": "bore cylindricity", "type": "cylindricity", "feature": "bore_axis", "tolerance": 0.01},
    {"name": "ball sphericity", "type": "sphericity", "feature": "ball", "tolerance": 0.01}
  ]
})";

constexpr double kLobe = 0.002;   // mm: the bore's 3-lobe amplitude (roundness 2 x)
constexpr double kWave = 0.0015;  // mm: the top's waviness amplitude (flatness 2 x)
constexpr double kZone = 0.0015;  // mm: the sphere's upper zone stands out this much

}  // namespace

TEST_CASE("inspection: roundness, flatness, cylindricity and sphericity from scans of thousands of points", "[inspection][scan]") {
  const InspectionPlan plan = parse_inspection_plan(kScanPlan, "scan.plan.json");
  const Eigen::Vector3d origin(400, 300, 0);
  std::vector<MeasuredPoint> pts;
  // The bore at z 40: one scan circle of 3 600 points (every 0.1°).
  for (int i = 0; i < 3600; ++i) {
    const double t = 2 * std::numbers::pi * i / 3600, r = 15 + kLobe * std::cos(3 * t);
    pts.push_back({"bore", origin + Eigen::Vector3d(60 + r * std::cos(t), 50 + r * std::sin(t), 40), std::nullopt, 0});
  }
  // The top: 40 scan lines of 100 points across 100 x 80 mm, waviness of 20 mm wavelength in x
  // and 16 mm in y.
  for (int l = 0; l < 40; ++l)
    for (int i = 0; i < 100; ++i) {
      const double x = 10 + 100.0 * i / 99, y = 10 + 80.0 * l / 39;
      const double z = 80 + kWave * std::sin(2 * std::numbers::pi * x / 20) * std::cos(2 * std::numbers::pi * y / 16);
      pts.push_back({"top", origin + Eigen::Vector3d(x, y, z), std::nullopt, 0});
    }
  // The bore as a cylinder: a helix of 10 turns over z 10 … 70 with the same lobing.
  for (int i = 0; i < 3600; ++i) {
    const double t = 2 * std::numbers::pi * 10 * i / 3600, r = 15 + kLobe * std::cos(3 * t);
    pts.push_back({"bore_axis", origin + Eigen::Vector3d(60 + r * std::cos(t), 50 + r * std::sin(t), 10 + 60.0 * i / 3600),
                   std::nullopt, 0});
  }
  // The reference sphere: 10 rings of 300 points from the equator to 60° up, its radius larger by
  // kZone on the rings above 30°: a zonal form whose least-squares range is known only from the
  // points, so the sphericity must be what a sphere fit of the same points gives as its form.
  std::vector<Eigen::Vector3d> ball;
  for (int i = 0; i < 3000; ++i) {
    const double lat = std::numbers::pi / 3 * (i % 10) / 9.0, lon = 2 * std::numbers::pi * (i / 10) / 300.0;
    const double r = 12.5 + (lat > std::numbers::pi / 6 ? kZone : 0.0);
    const Eigen::Vector3d p = Eigen::Vector3d(350, 350, 60) +
                              r * Eigen::Vector3d(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    ball.push_back(p);
    pts.push_back({"ball", origin + p, std::nullopt, 0});
  }
  const auto ball_fit = fit_sphere(ball);
  REQUIRE(ball_fit.ok());
  const InspectionResult res = evaluate_inspection(plan, pts);
  REQUIRE(res.characteristics.size() == 4);
  for (const auto& c : res.characteristics) REQUIRE(c.evaluated());
  const auto& flat = res.characteristics[0];
  const auto& round = res.characteristics[1];
  const auto& cyl = res.characteristics[2];
  // The sampled waviness reaches its peaks only where the grid meets them: the true peak to
  // valley of the sampled surface, from the points themselves.
  double zmin = 1e9, zmax = -1e9;
  for (const auto& p : pts)
    if (p.feature == "top") zmin = std::min(zmin, p.point.z()), zmax = std::max(zmax, p.point.z());
  CHECK(flat.actual == Approx(zmax - zmin).margin(1e-5));
  CHECK(round.actual == Approx(2 * kLobe).margin(1e-8));
  CHECK(cyl.actual == Approx(2 * kLobe).margin(1e-4));
  const auto& sph = res.characteristics[3];
  CHECK(sph.actual == Approx(ball_fit->stats.form()).margin(1e-9));
  // Of the 1.5 µm step the least-squares sphere (moved up and grown between the zones) leaves 1.27 µm.
  CHECK(sph.actual > 0.5 * kZone);
  CHECK(sph.actual < kZone);
  CHECK(res.features[1].stats.point_count == 3600);
  CHECK(res.features[1].stats.form() == Approx(round.actual).margin(1e-12));
  CHECK(res.out_of_tolerance() == 0);
}
