// The worked-example cube inspected live by its shipped plan (examples/cube-1996.plan.json):
// messcap inspect takes control of messd on the simulated machine, probes every feature, and
// every characteristic must come out as the simulated part is made — the 120/100/80 sizes, the
// 30 mm bore at the centre, the 10 mm fillet, perfect form and orientation; the 0.3 degree turn
// shows in the part frame, not as a deviation; tip-radius compensation puts every point on its
// nominal surface. The JSON report, read back with --points, gives the same figures. The QIF
// document of the same run (--qif) is valid by the QIF 3.0 schemas and holds the report's figures
// (tests/clients/qif/qif_check.py).
#include <catch2/catch.hpp>

#include <fstream>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "daemon_process.hpp"
#include "imess/sim/scene.hpp"

using namespace imess::test;
using nlohmann::json;

namespace {

const json& characteristic(const json& report, const std::string& name) {
  for (const auto& c : report["characteristics"])
    if (c["name"] == name) return c;
  FAIL("no characteristic '" << name << "' in the report");
  throw;
}

}  // namespace

TEST_CASE("messcap inspect: the worked-example cube measured live matches the simulated part", "[long]") {
  // As test_cube_example.cpp: brisk speeds, the simulated machine in loop time (a stalled
  // loop on a loaded test machine pauses the simulation instead of faulting the card link).
  DaemonProcess messd({"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/fast-cmm.json"},
                      DaemonProcess::Scheduling::RealtimeIfPermitted);
  TempDir dir;
  LineClient observer(messd.port());  // another client: it sees the run's result announced
  const std::string plan = std::string(IMESS_SOURCE_DIR) + "/examples/cube-1996.plan.json";
  const auto run = run_program({client_binary("messcap"), "inspect", plan, "127.0.0.1:" + std::to_string(messd.port()),
                                "--feed", "300", "--json", dir.file("cube.json"), "--html", dir.file("cube.html"),
                                "--qif", dir.file("cube.qif"), "--operator", "tester"},
                               240s);
  INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
  REQUIRE(run.status == 0);
  CHECK(run.out.find("13 characteristics: 13 in tolerance, 0 out of tolerance") != std::string::npos);
  CHECK(observer.until_prefix("Inspected ", 5.0) == std::optional<std::string>("Inspected cube-1996 13 0 pass"));
  {  // messd keeps the part frame messcap built, active, for every client
    LineClient monitor(messd.port());
    CHECK(monitor.request("Frames") == std::optional<std::string>("Ok Frames Active cube-1996 Names machine cube-1996"));
    const auto frame = monitor.request("Frame");
    REQUIRE(frame);
    CHECK(frame->rfind("Ok Frame cube-1996 Origin 400.26", 0) == 0);
  }
  const json report = json::parse(read_file(dir.file("cube.json")));

  const auto scene = imess::sim::worked_example_scene();
  const auto& cube = std::get<imess::sim::BoxSolid>(scene.solids().at(1));
  const double um = 0.001;
  for (const auto& c : report["characteristics"]) {
    INFO(c.dump());
    CHECK(c["in_tolerance"] == true);
  }
  CHECK(characteristic(report, "length")["actual"].get<double>() == Approx(cube.size.x()).margin(um));
  CHECK(characteristic(report, "width")["actual"].get<double>() == Approx(cube.size.y()).margin(um));
  CHECK(characteristic(report, "height")["actual"].get<double>() == Approx(cube.size.z()).margin(um));
  CHECK(characteristic(report, "bore diameter")["actual"].get<double>() == Approx(cube.bores.at(0).diameter).margin(um));
  CHECK(characteristic(report, "fillet radius")["actual"].get<double>() == Approx(cube.fillet_radius).margin(um));
  // The bore at the block's centre, in part coordinates (the front-left-bottom corner).
  const json& bore = characteristic(report, "bore position");
  CHECK(bore["actual"].get<double>() < 2 * um);
  CHECK(bore["actual_location"][0].get<double>() == Approx(cube.size.x() / 2 + cube.bores[0].x).margin(um));
  CHECK(bore["actual_location"][1].get<double>() == Approx(cube.size.y() / 2 + cube.bores[0].y).margin(um));
  for (const char* zone : {"bore roundness", "bore axis perpendicularity", "right perpendicularity", "top parallelism",
                           "bottom flatness", "top flatness"})
    CHECK(characteristic(report, zone)["actual"].get<double>() < um);
  CHECK(characteristic(report, "front-left angle")["actual"].get<double>() == Approx(90).margin(0.001));

  // The turn is taken up by the alignment: the part frame is the block's own.
  const json& al = report["alignment"];
  CHECK(al["from"] == "alignment");
  CHECK(al["rotation_deg"][2].get<double>() == Approx(cube.yaw_deg).margin(0.001));
  CHECK(std::abs(al["rotation_deg"][0].get<double>()) < 0.001);
  CHECK(std::abs(al["rotation_deg"][1].get<double>()) < 0.001);
  const Eigen::Vector3d corner =
      cube.center + Eigen::AngleAxisd(cube.yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()) * (-0.5 * cube.size);
  for (int k = 0; k < 3; ++k) CHECK(al["origin"][k].get<double>() == Approx(corner[k]).margin(um));

  // Every point compensated for the 2 mm tip onto its nominal surface.
  REQUIRE(report["points"].size() == 45);
  for (const auto& p : report["points"]) {
    INFO(p.dump());
    CHECK(std::abs(p["deviation"].get<double>()) < um);
    CHECK(p["radius"].get<double>() == 2.0);
  }
  for (const auto& f : report["features"]) CHECK(f["compensated"] == true);

  // The HTML report stands alone: pictures inline, nothing fetched.
  const std::string html = read_file(dir.file("cube.html"));
  CHECK(html.find("<svg") != std::string::npos);
  CHECK(html.find("src=") == std::string::npos);
  CHECK(html.find("href=") == std::string::npos);
  CHECK(html.find("13 in tolerance") != std::string::npos);

  // The run as QIF 3.0: valid, every characteristic's value, deviation and status, every fitted
  // feature and point the JSON report's; the machine and the operator recorded.
  CHECK(report["machine"] == "messd at 127.0.0.1:" + std::to_string(messd.port()));
  CHECK(report["operator"] == "tester");
  const auto qif = run_program({"/usr/bin/python3", std::string(IMESS_SOURCE_DIR) + "/tests/clients/qif/qif_check.py",
                                IMESS_SOURCE_DIR, dir.file("cube.qif"), dir.file("cube.json")},
                               30s);
  INFO("qif_check:\n" << qif.out << qif.err);
  CHECK(qif.status == 0);
  const std::string qif_text = read_file(dir.file("cube.qif"));
  CHECK(qif_text.find("<Name>messd at 127.0.0.1:" + std::to_string(messd.port()) + "</Name>") != std::string::npos);
  CHECK(qif_text.find("<ProbeRadius>2</ProbeRadius>") != std::string::npos);

  // The same points, read back from the report, give the same figures.
  const auto again = run_program({client_binary("messcap"), "inspect", plan, "--points", dir.file("cube.json"), "--json",
                                  dir.file("again.json")},
                                 30s);
  REQUIRE(again.status == 0);
  const json second = json::parse(read_file(dir.file("again.json")));
  for (std::size_t i = 0; i < report["characteristics"].size(); ++i)
    CHECK(second["characteristics"][i]["actual"].get<double>() ==
          Approx(report["characteristics"][i]["actual"].get<double>()).margin(1e-5));
}

TEST_CASE("messcap inspect without a machine: bad arguments, a bad plan, out of tolerance") {
  TempDir dir;
  const std::string messcap = client_binary("messcap");
  const std::string plan = std::string(IMESS_SOURCE_DIR) + "/examples/cube-1996.plan.json";
  auto usage = run_program({messcap, "inspect"});
  CHECK(usage.status == 2);
  CHECK(usage.err.find("inspect needs a PLAN file") != std::string::npos);
  usage = run_program({messcap, "inspect", plan, "--points", "x.txt", "localhost"});
  CHECK(usage.status == 2);
  CHECK(usage.err.find("either --points FILE or HOST[:PORT]") != std::string::npos);

  {
    std::ofstream bad(dir.file("bad.json"));
    bad << R"({"part": "p", "features": [{"name": "a", "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}],
              "characteristics": [{"name": "s", "type": "roundness", "feature": "a", "tolerance": 0.1}]})";
  }
  const auto bad = run_program({messcap, "inspect", dir.file("bad.json"), "--points", dir.file("none.txt")});
  CHECK(bad.status == 1);
  CHECK(bad.err.find("bad.json: characteristics[0].feature: roundness applies to a circle, and 'a' is a plane") !=
        std::string::npos);

  // The nominal cube with its right face 0.1 mm too far out, as plain surface points in machine
  // coordinates (the plan's placement: part + (400, 300, 0)): the length is out of tolerance.
  {
    std::ofstream pts(dir.file("cube.txt"));
    const auto parsed = nlohmann::json::parse(read_file(plan));
    for (const auto& f : parsed["features"])
      for (const auto& p : f["probe"]) {
        const double shift = f["name"] == "right" ? 0.1 : 0.0;
        pts << f["name"].get<std::string>() << " " << p[0].get<double>() + 400 + shift << " " << p[1].get<double>() + 300 << " "
            << p[2].get<double>() << "\n";
      }
  }
  const auto out = run_program({messcap, "inspect", plan, "--points", dir.file("cube.txt"), "--json", "-"});
  INFO(out.err);
  CHECK(out.status == 5);
  const json report = json::parse(out.out);
  CHECK(characteristic(report, "length")["deviation"].get<double>() == Approx(0.1).margin(1e-9));
  CHECK(characteristic(report, "length")["in_tolerance"] == false);
  CHECK(report["summary"]["out_of_tolerance"] == 1);
  CHECK(out.err.find("OUT") != std::string::npos);  // the table, on stderr beside --json -
}
