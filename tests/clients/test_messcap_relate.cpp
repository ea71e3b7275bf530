// messcap relate as a program: fitted by messcap fit, related by messcap relate, the printed
// JSON checked against the geometry the points were made from; bad inputs exit 1 or 2 with why.
#include <catch2/catch.hpp>

#include <fstream>

#include <nlohmann/json.hpp>

#include "child_process.hpp"

using imess::test::client_binary;
using imess::test::read_file;
using imess::test::run_program;
using imess::test::TempDir;

namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// messcap fit KIND FILE > OUT
std::string fit_into(const TempDir& dir, const std::string& kind, const std::string& points, const std::string& name) {
  write(dir.file(name + ".xyz"), points);
  auto r = run_program({client_binary("messcap"), "fit", kind, dir.file(name + ".xyz")});
  REQUIRE(r.status == 0);
  write(dir.file(name + ".json"), r.out);
  return dir.file(name + ".json");
}

}  // namespace

TEST_CASE("messcap relate: a bore's centre above a face, and two faces of a step") {
  TempDir dir;
  // Face z = 0, a bore D20 centred (50, 40) at z = 12, the step's upper face z = 25.
  auto face = fit_into(dir, "plane", "0 0 0\n100 0 0\n0 80 0\n100 80 0\n", "face");
  auto bore = fit_into(dir, "circle", "60 40 12\n50 50 12\n40 40 12\n50 30 12\n", "bore");
  auto step = fit_into(dir, "plane", "10 10 25\n30 10 25\n10 30 25\n", "step");

  auto r = run_program({client_binary("messcap"), "relate", face, bore});
  REQUIRE(r.status == 0);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j["a"] == "plane");
  CHECK(j["b"] == "circle");
  CHECK(j["distance"].get<double>() == Approx(12.0).margin(1e-9));
  CHECK(j["distance_rule"] == "plane-point");
  CHECK(j["to"][0].get<double>() == Approx(50.0).margin(1e-9));
  CHECK(j["angle_deg"].get<double>() == Approx(90.0).margin(1e-6));

  // Both on stdin, one per line, as two `messcap fit` runs print them.
  write(dir.file("two.json"), read_file(face) + "\n" + read_file(step));
  r = run_program({"/bin/sh", "-c", client_binary("messcap") + " relate - < " + dir.file("two.json")});
  REQUIRE(r.status == 0);
  j = nlohmann::json::parse(r.out);
  CHECK(j["distance"].get<double>() == Approx(25.0).margin(1e-9));
  CHECK(j["distance_rule"] == "plane-plane parallel");
  CHECK(j["angle_deg"].get<double>() == Approx(0.0).margin(1e-6));
}

TEST_CASE("messcap relate: unusable inputs and arguments say what was wrong") {
  TempDir dir;
  write(dir.file("half.json"), R"({"type":"plane","point":[0,0,0]})");
  write(dir.file("ok.json"), R"({"type":"sphere","center":[0,0,0],"diameter":4})");
  auto r = run_program({client_binary("messcap"), "relate", dir.file("ok.json"), dir.file("half.json")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains(dir.file("half.json") + ": a fitted plane needs 'normal'"));
  r = run_program({client_binary("messcap"), "relate", dir.file("ok.json"), dir.file("missing.json")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("cannot read '" + dir.file("missing.json") + "'"));
  r = run_program({"/bin/sh", "-c", client_binary("messcap") + " relate < " + dir.file("ok.json")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("expected two fit objects, one per line"));
  r = run_program({client_binary("messcap"), "relate", dir.file("ok.json")});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("relate needs two fit files A B"));
  r = run_program({client_binary("messcap"), "relate", "--far"});
  CHECK(r.status == 2);
  r = run_program({client_binary("messcap"), "relate", "--help"});
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::StartsWith("usage: messcap relate A B"));
}
