// The web panel's point tools (imess::webpoints): the page's points as files byte for byte as
// messcap's capture writes them (its PointFile, the real peer, writes the same hits here), fits
// as messcap reports them, and every refusal saying what is accepted.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "imess/webpoints/points_request.hpp"
#include "point_file.hpp"

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// Eight hits around a bore of diameter 40 at (430, 330, 60), touched from inside (approach
// outwards), tip radius 2, as messd's Hit lines print them (4 decimals, approach 6).
json bore_hits() {
  json hits = json::array();
  for (int n = 0; n < 8; ++n) {
    const double a = n * M_PI / 4;
    auto round_to = [](double v, double q) { return std::round(v * q) / q; };
    hits.push_back({{"seq", 101 + n},
                    {"x", round_to(430 + 20 * std::cos(a), 1e4)},
                    {"y", round_to(330 + 20 * std::sin(a), 1e4)},
                    {"z", 60.0},
                    {"i", round_to(std::cos(a), 1e6)},
                    {"j", round_to(std::sin(a), 1e6)},
                    {"k", 0.0},
                    {"r", 2.0}});
  }
  return hits;
}

json ask(const json& request) {
  auto reply = imess::webpoints::answer_points_message(request.dump());
  REQUIRE(reply);
  return json::parse(*reply);
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// What `messcap -o DIR/points.EXT` writes for these hits (its capture's PointFile).
std::string messcap_file(const json& hits, const std::string& ext) {
  const fs::path dir = fs::temp_directory_path() / ("imess-webpoints-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / ("points." + ext);
  fs::remove(path);
  {
    imess::exchange::ExportData base;
    if (ext == "hits") base.decimals = imess::exchange::kHitDecimals;
    imess::messcap::PointFile file(path.string(), imess::messcap::OpenMode::New, base);
    for (const auto& h : hits) {
      imess::metrology::ProbedPoint p;
      p.surface = Eigen::Vector3d(h["x"].get<double>(), h["y"].get<double>(), h["z"].get<double>());
      p.approach = Eigen::Vector3d(h["i"].get<double>(), h["j"].get<double>(), h["k"].get<double>()).normalized();
      p.radius = h["r"].get<double>();
      file.append(p, imess::messcap::PointNumber{h["seq"].get<std::uint64_t>(), {}});
    }
    file.flush();
  }
  std::string text = read(path);
  fs::remove_all(dir);
  return text;
}

// DMIS names the time it was written: the line after DMISMN ends with it.
std::string without_time(std::string dmis) {
  const auto at = dmis.find(" measured points");
  const auto end = dmis.find('\n', at);
  const auto comma = dmis.rfind(", ", end);
  return dmis.erase(comma, end - comma);
}

}  // namespace

TEST_CASE("web points: CSV, XYZ and .hits are what messcap's capture writes for the same hits, byte for byte") {
  const json hits = bore_hits();
  for (const std::string ext : {"csv", "xyz", "hits"}) {
    INFO(ext);
    const json reply = ask({{"export", ext}, {"id", 7}, {"hits", hits}});
    REQUIRE(reply["type"] == "Export");
    CHECK(reply["id"] == 7);
    CHECK(reply["name"] == "points." + ext);
    CHECK(reply["n"] == 8);
    CHECK(reply["text"].get<std::string>() == messcap_file(hits, ext));
  }
  const std::string csv = ask({{"export", "csv"}, {"hits", hits}})["text"];
  CHECK(csv.rfind("hit,x,y,z,scan\n101,450.000,330.000,60.000,\n", 0) == 0);
  const std::string xyz = ask({{"export", "xyz"}, {"hits", hits}})["text"];
  CHECK(xyz.rfind("450.000 330.000 60.000 # hit 101\n", 0) == 0);
}

TEST_CASE("web points: DMIS is messcap's, but for the time it was written") {
  const json hits = bore_hits();
  const std::string dmis = ask({{"export", "dmi"}, {"hits", hits}})["text"];
  CHECK(dmis.rfind("DMISMN/'IMESS messcap points.dmi',05.2\n", 0) == 0);
  CHECK(dmis.find("F(PT8)=FEAT/POINT,CART,") != std::string::npos);
  CHECK(without_time(dmis) == without_time(messcap_file(hits, "dmi")));
}

TEST_CASE("web points: fits as messcap fit reports them, probe-compensated from the hits") {
  const json hits = bore_hits();
  const json circle = ask({{"fit", "circle"}, {"id", 3}, {"hits", hits}});
  REQUIRE(circle["type"] == "Fit");
  CHECK(circle["id"] == 3);
  CHECK(circle["kind"] == "circle");
  CHECK(circle["n"] == 8);
  CHECK(circle["probed"] == true);
  REQUIRE(circle.contains("result"));
  // The surface points lie on a 40 mm circle; the ball centres on 36 mm, offset back by r.
  CHECK(circle["result"]["diameter"].get<double>() == Approx(40.0).margin(1e-3));
  CHECK(circle["result"]["center"][0].get<double>() == Approx(430.0).margin(1e-3));
  CHECK(circle["result"]["center"][1].get<double>() == Approx(330.0).margin(1e-3));
  CHECK(json::parse(circle["text"].get<std::string>()) == circle["result"]);
  // Hits without their approach: the surface points, as messcap fit of an .xyz file.
  json plain = hits;
  for (auto& h : plain) h.erase("i"), h.erase("j"), h.erase("k"), h.erase("r");
  const json surface = ask({{"fit", "circle"}, {"hits", plain}});
  CHECK(surface["probed"] == false);
  CHECK(surface["result"]["diameter"].get<double>() == Approx(40.0).margin(1e-3));
  // Sphere, plane, cylinder: the kinds the panel offers all answer.
  json top = json::array();
  for (int n = 0; n < 4; ++n)
    top.push_back({{"seq", n + 1}, {"x", 400.0 + 20 * (n % 2)}, {"y", 300.0 + 20 * (n / 2)}, {"z", 80.0},
                   {"i", 0.0}, {"j", 0.0}, {"k", -1.0}, {"r", 2.0}});
  const json plane = ask({{"fit", "plane"}, {"hits", top}});
  REQUIRE(plane.contains("result"));
  CHECK(plane["result"]["point"][2].get<double>() == Approx(80.0).margin(1e-9));
  CHECK(std::abs(plane["result"]["normal"][2].get<double>()) == Approx(1.0));
}

TEST_CASE("web points: a failed fit and every refusal say what was wrong and what is accepted") {
  const json hits = bore_hits();
  const json few = ask({{"fit", "sphere"}, {"hits", json::array({hits[0], hits[1]})}});
  REQUIRE(few.contains("error"));
  CHECK(few["error"].get<std::string>().rfind("fit sphere to the 2 points failed (", 0) == 0);
  CHECK(ask({{"fit", "torus"}, {"hits", hits}})["error"].get<std::string>().find("line, line2d, plane") != std::string::npos);
  CHECK(ask({{"export", "stl"}, {"hits", hits}})["error"].get<std::string>().find("accepted: csv, xyz, dmi, hits") != std::string::npos);
  const auto refused = [&](const json& request, const std::string& words) {
    const json r = ask(request);
    INFO(request.dump() << " -> " << r.dump());
    REQUIRE(r.contains("error"));
    CHECK(r["error"].get<std::string>().find(words) != std::string::npos);
    CHECK(r["error"].get<std::string>().find("accepted:") != std::string::npos);
  };
  refused({{"export", "csv"}}, "\"hits\" is missing");
  refused({{"export", "csv"}, {"fit", "plane"}, {"hits", hits}}, "either");
  refused({{"export", "csv"}, {"hits", hits}, {"extra", 1}}, "unknown key \"extra\"");
  refused({{"export", "csv"}, {"hits", json::array({{{"x", 1}, {"y", 2}, {"z", 3}}})}}, "no \"seq\"");
  refused({{"export", "csv"}, {"hits", json::array({{{"seq", 1}, {"x", 1}, {"y", 2}}})}}, "no \"z\"");
  refused({{"export", "csv"}, {"hits", json::array({{{"seq", 1}, {"x", "1"}, {"y", 2}, {"z", 3}}})}}, "not a finite number");
  refused({{"export", "csv"}, {"hits", json::array({{{"seq", 1}, {"x", 1}, {"y", 2}, {"z", 3}, {"i", 0.5}, {"j", 0}, {"k", 0}}})}},
          "not a unit vector");
  refused({{"export", "csv"}, {"hits", json::array({{{"seq", 1}, {"x", 1}, {"y", 2}, {"z", 3}, {"t", 1}}})}}, "unknown key \"t\"");
  refused({{"export", 3}, {"hits", hits}}, "not a string");
  // A .hits file needs each hit's approach.
  json plain = hits;
  for (auto& h : plain) h.erase("i"), h.erase("j"), h.erase("k");
  CHECK(ask({{"export", "hits"}, {"hits", plain}})["error"].get<std::string>().find("approach") != std::string::npos);
  // Not a points request: a MESSD command, or no JSON, is webjson's.
  CHECK_FALSE(imess::webpoints::answer_points_message(R"({"cmd":"StartMv","args":[0,0,-20]})"));
  CHECK_FALSE(imess::webpoints::answer_points_message(R"({"line":"Status"})"));
  CHECK_FALSE(imess::webpoints::answer_points_message(R"({"export": broken)"));
}
