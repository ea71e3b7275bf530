// messcap -o FILE.hits from a live messd on the simulated table: the reference sphere and the
// cube's top are probed slantwise (off their normals, as a probe driven at an angle meets
// them), captured in the machine frame and in a slanted part frame; messcap fit on the files
// gives the scene's sphere and plane. Only the kept approaches make that so: the surface
// points alone fit a sphere 0.4 mm too big and a top 0.27 mm too high.
#include <catch2/catch.hpp>

#include <cstdio>
#include <memory>
#include <thread>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "daemon_process.hpp"
#include "imess/metrology/frame_store.hpp"
#include "imess/sim/scene.hpp"
#include "tilted_touches.hpp"

using namespace imess::test;
using Eigen::Vector3d;

namespace {

const double kTip = 2.0;            // messd's TipRadius and the simulated ball (fast-cmm.json: the defaults)
const double kSafeZ = 100.0;        // above the sphere (the ball centre touches up to 74.5) and the cube (82)
const double kFitTolerance = 0.0005;  // the fits came out within 0.05 um; the files hold 0.1 um

std::string capture_config() { return std::string(IMESS_SOURCE_DIR) + "/tests/e2e/fast-cmm.json"; }

std::string words(const char* axes, const Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, axes, p.x(), p.y(), p.z());
  return buf;
}

// One touch as queued commands: over the start at the safe height, down to it, Probe 1 mm
// past the expected contact, back to the start, up. Waits for the last one's Done.
void touch(LineClient& c, const TiltedTouch& t, int& id) {
  const Vector3d start = t.centre - 8.0 * t.approach;
  const Vector3d target = t.centre + 1.0 * t.approach;
  const int first = id;
  c.send("MoveTo " + std::to_string(id++) + words(" X%.4f Y%.4f", start) + " Z" + std::to_string(kSafeZ));
  c.send("MoveTo " + std::to_string(id++) + words(" X%.4f Y%.4f Z%.4f", start));
  c.send("Probe " + std::to_string(id++) + words(" X%.4f Y%.4f Z%.4f", target) + " F20");
  c.send("MoveTo " + std::to_string(id++) + words(" X%.4f Y%.4f Z%.4f", start));
  c.send("MoveTo " + std::to_string(id) + " Z" + std::to_string(kSafeZ));
  const std::string done = "Done " + std::to_string(id);
  const auto end = c.until([&](const std::string& l) { return l == done || l.rfind("Failed ", 0) == 0 || l.rfind("Err ", 0) == 0; },
                           60.0);
  INFO("touch from command " << first << ":\n" << c.raw());
  REQUIRE(end == done);
  ++id;
}

// A capture started and connected (its start probe sent), before anything is measured.
std::unique_ptr<ChildProcess> start_capture(int port, std::vector<std::string> extra) {
  std::vector<std::string> argv{client_binary("messcap"), "127.0.0.1:" + std::to_string(port)};
  argv.insert(argv.end(), extra.begin(), extra.end());
  auto cap = std::make_unique<ChildProcess>(argv);
  for (auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5); cap->err().find("connected to") == std::string::npos;) {
    REQUIRE(std::chrono::steady_clock::now() < until);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  return cap;
}

nlohmann::json fit(const std::vector<std::string>& args) {
  std::vector<std::string> argv{client_binary("messcap"), "fit"};
  argv.insert(argv.end(), args.begin(), args.end());
  const auto r = run_program(argv);
  INFO(r.err);
  REQUIRE(r.status == 0);
  return nlohmann::json::parse(r.out);
}

Vector3d vec(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

}  // namespace

TEST_CASE("messcap captures slantwise touches into .hits from live messd and messcap fit finds the scene's sphere and top", "[long]") {
  DaemonProcess messd({"--config", capture_config()});
  TempDir dir;
  const int port = messd.port();
  LineClient c(messd.port());
  REQUIRE(c.next());  // CurrCor: connected

  // A part frame turned 40 deg about a slanted axis and moved.
  const imess::metrology::Frame part(
      Eigen::AngleAxisd(degrees(40), Vector3d(0.3, -0.5, 0.81).normalized()).toRotationMatrix(), Vector3d(700, 600, 10));
  imess::metrology::FrameStore store;
  store.set("part", part.matrix());
  imess::metrology::save_frame_store(dir.file("frames.json"), store);

  const auto sphere = imess::sim::reference_sphere();
  const auto ball_touches = sphere_touches(sphere.center, sphere.diameter / 2, kTip, 25,
                                           {{20, 0}, {20, 72}, {20, 144}, {20, 216}, {20, 288}, {55, 36}, {55, 180}, {85, 0}});
  const std::string n = std::to_string(ball_touches.size());
  auto in_machine = start_capture(port, {"-n", n, "-o", dir.file("ball.hits"), "--fit", "sphere"});
  auto in_part = start_capture(port, {"-n", n, "-o", dir.file("ball-part.hits"), "--frame", "part", "--frames", dir.file("frames.json")});
  int id = 1;
  for (const auto& t : ball_touches) touch(c, t, id);
  REQUIRE(in_machine->wait(10s) == 0);
  REQUIRE(in_part->wait(10s) == 0);

  const auto ball = fit({"sphere", dir.file("ball.hits")});
  INFO(ball.dump());
  CHECK(ball["diameter"].get<double>() == Approx(sphere.diameter).margin(kFitTolerance));
  CHECK((vec(ball["center"]) - sphere.center).norm() < kFitTolerance);
  CHECK(fit({"--surface", "sphere", dir.file("ball.hits")})["diameter"].get<double>() > sphere.diameter + 0.3);
  // capture --fit into .hits printed the same compensated sphere.
  const auto out = in_machine->out();
  const auto printed = nlohmann::json::parse(out.substr(out.rfind('\n', out.size() - 2) + 1));
  CHECK(printed["diameter"].get<double>() == Approx(ball["diameter"].get<double>()).margin(1e-5));
  // In the part frame: the same sphere where the frame sees it (every approach turned with it).
  const auto ball_in_part = fit({"sphere", dir.file("ball-part.hits")});
  CHECK(ball_in_part["diameter"].get<double>() == Approx(sphere.diameter).margin(kFitTolerance));
  CHECK((vec(ball_in_part["center"]) - part.point_from_parent(sphere.center)).norm() < kFitTolerance);

  // The cube's top (z 80), away from its bore and its rounded front edge, touched 30 deg off
  // the vertical from four sides and one diagonal.
  const auto top_touches = top_face_touches(80, kTip, 30, {{415, 325, 0}, {505, 325, 90}, {505, 385, 180}, {415, 385, 270}, {440, 392, 45}});
  auto top_capture = start_capture(port, {"-n", std::to_string(top_touches.size()), "-o", dir.file("top.hits")});
  for (const auto& t : top_touches) touch(c, t, id);
  REQUIRE(top_capture->wait(10s) == 0);
  const auto top = fit({"plane", dir.file("top.hits")});
  INFO(top.dump());
  CHECK(std::abs(vec(top["normal"]).z()) == Approx(1.0).margin(1e-6));
  CHECK(vec(top["point"]).z() == Approx(80.0).margin(kFitTolerance));
  CHECK(fit({"--surface", "plane", dir.file("top.hits")})["point"][2].get<double>() > 80.2);
}
