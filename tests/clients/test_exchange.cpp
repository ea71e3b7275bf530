// imess::exchange: fit reports (kinds, 2-D embedding, cone apex, JSON) and the structure of the
// whole-file writers (IGES columns and counts, STEP references, DMIS blocks, PLY header).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "imess/exchange/export_format.hpp"
#include "imess/exchange/fit_report.hpp"

using namespace imess::exchange;
using Eigen::Vector3d;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

ExportData sample(std::size_t n = 12) {
  ExportData d;
  for (std::size_t i = 0; i < n; ++i)
    d.points.emplace_back(-123.456 + 10.5 * static_cast<double>(i), 0.001 * static_cast<double>(i), 987.654);
  d.file_name = "sample";
  return d;
}

std::string write(const char* ext, const ExportData& d) { return export_format_for(std::string("x") + ext).write(d); }

}  // namespace

TEST_CASE("parse_fit_kind: the eight words, anything else listed") {
  for (auto word : {"line", "line2d", "plane", "circle", "circle2d", "sphere", "cylinder", "cone"})
    CHECK(to_string(parse_fit_kind(word)) == word);
  CHECK_THROWS_WITH(parse_fit_kind("Circle"), Catch::Contains("'Circle'") && Catch::Contains("circle2d, sphere"));
}

TEST_CASE("fit_points circle2d: the coordinate plane is found and the result embedded") {
  std::vector<Vector3d> pts;
  for (int deg : {0, 100, 200, 300}) {  // a circle D 20 at (5, 7) in the plane y = -3
    double a = deg * M_PI / 180;
    pts.emplace_back(5 + 10 * std::cos(a), -3.0, 7 + 10 * std::sin(a));
  }
  auto fit = fit_points(FitKind::Circle2d, pts);
  REQUIRE(fit.ok());
  CHECK(fit->diameter.value() == Approx(20.0).epsilon(1e-12));
  CHECK((*fit->center - Vector3d(5, -3, 7)).norm() < 1e-9);
  CHECK(*fit->normal == Vector3d::UnitY());
  pts[0].y() += 0.5;
  auto bad = fit_points(FitKind::Circle2d, pts);
  REQUIRE_FALSE(bad.ok());
  CHECK_THAT(bad.error().message, Catch::Contains("no coordinate plane") && Catch::Contains("'circle'"));
}

TEST_CASE("fit_points cone: axis toward increasing radius, apex where the radius is zero") {
  // Cone with apex (1, 2, 3), axis +x, half angle 30 deg: radius = (x - 1) tan 30.
  std::vector<Vector3d> pts;
  for (double x : {5.0, 8.0, 12.0})
    for (int deg = 0; deg < 360; deg += 60) {
      double a = deg * M_PI / 180, r = (x - 1) * std::tan(M_PI / 6);
      pts.emplace_back(x, 2 + r * std::cos(a), 3 + r * std::sin(a));
    }
  auto fit = fit_points(FitKind::Cone, pts);
  REQUIRE(fit.ok());
  CHECK((*fit->apex - Vector3d(1, 2, 3)).norm() < 1e-8);
  CHECK((*fit->axis - Vector3d::UnitX()).norm() < 1e-9);
  CHECK(*fit->apex_angle_deg == Approx(60.0).epsilon(1e-10));
  const double h = (*fit->point - *fit->apex).dot(*fit->axis);
  CHECK(*fit->diameter == Approx(2 * h * std::tan(M_PI / 6)).epsilon(1e-10));
}

TEST_CASE("fit_points: the library's error passes through") {
  std::vector<Vector3d> pts{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  auto fit = fit_points(FitKind::Plane, pts);
  REQUIRE_FALSE(fit.ok());
  CHECK(fit.error().code == imess::metrology::FitErrorCode::CollinearPoints);
  CHECK_THAT(fit.error().message, Catch::Contains("collinear"));
}

TEST_CASE("to_json: documented keys in order, only those that apply") {
  std::vector<Vector3d> pts{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}, {10, 10, 10}};
  auto fit = fit_points(FitKind::Sphere, pts);
  REQUIRE(fit.ok());
  auto j = nlohmann::ordered_json::parse(to_json(*fit));
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  CHECK(keys == std::vector<std::string>{"type", "center", "diameter", "rms", "form_min", "form_max", "n"});
  CHECK(j["n"] == 5);
  CHECK(j["diameter"].get<double>() == Approx(*fit->diameter));
}

TEST_CASE("IGES: 80-column records, S/G/D/P/T in order, counts and pointers consistent") {
  auto d = sample(30);
  auto lines = lines_of(write(".igs", d));
  std::map<char, int> count;
  std::string order;
  for (const auto& l : lines) {
    REQUIRE(l.size() == 80);
    char section = l[72];
    if (order.empty() || order.back() != section) order.push_back(section);
    CHECK(std::stoi(l.substr(73)) == ++count[section]);  // sequence numbers 1, 2, ...
  }
  CHECK(order == "SGDPT");
  CHECK(count['D'] == 2 * 31);  // 30 points + the group
  char t[80];
  std::snprintf(t, sizeof t, "S%7dG%7dD%7dP%7d", count['S'], count['G'], count['D'], count['P']);
  CHECK(lines.back().substr(0, 32) == t);
  // Every point's D record points at its P record, and the P record points back.
  std::vector<std::string> d_lines, p_lines;
  for (const auto& l : lines) {
    if (l[72] == 'D') d_lines.push_back(l);
    if (l[72] == 'P') p_lines.push_back(l);
  }
  int points = 0;
  for (std::size_t i = 0; i + 1 < d_lines.size(); i += 2) {
    if (d_lines[i].substr(0, 8) != "     116") continue;
    int p = std::stoi(d_lines[i].substr(8, 8));
    const auto& pl = p_lines.at(static_cast<std::size_t>(p - 1));
    CHECK(std::stoi(pl.substr(64, 8)) == static_cast<int>(i + 1));
    ++points;
    std::string expected = "116," + fixed(d.points[static_cast<std::size_t>(points - 1)].x(), 3) + ",";
    CHECK(pl.substr(0, expected.size()) == expected);
  }
  CHECK(points == 30);
}

TEST_CASE("STEP: every #reference is defined, points in one GEOMETRIC_CURVE_SET") {
  auto text = write(".stp", sample(5));
  std::set<std::string> defined, used;
  std::regex def(R"(^(#\d+)=)"), ref(R"(#\d+)");
  for (const auto& l : lines_of(text)) {
    std::smatch m;
    if (std::regex_search(l, m, def)) defined.insert(m[1]);
    for (auto it = std::sregex_iterator(l.begin(), l.end(), ref); it != std::sregex_iterator(); ++it)
      used.insert(it->str());
  }
  for (const auto& u : used) CHECK(defined.count(u) == 1);
  CHECK_THAT(text, Catch::StartsWith("ISO-10303-21;") && Catch::EndsWith("END-ISO-10303-21;\n") &&
                       Catch::Contains("AUTOMOTIVE_DESIGN") && Catch::Contains("CARTESIAN_POINT('',(-123.456,0.000,987.654))"));
  CHECK(std::regex_search(text, std::regex(R"(GEOMETRIC_CURVE_SET\('measured points',\(#\d+,#\d+,#\d+,#\d+,#\d+\)\))")));
}

TEST_CASE("DMIS: points as POINT features, and with a fit F, MEAS with every point, FA") {
  auto d = sample(3);
  auto plain = write(".dmi", d);
  CHECK_THAT(plain, Catch::StartsWith("DMISMN/'") && Catch::Contains("UNITS/MM,ANGDEC") &&
                        Catch::Contains("F(PT3)=FEAT/POINT,CART,-102.456,0.002,987.654,0,0,1\nMEAS/POINT,F(PT3),1\n"
                                        "PTMEAS/CART,-102.456,0.002,987.654\nENDMES\n") &&
                        Catch::EndsWith("ENDFIL\n"));
  std::vector<Vector3d> ring;
  for (int deg : {0, 120, 240}) ring.emplace_back(10 * std::cos(deg * M_PI / 180), 10 * std::sin(deg * M_PI / 180), 5);
  ExportData c;
  c.points = ring;
  c.fit = *fit_points(FitKind::Circle, ring);
  c.outer = true;
  auto text = write(".dmi", c);
  CHECK_THAT(text, Catch::Contains("F(CIR1)=FEAT/CIRCLE,OUTER,CART,0.000000,0.000000,5.000000,0.000000000,0.000000000,"
                                   "1.000000000,20.000000\nMEAS/CIRCLE,F(CIR1),3\nPTMEAS/CART,10.000,0.000,5.000\n") &&
                       Catch::Contains("ENDMES\nFA(CIR1)=FEAT/CIRCLE,OUTER,CART,0.000000,0.000000,5.000000"));
}

namespace {

// The numbers after "F(<label>)=FEAT/<word>," (and a leading INNER/OUTER/BND, CART dropped).
std::vector<double> dmis_feature_numbers(const std::string& text, const std::string& word) {
  std::smatch m;
  REQUIRE(std::regex_search(text, m, std::regex("\nF\\([A-Z0-9]+\\)=FEAT/" + word + ",([^\n]*)\n")));
  std::vector<double> out;
  std::istringstream in(m[1].str());
  for (std::string f; std::getline(in, f, ',');)
    if (f != "INNER" && f != "OUTER" && f != "BND" && f != "CART") out.push_back(std::stod(f));
  return out;
}

// Two orthonormal vectors perpendicular to the unit vector n.
std::pair<Vector3d, Vector3d> across(const Vector3d& n) {
  Vector3d u = n.unitOrthogonal();
  return {u, n.cross(u)};
}

double sign_free_angle(const Vector3d& a, const Vector3d& b) {
  return std::min((a.normalized() - b.normalized()).norm(), (a.normalized() + b.normalized()).norm());
}

}  // namespace

TEST_CASE("DMIS: every fitted feature carries its own vector, checked on tilted features") {
  const Vector3d n = Vector3d(0.3, -0.5, 0.81).normalized();  // no coordinate axis, no sign symmetry
  const auto [u, v] = across(n);
  const Vector3d c(12.5, -40.25, 7.75);
  auto dmi = [](FitKind kind, const std::vector<Vector3d>& pts) {
    ExportData d;
    d.points = pts;
    auto fit = fit_points(kind, pts);
    REQUIRE(fit.ok());
    d.fit = *fit;
    return std::pair{write(".dmi", d), *fit};
  };
  auto vec_at = [](const std::vector<double>& f, std::size_t i) { return Vector3d(f.at(i), f.at(i + 1), f.at(i + 2)); };
  std::vector<Vector3d> pts;

  SECTION("plane: its normal") {
    for (double a : {-20.0, 0.0, 15.0})
      for (double b : {-10.0, 5.0, 30.0}) pts.push_back(c + a * u + b * v);
    auto [text, fit] = dmi(FitKind::Plane, pts);
    auto f = dmis_feature_numbers(text, "PLANE");
    REQUIRE(f.size() == 6);
    CHECK((vec_at(f, 3) - *fit.normal).norm() < 1e-8);  // as fitted, sign included (9 decimals)
    CHECK(sign_free_angle(vec_at(f, 3), n) < 1e-8);
  }
  SECTION("circle: its normal") {
    for (int deg = 0; deg < 360; deg += 45)
      pts.push_back(c + 15.0 * (std::cos(deg * M_PI / 180) * u + std::sin(deg * M_PI / 180) * v));
    auto [text, fit] = dmi(FitKind::Circle, pts);
    auto f = dmis_feature_numbers(text, "CIRCLE");
    REQUIRE(f.size() == 7);
    CHECK((vec_at(f, 0) - c).norm() < 1e-6);
    CHECK((vec_at(f, 3) - *fit.normal).norm() < 1e-8);
    CHECK(sign_free_angle(vec_at(f, 3), n) < 1e-8);
    CHECK(f[6] == Approx(30.0).margin(1e-6));
  }
  SECTION("cylinder: its axis") {
    for (double h : {-10.0, 0.0, 25.0})
      for (int deg = 0; deg < 360; deg += 60)
        pts.push_back(c + h * n + 8.0 * (std::cos(deg * M_PI / 180) * u + std::sin(deg * M_PI / 180) * v));
    auto [text, fit] = dmi(FitKind::Cylinder, pts);
    auto f = dmis_feature_numbers(text, "CYLNDR");
    REQUIRE(f.size() == 7);
    CHECK((vec_at(f, 3) - *fit.axis).norm() < 1e-8);
    CHECK(sign_free_angle(vec_at(f, 3), n) < 1e-8);
    CHECK(f[6] == Approx(16.0).margin(1e-6));
  }
  SECTION("cone: its axis, toward the wider end") {
    for (double h : {5.0, 10.0, 20.0})  // apex c, half angle 20 degrees, widening along +n
      for (int deg = 0; deg < 360; deg += 60)
        pts.push_back(c + h * n + h * std::tan(20 * M_PI / 180) *
                                      (std::cos(deg * M_PI / 180) * u + std::sin(deg * M_PI / 180) * v));
    auto [text, fit] = dmi(FitKind::Cone, pts);
    auto f = dmis_feature_numbers(text, "CONE");
    REQUIRE(f.size() == 7);
    CHECK((vec_at(f, 0) - c).norm() < 1e-6);
    CHECK((vec_at(f, 3) - n).norm() < 1e-8);  // the sign is fixed: toward increasing radius
    CHECK(f[6] == Approx(40.0).margin(1e-6));
  }
  SECTION("line: end points along its direction, the vector normal to it") {
    for (double t : {-30.0, -5.0, 10.0, 42.0}) pts.push_back(c + t * u);
    auto [text, fit] = dmi(FitKind::Line, pts);
    auto f = dmis_feature_numbers(text, "LINE");
    REQUIRE(f.size() == 9);
    const Vector3d along = vec_at(f, 3) - vec_at(f, 0);
    CHECK(along.norm() == Approx(72.0).margin(1e-5));
    CHECK(sign_free_angle(along, u) < 1e-7);
    CHECK((along.normalized() - *fit.direction).norm() < 1e-7);  // first end point to second
    CHECK(std::abs(vec_at(f, 6).dot(u)) < 1e-8);
    CHECK(vec_at(f, 6).norm() == Approx(1.0).margin(1e-8));
  }
}

TEST_CASE("DMIS: bare points keep the placeholder vector 0,0,1 and the file says so") {
  auto d = sample(2);
  auto text = write(".dmi", d);
  CHECK_THAT(text, Catch::Contains("F(PT1)=FEAT/POINT,CART,-123.456,0.000,987.654,0,0,1\n") &&
                       Catch::Contains("$$ point vectors 0,0,1 are placeholders"));
  d.fit = *fit_points(FitKind::Plane, std::vector<Vector3d>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  d.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  CHECK_THAT(write(".dmi", d), !Catch::Contains("placeholders") && !Catch::Contains("FEAT/POINT"));
}

TEST_CASE("PLY and JSON: counts in the header, coordinates rounded to the decimals") {
  auto d = sample(4);
  auto ply = write(".ply", d);
  CHECK_THAT(ply, Catch::StartsWith("ply\nformat ascii 1.0\n") && Catch::Contains("element vertex 4\n") &&
                      Catch::Contains("end_header\n-123.456 0.000 987.654\n"));
  d.points[0].x() = 1.23456789;
  auto j = nlohmann::json::parse(write(".json", d));
  CHECK(j["points"].size() == 4);
  CHECK(j["points"][0][0].get<double>() == 1.235);
  CHECK(j["frame"] == "machine");
  CHECK_FALSE(j.contains("fit"));
}
