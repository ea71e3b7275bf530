// messcap qualify on the simulated machine: the reference sphere of the default table is
// touched with Probe cycles; the radius must come out as the simulated ball's (1.9985 mm), not
// messd's 1.9 mm it started with, and the offset as the nominal centre given less where the
// sphere is. Another client hears Qualified, Get reads the new values, the --rc file holds them
// and a messd started with it has them again. A sphere that is not where --sphere says is named.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "daemon_process.hpp"
#include "imess/sim/scene.hpp"

using namespace imess::test;
using nlohmann::json;

namespace {

const double kBall = 1.9985;  // sim.probe.ball_radius in qualify-cmm.json
const double kHalfMicron = 0.0005;

std::string config() { return std::string(IMESS_SOURCE_DIR) + "/tests/e2e/qualify-cmm.json"; }

double got(LineClient& c, const std::string& name) {
  const auto reply = c.request("Get " + name);
  REQUIRE(reply);
  std::istringstream words(*reply);
  std::string ok, get, n;
  double v = 0;
  REQUIRE(words >> ok >> get >> n >> v);
  CHECK(n == name);
  return v;
}

// The value after `word` in a line of words.
double after(const std::string& line, const std::string& word, int skip = 0) {
  std::istringstream words(line);
  std::string w;
  while (words >> w)
    if (w == word) {
      for (int k = 0; k < skip; ++k) words >> w;
      double v = 0;
      words >> v;
      return v;
    }
  FAIL("no " << word << " in '" << line << "'");
  return 0;
}

}  // namespace

TEST_CASE("messcap qualify measures the simulated ball on the reference sphere and messd takes it over", "[long]") {
  DaemonProcess messd({"--config", config()}, DaemonProcess::Scheduling::RealtimeIfPermitted);
  TempDir dir;
  const auto sphere = imess::sim::reference_sphere();
  LineClient observer(messd.port());
  REQUIRE(observer.request("Status"));
  CHECK(got(observer, "TipRadius") == Approx(1.9));

  // An offset in use already (a stylus qualified before): the points come shifted by it, and
  // the new offset must take it back out. The nominal centre given is 20 um off in X, 10 in Y.
  {
    LineClient c(messd.port());
    REQUIRE(c.request("Take") == std::optional<std::string>("Ok Take"));
    REQUIRE(c.request("Set ProbeOffX 0.3"));
    REQUIRE(c.request("Release"));
  }
  const Eigen::Vector3d nominal = sphere.center + Eigen::Vector3d(0.02, -0.01, 0);
  char where[64];
  std::snprintf(where, sizeof where, "%.3f,%.3f,%.3f", nominal.x(), nominal.y(), nominal.z());
  {
    std::ofstream rc(dir.file("stylus.rc"));
    rc << "# stylus: 4 mm ruby ball, 20 mm shaft\nSpeedLevel 1.0   # all speeds\nTipRadius 2.0    # mm\n";
  }
  const auto run = run_program({client_binary("messcap"), "qualify", "127.0.0.1:" + std::to_string(messd.port()), "--sphere", where,
                                "--diameter", std::to_string(sphere.diameter), "--rc", dir.file("stylus.rc"), "--json",
                                dir.file("q.json"), "--feed", "100"},
                               240s);
  INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
  REQUIRE(run.status == 0);
  const json report = json::parse(read_file(dir.file("q.json")));
  CHECK(report["qualified"] == true);
  CHECK(report["touches"].size() == 9);
  const double radius = report["tip_radius"].get<double>();
  CHECK(radius == Approx(kBall).margin(kHalfMicron));
  CHECK(report["form"].get<double>() < kHalfMicron);
  const Eigen::Vector3d expected_offset = nominal - sphere.center;  // 0.3 in use + nominal - (sphere + 0.3)
  for (int k = 0; k < 3; ++k) CHECK(report["offset"][k].get<double>() == Approx(expected_offset[k]).margin(kHalfMicron));
  CHECK(report["previous"]["tip_radius"].get<double>() == Approx(1.9));
  CHECK(report["previous"]["offset"][0].get<double>() == Approx(0.3));

  // Another client heard it, with the values of the report (the event has 4 decimals).
  const double last_digit = 0.00005 + 1e-9;
  const auto event = observer.until_prefix("Qualified ", 10);
  REQUIRE(event);
  CHECK(after(*event, "TipRadius") == Approx(radius).margin(last_digit));
  CHECK(after(*event, "Offset") == Approx(report["offset"][0].get<double>()).margin(last_digit));
  CHECK(after(*event, "Offset", 1) == Approx(report["offset"][1].get<double>()).margin(last_digit));
  CHECK(after(*event, "Offset", 2) == Approx(report["offset"][2].get<double>()).margin(last_digit));
  CHECK(after(*event, "Form") == Approx(report["form"].get<double>()).margin(last_digit));
  // Get reads them (TipRadius with 3 decimals, the offset with 4).
  CHECK(got(observer, "TipRadius") == Approx(radius).margin(0.0005 + 1e-9));
  CHECK(got(observer, "ProbeOffX") == Approx(report["offset"][0].get<double>()).margin(last_digit));
  CHECK(got(observer, "ProbeOffY") == Approx(report["offset"][1].get<double>()).margin(last_digit));
  CHECK(got(observer, "ProbeOffZ") == Approx(report["offset"][2].get<double>()).margin(last_digit));

  // The messdrc holds them, its other lines kept, and a messd started with it has them.
  const std::string rc = read_file(dir.file("stylus.rc"));
  CHECK(rc.rfind("# stylus: 4 mm ruby ball, 20 mm shaft\nSpeedLevel 1.0   # all speeds\nTipRadius ", 0) == 0);
  CHECK(after(rc, "TipRadius") == Approx(radius).margin(1e-6));
  CHECK(after(rc, "ProbeOffX") == Approx(report["offset"][0].get<double>()).margin(1e-6));
  CHECK(after(rc, "ProbeOffZ") == Approx(report["offset"][2].get<double>()).margin(1e-6));
  DaemonProcess restarted({"--config", config(), "--rc", dir.file("stylus.rc")});
  LineClient again(restarted.port());
  CHECK(got(again, "TipRadius") == Approx(radius).margin(0.0005 + 1e-9));
  CHECK(got(again, "ProbeOffX") == Approx(report["offset"][0].get<double>()).margin(last_digit));
  CHECK(got(again, "ProbeOffY") == Approx(report["offset"][1].get<double>()).margin(last_digit));
}

TEST_CASE("messcap qualify names a sphere that is not where --sphere says and leaves messd as it was") {
  DaemonProcess messd({"--config", config()}, DaemonProcess::Scheduling::RealtimeIfPermitted);
  const auto sphere = imess::sim::reference_sphere();
  char where[64];  // 60 mm above the real one: the ring's touches meet nothing
  std::snprintf(where, sizeof where, "%.3f,%.3f,%.3f", sphere.center.x(), sphere.center.y(), sphere.center.z() + 60);
  const auto run = run_program({client_binary("messcap"), "qualify", "127.0.0.1:" + std::to_string(messd.port()), "--sphere", where,
                                "--diameter", "25", "--feed", "100"},
                               240s);
  INFO("stderr:\n" << run.err);
  CHECK(run.status == 1);
  CHECK(run.err.find("touch 1 of 9 found no surface") != std::string::npos);
  CHECK(run.err.find(std::string("the sphere is not at ") + where) != std::string::npos);
  LineClient c(messd.port());
  CHECK(got(c, "TipRadius") == Approx(1.9));
}
