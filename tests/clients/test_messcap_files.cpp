// messcap fit / convert and capture into the whole-file formats, run as programs: fits agree
// with the NIST reference pairs, frames transform, failures name the points and the reason,
// and csv/xyz/asc/json/dmi/dxf files are parsed back here and checked point by point.
#include <catch2/catch.hpp>

#include <cmath>
#include <csignal>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "fake_daemon.hpp"
#include "imess/metrology/frame_store.hpp"
#include "imess/metrology/point_file.hpp"

using imess::test::ChildProcess;
using imess::test::client_binary;
using imess::test::FakeDaemon;
using imess::test::read_file;
using imess::test::run_program;
using imess::test::TempDir;
using Eigen::Vector3d;

namespace {

const std::string kNist = std::string(IMESS_TEST_DATA) + "/nist-ls/";

std::vector<double> fit_values(const std::string& path) {
  std::ifstream in(path);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

Vector3d vec(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

double angle(const Vector3d& a, const Vector3d& b) {  // sign-free, as ISO 10360-6
  return std::min((a.normalized() - b.normalized()).norm(), (a.normalized() + b.normalized()).norm());
}

nlohmann::json fit_json(const std::string& kind, const std::string& file) {
  auto r = run_program({client_binary("messcap"), "fit", kind, file});
  INFO(r.err);
  REQUIRE(r.status == 0);
  REQUIRE(r.out.find('\n') == r.out.size() - 1);  // one line
  return nlohmann::json::parse(r.out);
}

// Points of a .xyz/.asc/.csv file as written by messcap (CSV: one header line).
std::vector<Vector3d> parse_lines(const std::string& text, char sep, bool header) {
  std::vector<Vector3d> out;
  std::istringstream in(text);
  std::string line;
  if (header) std::getline(in, line);
  while (std::getline(in, line)) {
    for (char& c : line)
      if (c == sep) c = ' ';
    std::istringstream l(line);
    Vector3d p;
    l >> p.x() >> p.y() >> p.z();
    REQUIRE(l);
    out.push_back(p);
  }
  return out;
}

std::vector<Vector3d> dmis_ptmeas(const std::string& text) {
  std::vector<Vector3d> out;
  std::regex re(R"(PTMEAS/CART,([-0-9.]+),([-0-9.]+),([-0-9.]+))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
    out.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]));
  return out;
}

std::vector<Vector3d> dxf_points(const std::string& text) {  // group code / value pairs
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  std::vector<Vector3d> out;
  for (std::size_t i = 0; i + 1 < v.size(); i += 2)
    if (std::stoi(v[i]) == 0 && v[i + 1] == "POINT") {
      Vector3d p;
      for (std::size_t k = i + 2; k + 1 < v.size() && std::stoi(v[k]) != 0; k += 2) {
        int code = std::stoi(v[k]);
        if (code == 10 || code == 20 || code == 30) p[(code - 10) / 10] = std::stod(v[k + 1]);
      }
      out.push_back(p);
    }
  return out;
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// A frame turned 90 deg about z and moved to (100, 0, 0): part x = machine y - 0, ...
std::string frame_store(const TempDir& dir) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  m.block<3, 1>(0, 3) << 100, 0, 0;
  imess::metrology::FrameStore store;
  store.set("part", m);
  auto path = dir.file("frames.json");
  imess::metrology::save_frame_store(path, store);
  return path;
}

}  // namespace

TEST_CASE("messcap fit: NIST reference pairs, one JSON object each") {
  SECTION("circle (3-D)") {
    auto ref = fit_values(kNist + "Circle3d/cir5.fit");
    auto j = fit_json("circle", kNist + "Circle3d/cir5.ds");
    CHECK(j["type"] == "circle");
    CHECK((vec(j["center"]) - Vector3d(ref[0], ref[1], ref[2])).norm() < 1e-7);
    CHECK(angle(vec(j["normal"]), Vector3d(ref[3], ref[4], ref[5])) < 1e-9);
    CHECK(j["diameter"].get<double>() == Approx(ref[6]).margin(1e-7));
    CHECK(j["rms"].get<double>() > 0);
    CHECK(j["form_min"].get<double>() < 0);
    CHECK(j["form_max"].get<double>() > 0);
  }
  SECTION("sphere") {
    auto ref = fit_values(kNist + "Sphere/sph5.fit");
    auto j = fit_json("sphere", kNist + "Sphere/sph5.ds");
    CHECK((vec(j["center"]) - Vector3d(ref[0], ref[1], ref[2])).norm() < 1e-7);
    CHECK(j["diameter"].get<double>() == Approx(ref[3]).margin(1e-7));
  }
  SECTION("cylinder") {
    auto ref = fit_values(kNist + "Cylinder/cyl21.fit");
    auto j = fit_json("cylinder", kNist + "Cylinder/cyl21.ds");
    CHECK((vec(j["point"]) - Vector3d(ref[0], ref[1], ref[2])).norm() < 1e-7);
    CHECK(angle(vec(j["axis"]), Vector3d(ref[3], ref[4], ref[5])) < 1e-9);
    CHECK(j["diameter"].get<double>() == Approx(ref[6]).margin(1e-7));
  }
  SECTION("cone: axis toward increasing radius, apex on the axis, full angle") {
    auto ref = fit_values(kNist + "Cone/con17.fit");
    auto j = fit_json("cone", kNist + "Cone/con17.ds");
    Vector3d point = vec(j["point"]), axis = vec(j["axis"]), apex = vec(j["apex"]);
    CHECK((point - Vector3d(ref[0], ref[1], ref[2])).norm() < 1e-7);
    CHECK((axis - Vector3d(ref[3], ref[4], ref[5])).norm() < 1e-9);  // same sense
    CHECK(j["apex_angle_deg"].get<double>() == Approx(ref[7]).margin(1e-8));
    const double half = ref[7] * M_PI / 360;
    CHECK(j["diameter"].get<double>() == Approx(2 * ref[6] / std::cos(half)).margin(1e-7));
    CHECK((point - apex).normalized().dot(axis) == Approx(1.0).margin(1e-12));
    CHECK((point - apex).norm() * std::tan(half) == Approx(ref[6] / std::cos(half)).margin(1e-7));
  }
  SECTION("plane, line, line2d") {
    auto ref = fit_values(kNist + "Plane/pla7.fit");
    auto j = fit_json("plane", kNist + "Plane/pla7.ds");
    CHECK((vec(j["point"]) - Vector3d(ref[0], ref[1], ref[2])).norm() < 1e-7);
    CHECK(angle(vec(j["normal"]), Vector3d(ref[3], ref[4], ref[5])) < 1e-9);
    ref = fit_values(kNist + "Line3d/lin3.fit");
    j = fit_json("line", kNist + "Line3d/lin3.ds");
    CHECK(angle(vec(j["direction"]), Vector3d(ref[3], ref[4], ref[5])) < 1e-9);
    ref = fit_values(kNist + "Line2d/lin2d1.fit");
    j = fit_json("line2d", kNist + "Line2d/lin2d1.ds");
    CHECK((vec(j["point"]) - Vector3d(ref[0], ref[1], ref[2])).norm() < 1e-7);
    CHECK(angle(vec(j["direction"]), Vector3d(ref[3], ref[4], ref[5])) < 1e-9);
    CHECK(j["n"] == 33);
  }
}

TEST_CASE("messcap fit: stdin, and failures name the points and the reason") {
  TempDir dir;
  write_text(dir.file("line.xyz"), "1 0 0\n2 0 0\n3 0 0\n");
  auto r = run_program({"/bin/sh", "-c", client_binary("messcap") + " fit sphere - < " + kNist + "Sphere/sph5.ds"});
  CHECK(r.status == 0);
  CHECK(nlohmann::json::parse(r.out)["type"] == "sphere");
  r = run_program({client_binary("messcap"), "fit", "circle", dir.file("line.xyz")});
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::StartsWith("messcap: fit circle to the 3 points of " + dir.file("line.xyz") +
                                      " failed (collinear_points): ") &&
                        Catch::Contains("collinear"));
  write_text(dir.file("bad.xyz"), "1 2 3\n4 five 6\n");
  r = run_program({client_binary("messcap"), "fit", "plane", dir.file("bad.xyz")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains(dir.file("bad.xyz") + ":2:"));
  r = run_program({client_binary("messcap"), "fit", "torus", dir.file("line.xyz")});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("unknown feature kind 'torus'; accepted: line, line2d, plane"));
  r = run_program({client_binary("messcap"), "fit"});
  CHECK(r.status == 2);
}

TEST_CASE("messcap fit: hits with approach and tip radius are fitted probe-compensated, --surface plainly") {
  // A bore of diameter 20 (axis z through (100, 50)) probed with a 1 mm tip moving outward: the
  // surface points messd reports lie on radius 10, the ball centres on radius 9.
  TempDir dir;
  std::string hits = "# x y z i j k r\n";
  for (int i = 0; i < 12; ++i) {
    const double t = 0.5 * i;
    char line[160];
    std::snprintf(line, sizeof line, "%.4f %.4f %.4f %.6f %.6f 0 1.0000\n", 100 + 10 * std::cos(t), 50 + 10 * std::sin(t),
                  5.0 * (i % 3), std::cos(t), std::sin(t));
    hits += line;
  }
  write_text(dir.file("bore.hits"), hits);
  const auto probed = fit_json("cylinder", dir.file("bore.hits"));
  CHECK(probed["diameter"].get<double>() == Approx(20.0).margin(1e-3));
  CHECK((vec(probed["point"]).head<2>() - Eigen::Vector2d(100, 50)).norm() < 1e-3);
  // The surface path fits the same surface points: same bore, with the residuals of the surface.
  auto r = run_program({client_binary("messcap"), "fit", "--surface", "cylinder", dir.file("bore.hits")});
  REQUIRE(r.status == 0);
  CHECK(nlohmann::json::parse(r.out)["diameter"].get<double>() == Approx(20.0).margin(1e-3));
  // A ball centre fit of the wrong side would give 18 (radius 9 - 1): hits moving inward = a shaft.
  std::string shaft;
  for (int i = 0; i < 12; ++i) {
    const double t = 0.5 * i;
    char line[160];
    std::snprintf(line, sizeof line, "%.4f %.4f %.4f %.6f %.6f 0 1.0000\n", 10 * std::cos(t), 10 * std::sin(t),
                  5.0 * (i % 3), -std::cos(t), -std::sin(t));
    shaft += line;
  }
  write_text(dir.file("shaft.hits"), shaft);
  CHECK(fit_json("cylinder", dir.file("shaft.hits"))["diameter"].get<double>() == Approx(20.0).margin(1e-3));
  // A forced point (no direction) cannot be compensated: the error says so and names --surface.
  write_text(dir.file("forced.hits"), "0 0 0 0 0 1 2\n1 0 0 0 0 1 2\n0 1 0 0 0 0 0\n");
  r = run_program({client_binary("messcap"), "fit", "plane", dir.file("forced.hits")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("hit 2 has no approach direction") && Catch::Contains("--surface"));
  write_text(dir.file("bad.hits"), "0 0 0 0 0 1 2\n1 0 0 0 0.5 0.5 2\n");
  r = run_program({client_binary("messcap"), "fit", "plane", dir.file("bad.hits")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains(dir.file("bad.hits") + ":2:7:") && Catch::Contains("unit vector"));
}

TEST_CASE("messcap convert: csv, xyz, asc, json and dmi read back point by point, in a frame") {
  TempDir dir;
  const std::vector<Vector3d> pts{{0, 0, 0}, {430.125, 330, 80}, {-12.5, 7.25, 600}, {1, 2, 3}};
  std::string text = "4\n";
  for (const auto& p : pts) text += std::to_string(p.x()) + "\t" + std::to_string(p.y()) + "\t" + std::to_string(p.z()) + "\n";
  write_text(dir.file("in.ds"), text);
  for (const char* ext : {".csv", ".xyz", ".asc", ".json", ".dmi"}) {
    INFO(ext);
    auto out = dir.file(std::string("out") + ext);
    auto r = run_program({client_binary("messcap"), "convert", dir.file("in.ds"), out, "--decimals", "3"});
    REQUIRE(r.status == 0);
    auto content = read_file(out);
    std::vector<Vector3d> got;
    if (std::string(ext) == ".json") {
      const auto doc = nlohmann::json::parse(content);
      for (const auto& p : doc["points"]) got.push_back(vec(p));
    } else if (std::string(ext) == ".dmi") {
      got = dmis_ptmeas(content);
    } else {
      got = parse_lines(content, std::string(ext) == ".csv" ? ',' : ' ', std::string(ext) == ".csv");
    }
    REQUIRE(got.size() == pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) CHECK((got[i] - pts[i]).norm() < 1e-9);
  }
  // The csv just written is valid input again (its header is skipped).
  CHECK(run_program({client_binary("messcap"), "fit", "plane", dir.file("out.csv")}).status == 0);

  auto frames = frame_store(dir);
  auto r = run_program({client_binary("messcap"), "convert", dir.file("in.ds"), dir.file("part.xyz"), "--frame", "part",
                        "--frames", frames});
  REQUIRE(r.status == 0);
  auto got = parse_lines(read_file(dir.file("part.xyz")), ' ', false);
  REQUIRE(got.size() == 4);
  CHECK((got[1] - Vector3d(330, -430.125 + 100, 80)).norm() < 1e-9);  // R^T (p - t)
  r = run_program({client_binary("messcap"), "convert", dir.file("in.ds"), dir.file("x.xyz"), "--frame", "tool",
                   "--frames", frames});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("no frame 'tool'") && Catch::Contains("it holds: part"));
  r = run_program({client_binary("messcap"), "convert", dir.file("in.ds"), dir.file("y.xyz"), "--frame", "part"});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("needs --frames FILE"));
  r = run_program({client_binary("messcap"), "convert", dir.file("in.ds"), dir.file("out.csv")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("exists; add --force"));
  r = run_program({client_binary("messcap"), "convert", dir.file("in.ds"), dir.file("out.step")});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("unknown extension '.step'; accepted: .csv, .xyz, .asc, .hits, .json, .ply, .dxf, .igs, "
                                    ".stp, .dmi"));
}

TEST_CASE("messcap capture --fit: the fit printed at the end and written into .json and .dmi") {
  TempDir dir;
  std::vector<std::string> session{"CurrCor 0.000 0.000 0.000"};
  for (int deg : {0, 90, 180, 270}) {  // a bore D 30 at (460, 350), z 40
    double a = deg * M_PI / 180;
    char line[80];
    std::snprintf(line, sizeof line, "MeasPt %.3f %.3f 40.000", 460 + 15 * std::cos(a), 350 + 15 * std::sin(a));
    session.push_back(line);
    session.push_back("State idle");
  }
  FakeDaemon daemon({0, session, {}});
  auto json_path = dir.file("bore.json");
  auto r = run_program({client_binary("messcap"), daemon.address(), "-n", "4", "-o", json_path, "--fit", "circle",
                        "--frame", "part", "--frames", frame_store(dir)});
  INFO(r.err);
  REQUIRE(r.status == 0);
  auto last_line = r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1);
  auto printed = nlohmann::json::parse(last_line);
  auto file = nlohmann::json::parse(read_file(json_path));
  CHECK(file["frame"] == "part");
  CHECK(file["points"].size() == 4);
  CHECK((vec(file["points"][0]) - Vector3d(350, -475 + 100, 40)).norm() < 1e-9);  // (475, 350) in the frame
  CHECK(file["fit"] == printed);
  CHECK(printed["diameter"].get<double>() == Approx(30.0).margin(1e-9));
  CHECK((vec(printed["center"]) - Vector3d(350, -360, 40)).norm() < 1e-9);
  CHECK_THAT(r.out, Catch::StartsWith("point 1: 350.000 -375.000 40.000\n"));

  auto dmi = dir.file("bore.dmi");
  r = run_program({client_binary("messcap"), daemon.address(), "-n", "4", "-o", dmi, "--fit", "circle"});
  REQUIRE(r.status == 0);
  auto text = read_file(dmi);
  CHECK_THAT(text, Catch::Contains("MEAS/CIRCLE,F(CIR1),4\n") && Catch::Contains("FA(CIR1)=FEAT/CIRCLE,INNER,CART,"
                                                                                  "460.000000,350.000000,40.000000,"));
  CHECK(dmis_ptmeas(text).size() == 4);
  CHECK((dmis_ptmeas(text)[1] - Vector3d(460, 365, 40)).norm() < 1e-9);

  r = run_program({client_binary("messcap"), daemon.address(), "-n", "2", "--fit", "sphere"});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("fit sphere to the 2 points of this capture failed (too_few_points)"));
}

TEST_CASE("messcap capture into .dxf: a complete file after every point, nothing lost on Ctrl-C") {
  TempDir dir;
  auto dxf = dir.file("live.dxf");
  FakeDaemon daemon({0, {"MeasPt 1.000 2.000 3.000"}, {}});
  ChildProcess cap({client_binary("messcap"), daemon.address(), "-o", dxf});
  REQUIRE(cap.wait_for_output("point 1:"));
  auto first = read_file(dxf);  // written before the point was printed
  CHECK_THAT(first, Catch::EndsWith("  0\nEOF\n"));
  CHECK(dxf_points(first) == std::vector<Vector3d>{{1, 2, 3}});
  daemon.send("MeasPt -4.500 5.000 6.125");
  daemon.send("MeasPt 7.000 8.000 9.000");
  REQUIRE(cap.wait_for_output("point 3:"));
  cap.signal(SIGINT);
  REQUIRE(cap.wait() == 0);
  CHECK(dxf_points(read_file(dxf)) == std::vector<Vector3d>{{1, 2, 3}, {-4.5, 5, 6.125}, {7, 8, 9}});
  CHECK_FALSE(imess::test::file_exists(dxf + ".tmp"));

  auto again = run_program({client_binary("messcap"), daemon.address(), "-o", dxf, "--append"});
  CHECK(again.status == 2);
  CHECK_THAT(again.err, Catch::Contains("written whole") && Catch::Contains(".csv, .xyz, .asc and .hits"));
}
