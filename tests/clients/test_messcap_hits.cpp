// .hits files: each hit's surface point, approach direction and tip radius, written by a
// capture (PointFile and the built messcap against a fake daemon) and by convert, read back by
// metrology::parse_probed_points; in a frame the approach turns with the points; --append
// continues after the last hit number; a messd without Hit is refused, never written as hits.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "fake_daemon.hpp"
#include "frame_option.hpp"
#include "hit_numbers.hpp"
#include "imess/exchange/export_format.hpp"
#include "imess/metrology/frame_store.hpp"
#include "imess/metrology/point_file.hpp"
#include "imess/protocol/messages.hpp"
#include "point_file.hpp"
#include "tilted_touches.hpp"

using namespace imess::messcap;
using Eigen::Vector3d;
using imess::metrology::ProbedPoint;
using imess::test::client_binary;
using imess::test::FakeDaemon;
using imess::test::FakeDaemonScript;
using imess::test::read_file;
using imess::test::run_program;
using imess::test::TempDir;
using imess::test::TiltedTouch;

namespace {

// The reference sphere of the simulated table, touched 25 deg off its normal with a 2 mm tip.
const Vector3d kCentre(750, 650, 60);
const double kDiameter = 25.0;
std::vector<TiltedTouch> sphere_touches() {
  return imess::test::sphere_touches(kCentre, kDiameter / 2, 2.0, 25,
                                     {{20, 0}, {20, 72}, {20, 144}, {20, 216}, {20, 288}, {55, 36}, {55, 180}, {85, 0}});
}

// Turned 40 deg about a slanted axis (no coordinate axis, no symmetry) and moved: a direction
// left unturned, or turned the wrong way, shows in every number.
imess::metrology::Frame slanted_frame() {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(imess::test::degrees(40), Vector3d(0.3, -0.5, 0.81).normalized()).toRotationMatrix();
  return imess::metrology::Frame(r, Vector3d(700, 600, 10));
}

std::string frames_file(const TempDir& dir) {
  imess::metrology::FrameStore store;
  store.set("part", slanted_frame().matrix());
  const auto path = dir.file("frames.json");
  imess::metrology::save_frame_store(path, store);
  return path;
}

// messd's Hit line for a touch (4 decimals for the point and radius, 6 for the direction).
std::string hit_line(std::uint64_t seq, const Vector3d& surface, const Vector3d& approach, double radius) {
  imess::protocol::HitMsg h{seq, 0, {surface.x(), surface.y(), surface.z()}, {approach.x(), approach.y(), approach.z()},
                            radius, 10.0 + static_cast<double>(seq)};
  std::string line = imess::protocol::format_hit(h);
  line.pop_back();  // the fake daemon adds the "\n"
  return line;
}
std::string hit_line(std::uint64_t seq, const TiltedTouch& t) { return hit_line(seq, t.reported(), t.approach, t.tip); }

std::string meas_line(const Vector3d& p) {
  std::string line = imess::protocol::format_meas_pt({p.x(), p.y(), p.z()});
  line.pop_back();
  return line;
}

// A line of a hits file written by hand: "x y z i j k r".
std::string hits_file_line(const TiltedTouch& t) {
  const Vector3d s = t.reported();
  char line[160];
  std::snprintf(line, sizeof line, "%.4f %.4f %.4f %.6f %.6f %.6f %.4f\n", s.x(), s.y(), s.z(), t.approach.x(), t.approach.y(),
                t.approach.z(), t.tip);
  return line;
}

nlohmann::json fit(const std::vector<std::string>& args) {
  std::vector<std::string> argv{client_binary("messcap"), "fit"};
  argv.insert(argv.end(), args.begin(), args.end());
  auto r = run_program(argv);
  INFO(r.err);
  REQUIRE(r.status == 0);
  return nlohmann::json::parse(r.out);
}

Vector3d vec(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

// The lines of a file that are not comments.
std::vector<std::string> data_lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at < text.size()) {
    const auto end = text.find('\n', at);
    std::string line = text.substr(at, end - at);
    if (!line.empty() && line[0] != '#') out.push_back(line);
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return out;
}

}  // namespace

TEST_CASE(".hits line: point and radius with the decimals asked, approach with 6, a forced point as 0 0 0 and r 0") {
  const auto& f = imess::exchange::export_format_for("dir/P.HITS");
  CHECK(f.extension == ".hits");
  CHECK(f.appendable());
  CHECK(f.needs_approach());
  CHECK(f.hit_line(ProbedPoint{{1.5, -2, 80.00004}, {0.6, 0, -0.8}, 2}, 4) ==
        "1.5000 -2.0000 80.0000 0.600000 0.000000 -0.800000 2.0000\n");
  CHECK(f.hit_line(ProbedPoint{{1, 2, 3}, {0, -0.0, 0}, 0}, 4) == "1.0000 2.0000 3.0000 0.000000 0.000000 0.000000 0.0000\n");
  for (const auto& other : imess::exchange::export_formats())
    if (other.extension != ".hits") CHECK_FALSE(other.needs_approach());
  // Whole: a header comment, then the hits; points without their hits are refused.
  imess::exchange::ExportData d;
  d.decimals = 3;
  d.points = {{1, 2, 3}};
  CHECK_THROWS_AS(f.write(d), imess::exchange::FormatError);
  d.hits = {ProbedPoint{{1, 2, 3}, {0, 0, 1}, 1.5}};
  CHECK(f.write(d) == f.header() + "1.000 2.000 3.000 0.000000 0.000000 1.000000 1.500\n");
  CHECK(f.header().front() == '#');
  CHECK(imess::exchange::appendable_extensions() == ".csv, .xyz, .asc and .hits");
}

TEST_CASE("PointFile .hits in a frame: the point moved and turned, the approach only turned, read back by parse_probed_points") {
  TempDir dir;
  const auto path = dir.file("part.hits");
  const auto frame = slanted_frame();
  const Eigen::Matrix3d r = frame.rotation();
  const Vector3d t = frame.translation();
  auto touches = sphere_touches();
  {
    imess::exchange::ExportData base;
    base.decimals = imess::exchange::kHitDecimals;
    PointFile file(path, OpenMode::New, base);
    REQUIRE(file.needs_approach());
    std::uint64_t seq = 10;
    for (const auto& touch : touches)
      file.append(hit_from_parent(frame, {touch.reported(), touch.approach, touch.tip}), PointNumber{seq++, {}});
    file.append(hit_from_parent(frame, ProbedPoint{{430, 330, 82.5}, Vector3d::Zero(), 0}), PointNumber{seq++, {}});  // a ForcePt
    // A point without its approach never goes into a hits file.
    CHECK_THROWS_AS(file.append(Vector3d(1, 2, 3), PointNumber{seq, {}}), std::logic_error);
    CHECK(file.points() == static_cast<int>(touches.size()) + 1);
    file.flush();
  }
  const std::string text = read_file(path);
  const auto back = imess::metrology::parse_probed_points(text, path);
  REQUIRE(back.size() == touches.size() + 1);
  for (std::size_t i = 0; i < touches.size(); ++i) {
    INFO("hit " << i);
    CHECK((back[i].surface - r.transpose() * (touches[i].reported() - t)).norm() < 1e-4);
    CHECK((back[i].approach - r.transpose() * touches[i].approach).norm() < 2e-6);
    CHECK(back[i].radius == 2.0);
    CHECK((back[i].centre() - r.transpose() * (touches[i].centre - t)).norm() < 1e-4);  // the ball where it was
  }
  CHECK_FALSE(back.back().has_approach());
  CHECK(back.back().radius == 0.0);
  CHECK((back.back().surface - r.transpose() * (Vector3d(430, 330, 82.5) - t)).norm() < 1e-4);
  const auto lines = data_lines(text);
  REQUIRE(lines.size() == touches.size() + 1);
  for (std::size_t i = 0; i < lines.size(); ++i) CHECK_THAT(lines[i], Catch::EndsWith(" # hit " + std::to_string(10 + i)));
  CHECK(last_hit_number(path) == 10 + touches.size());
}

TEST_CASE("messcap -o FILE.hits: every Hit with its approach and tip radius, turned into a frame, fitted compensated") {
  TempDir dir;
  const auto touches = sphere_touches();
  std::vector<std::string> session{"CurrCor 750.000 650.000 100.000"};
  std::uint64_t seq = 5;
  for (const auto& touch : touches) {
    session.push_back(hit_line(seq++, touch));
    session.push_back(meas_line(touch.reported()));
    session.push_back("State retract");
  }
  FakeDaemon daemon({0, session, [](const std::string& line) -> std::vector<std::string> {
                       if (line == "Hello messcap") return {"Ok Hello IMESS 1 messd 0.9 Caps jog goto probe journal queue"};
                       if (line == "Replay 9007199254740991") return {"Ok Replay 0 4"};  // the start probe
                       return {};
                     }});
  const std::string n = std::to_string(touches.size());
  const auto machine = dir.file("ball.hits");
  auto r = run_program({client_binary("messcap"), daemon.address(), "-n", n, "-o", machine, "--fit", "sphere"});
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto hits = imess::metrology::read_probed_points(machine);
  REQUIRE(hits.size() == touches.size());
  for (std::size_t i = 0; i < hits.size(); ++i) {
    CHECK((hits[i].surface - touches[i].reported()).norm() < 1e-4);
    CHECK((hits[i].approach - touches[i].approach).norm() < 2e-6);
    CHECK(hits[i].radius == 2.0);
  }
  CHECK(last_hit_number(machine) == 4 + touches.size());
  // The file fits probe-compensated to the sphere that was touched; its surface points alone
  // (the approach thrown away) give one 0.4 mm too big — the approach is what makes it right.
  const auto ball = fit({"sphere", machine});
  CHECK(ball["diameter"].get<double>() == Approx(kDiameter).margin(2e-4));
  CHECK((vec(ball["center"]) - kCentre).norm() < 2e-4);
  CHECK(fit({"--surface", "sphere", machine})["diameter"].get<double>() > kDiameter + 0.3);
  // capture --fit into .hits fits as `messcap fit` does on the file it wrote.
  const auto printed = nlohmann::json::parse(r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1));
  CHECK(printed["diameter"].get<double>() == Approx(ball["diameter"].get<double>()).margin(1e-5));
  CHECK((vec(printed["center"]) - vec(ball["center"])).norm() < 1e-5);

  // In the part frame: the same ball, where the frame sees it — only if every approach turned.
  const auto part = dir.file("ball-part.hits");
  r = run_program({client_binary("messcap"), daemon.address(), "-n", n, "-o", part, "--frame", "part", "--frames",
                   frames_file(dir)});
  REQUIRE(r.status == 0);
  const auto frame = slanted_frame();
  const auto in_part = fit({"sphere", part});
  CHECK(in_part["diameter"].get<double>() == Approx(kDiameter).margin(2e-4));
  CHECK((vec(in_part["center"]) - frame.rotation().transpose() * (kCentre - frame.translation())).norm() < 2e-4);
  const Vector3d first = frame.point_from_parent(touches[0].reported());
  char printed_first[96];
  std::snprintf(printed_first, sizeof printed_first, "point 1: %.3f %.3f %.3f (hit ", first.x(), first.y(), first.z());
  CHECK_THAT(r.out, Catch::StartsWith(printed_first));
}

TEST_CASE("messcap --append to a .hits file continues after its last hit, a ForcePt kept as 0 0 0 with r 0") {
  TempDir dir;
  const auto path = dir.file("more.hits");
  const auto touches = sphere_touches();
  {
    imess::exchange::ExportData base;
    base.decimals = imess::exchange::kHitDecimals;
    PointFile file(path, OpenMode::New, base);
    file.append(ProbedPoint{touches[0].reported(), touches[0].approach, 2.0}, PointNumber{4, {}});
    file.append(ProbedPoint{touches[1].reported(), touches[1].approach, 2.0}, PointNumber{5, {}});
    file.flush();
  }
  const std::string before = read_file(path);
  const Vector3d forced(430, 330, 82.5);
  FakeDaemonScript script{0, {"CurrCor 0.000 0.000 0.000"}, [&](const std::string& line) -> std::vector<std::string> {
                            if (line == "Replay 6")
                              return {hit_line(6, touches[2]), hit_line(7, forced, Vector3d::Zero(), 0), "Ok Replay 2 7"};
                            return {};
                          }};
  FakeDaemon daemon(script);
  auto r = run_program({client_binary("messcap"), daemon.address(), "-n", "2", "-o", path, "--append"});
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("continuing after hit 5"));
  const std::string after = read_file(path);
  REQUIRE(after.rfind(before, 0) == 0);  // the old lines untouched, the header once
  const auto lines = data_lines(after);
  REQUIRE(lines.size() == 4);
  CHECK_THAT(lines[2], Catch::EndsWith(" 2.0000 # hit 6"));
  CHECK(lines[3] == "430.0000 330.0000 82.5000 0.000000 0.000000 0.000000 0.0000 # hit 7");
  const auto hits = imess::metrology::read_probed_points(path);
  REQUIRE(hits.size() == 4);
  CHECK((hits[2].approach - touches[2].approach).norm() < 2e-6);
  CHECK_FALSE(hits[3].has_approach());
}

TEST_CASE("messcap -o FILE.hits from a messd without Hit: refused, saying why and what is accepted, nothing written") {
  TempDir dir;
  // Only MeasPt (no journal): the first one ends the capture.
  FakeDaemon plain({0, {"CurrCor 0.000 0.000 0.000", "MeasPt 1.000 2.000 3.000", "MeasPt 4.000 5.000 6.000"}, {}});
  const auto hits = dir.file("x.hits");
  auto r = run_program({client_binary("messcap"), plain.address(), "-n", "2", "-o", hits});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("cannot capture into " + hits) && Catch::Contains("approach direction and tip radius") &&
                        Catch::Contains("MeasPt point without a Hit") && Catch::Contains("Capture into .xyz"));
  CHECK(r.out.empty());
  CHECK_FALSE(imess::test::file_exists(hits));
  // An existing file is left as it was.
  { std::ofstream(hits) << "1.0000 2.0000 3.0000 0.000000 0.000000 -1.000000 2.0000 # hit 3\n"; }
  r = run_program({client_binary("messcap"), plain.address(), "-n", "2", "-o", hits, "--append"});
  CHECK(r.status == 1);
  CHECK(read_file(hits) == "1.0000 2.0000 3.0000 0.000000 0.000000 -1.000000 2.0000 # hit 3\n");
  // The same messd into a file of plain points: taken as ever.
  r = run_program({client_binary("messcap"), plain.address(), "-n", "2", "-o", dir.file("x.xyz")});
  CHECK(r.status == 0);
  CHECK(read_file(dir.file("x.xyz")) == "1.000 2.000 3.000\n4.000 5.000 6.000\n");

  // A messd whose Hello lists no journal is refused at once, before anything is measured.
  FakeDaemon old({0, {"CurrCor 0.000 0.000 0.000"}, [](const std::string& line) -> std::vector<std::string> {
                    if (line == "Hello messcap") return {"Ok Hello IMESS 1 messd 0.5 Caps jog goto home probe"};
                    return {};
                  }});
  r = run_program({client_binary("messcap"), old.address(), "-o", hits, "--force"});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("lists no 'journal' among its Caps") && Catch::Contains("Capture into .xyz"));
}

TEST_CASE("messcap convert: hits keep approach and radius into .hits and turn with --frame, plain formats get the surface points") {
  TempDir dir;
  const auto touches = sphere_touches();
  std::string text = "# a sphere touched slantwise\n";
  for (const auto& touch : touches) text += hits_file_line(touch);
  const auto in = dir.file("in.hits");
  { std::ofstream(in) << text; }
  const std::string messcap = client_binary("messcap");

  auto r = run_program({messcap, "convert", in, dir.file("out.xyz"), "--decimals", "4"});
  REQUIRE(r.status == 0);
  const auto surface = imess::metrology::read_points(dir.file("out.xyz"));
  REQUIRE(surface.size() == touches.size());
  for (std::size_t i = 0; i < surface.size(); ++i) CHECK((surface[i] - touches[i].reported()).norm() < 1e-4);

  r = run_program({messcap, "convert", in, dir.file("part.hits"), "--frame", "part", "--frames", frames_file(dir)});
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto frame = slanted_frame();
  const auto part = imess::metrology::read_probed_points(dir.file("part.hits"));
  REQUIRE(part.size() == touches.size());
  for (std::size_t i = 0; i < part.size(); ++i) {
    CHECK((part[i].surface - frame.point_from_parent(touches[i].reported())).norm() < 1e-4);
    CHECK((part[i].approach - frame.rotation().transpose() * touches[i].approach).norm() < 2e-6);
  }
  // --fit fits hits compensated, as messcap fit does.
  r = run_program({messcap, "convert", in, dir.file("ball.json"), "--fit", "sphere"});
  REQUIRE(r.status == 0);
  CHECK(nlohmann::json::parse(r.out)["diameter"].get<double>() == Approx(kDiameter).margin(2e-4));

  { std::ofstream(dir.file("plain.xyz")) << "1 2 3\n4 5 6\n"; }
  r = run_program({messcap, "convert", dir.file("plain.xyz"), dir.file("plain.hits")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("holds plain points") && Catch::Contains("x y z i j k r") &&
                        Catch::Contains("messcap -o FILE.hits"));
  CHECK_FALSE(imess::test::file_exists(dir.file("plain.hits")));
}
