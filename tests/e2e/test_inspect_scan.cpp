// messcap inspect measures by scanning: examples/cube-bore-scan.plan.json run live against the
// real messd on a simulated CMM with a measuring probe (tests/e2e/scan-cmm.json: the scene of
// the worked example, no probe noise) — the bore's diameter 30 and its form near 0 from the
// Scan points, fitted probe-compensated; on a touch-trigger machine the plan's first scan
// fails with messd's NoMeasuringProbe, said clearly.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "daemon_process.hpp"

using namespace imess::test;

namespace {

const std::string kPlan = std::string(IMESS_SOURCE_DIR) + "/examples/cube-bore-scan.plan.json";

const nlohmann::json& named(const nlohmann::json& list, const std::string& name) {
  for (const auto& e : list)
    if (e["name"] == name) return e;
  FAIL("no entry named '" << name << "'");
  return list;
}

}  // namespace

TEST_CASE("messcap inspect scans the worked example's bore and top (cube-bore-scan.plan.json): Ø 30, form near 0") {
  DaemonProcess messd({"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/scan-cmm.json"});
  TempDir dir;
  const auto run = run_program({client_binary("messcap"), "inspect", kPlan, "127.0.0.1:" + std::to_string(messd.port()),
                                "--json", dir.file("report.json")},
                               30s);
  INFO(run.out << run.err);
  REQUIRE(run.status == 0);
  CHECK_THAT(run.err, Catch::Contains("messcap: bore: ") && Catch::Contains(" points (1 scan)"));
  CHECK_THAT(run.err, Catch::Contains(" points (2 scans)"));
  const auto report = nlohmann::json::parse(read_file(dir.file("report.json")));

  // The bore: a full turn, a point every 0.1 mm (its 94 mm of surface; the ball's path is shorter).
  const auto& bore = named(report["features"], "bore");
  CHECK(bore["points"].get<int>() > 800);
  CHECK(bore["compensated"] == true);
  const double tolerance = 0.001;  // the simulated probe has no noise: the points lie within 0.2 um
  CHECK(named(report["characteristics"], "bore diameter")["actual"].get<double>() == Approx(30.0).margin(tolerance));
  CHECK(named(report["characteristics"], "bore roundness")["actual"].get<double>() < tolerance);
  CHECK(named(report["characteristics"], "bore position")["actual"].get<double>() < tolerance);
  CHECK(named(report["characteristics"], "bore cylinder diameter")["actual"].get<double>() == Approx(30.0).margin(tolerance));
  CHECK(named(report["characteristics"], "bore cylindricity")["actual"].get<double>() < tolerance);
  CHECK(named(report["characteristics"], "bore square to the top")["actual"].get<double>() < tolerance);
  CHECK(named(report["characteristics"], "top flatness")["actual"].get<double>() < tolerance);
  // Every point is a scan's: the measured direction toward the surface and the tip radius kept.
  for (const auto& p : report["points"]) {
    REQUIRE(p.contains("approach"));
    REQUIRE(p["radius"].get<double>() == 2.0);
  }
  // The plan's steps were the plan's: messd's own ScanStep is as it was.
  LineClient c(messd.port());
  CHECK(c.request("Get ScanStep") == "Ok Get ScanStep 0.100");
}

TEST_CASE("messcap inspect: a plan that scans fails clearly on a touch-trigger machine (NoMeasuringProbe)") {
  DaemonProcess messd({"--config", fast_cmm()});
  const auto run = run_program({client_binary("messcap"), "inspect", kPlan, "127.0.0.1:" + std::to_string(messd.port())}, 20s);
  CHECK(run.status == 1);
  CHECK_THAT(run.err, Catch::Contains("messcap: inspect: feature 'bore': 'ScanCirc ") &&
                          Catch::Contains("ended with 'Failed ") && Catch::Contains(" NoMeasuringProbe ") &&
                          Catch::Contains("a scan needs a measuring (analog) probe"));
  CHECK(run.out.empty());  // no report of points never measured
}
