// scripts/bench --quick with the suite's own build (IMESS_BENCH_BIN, no Release build) into a
// temporary results directory: it exits 0, its results file holds one run of net and rt with
// every figure id of both, each figure's line is printed by the report, and the plots it lists
// exist (PNG only in quick mode). report.py without matplotlib still writes the results and
// says why there are no plots. No timing is asserted.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "child_process.hpp"
#include "figure_ids.hpp"

using namespace imess::test;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> files_ending(const std::string& dir, const std::string& ending) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name.size() >= ending.size() && name.compare(name.size() - ending.size(), ending.size(), ending) == 0)
      found.push_back(e.path());
  }
  return found;
}

std::set<std::string> figure_ids(const nlohmann::json& bench) {
  std::set<std::string> ids;
  for (const auto& f : bench.at("figures")) ids.insert(f.at("id").get<std::string>());
  return ids;
}

}  // namespace

TEST_CASE("scripts/bench --quick with the built programs writes one run of net and rt with every figure") {
  TempDir dir;
  const std::string out = dir.file("results");
  // A Debug build and a busy suite are slower than the minute a Release build takes alone:
  // the deadline only stops a hang.
  auto run = run_program({"/usr/bin/env", "IMESS_BENCH_BIN=" + std::string(IMESS_BIN_DIR), "IMESS_BENCH_OUT=" + out,
                          std::string(IMESS_SOURCE_DIR) + "/scripts/bench", "--quick"},
                         280s);
  INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
  REQUIRE(run.status == 0);

  const auto results = files_ending(out, ".json");
  REQUIRE(results.size() == 1);
  std::ifstream file(results[0]);
  const auto j = nlohmann::json::parse(file);
  CHECK(j.at("machine").at("quick") == true);
  REQUIRE(j.at("runs").size() == 1);  // quick: one run
  const auto& benches = j.at("runs")[0].at("benches");
  REQUIRE(benches.contains("net"));
  REQUIRE(benches.contains("rt"));
  CHECK(benches.size() == 2);  // quick: net and rt only

  const std::string report = run.out.substr(run.out.find("== figures"));
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected{{"net", bench_ids::net_all(true)},
                                                                                {"rt", bench_ids::rt_all()}};
  for (const auto& [name, want] : expected) {
    const auto& bench = benches.at(name);
    CHECK(bench.at("quick") == true);
    const auto ids = figure_ids(bench);
    for (const auto& id : want) {
      INFO(name << ": " << id);
      CHECK(ids.count(id) == 1);
    }
    // Every figure (also one a command adds when it could not finish) is printed by the report
    // on a line of its own that starts with its id.
    for (const auto& id : ids) {
      INFO(name << ": " << id);
      CHECK(report.find("\n" + id + " ") != std::string::npos);
      CHECK(id.find(".failed") == std::string::npos);
    }
  }

  // The plots: the ones listed exist, PNG only; a plot of its own for every distribution that
  // is not drawn beside another as its reference (the floors); or none, and the reason.
  const auto& plots = j.at("plots");
  if (j.contains("plots_unavailable")) {
    CHECK(plots.empty());
    CHECK(run.err.find("report.py: no plots: ") != std::string::npos);
  } else {
    CHECK(!plots.empty());
    std::set<std::string> names;
    for (const auto& p : plots) {
      const fs::path path = p.get<std::string>();
      INFO(path);
      CHECK(fs::exists(path));
      CHECK(path.extension() == ".png");
      names.insert(path.filename().string());
    }
    for (const auto& [name, want] : expected) {
      std::set<std::string> beside;
      for (const auto& d : benches.at(name).at("distributions"))
        if (d.contains("reference_id")) beside.insert(d.at("reference_id").get<std::string>());
      for (const auto& d : benches.at(name).at("distributions")) {
        const std::string id = d.at("id");
        INFO(id);
        if (!d.at("samples").empty()) CHECK(names.count(id + ".run1.png") == (beside.count(id) ? 0 : 1));
      }
    }
  }
}

TEST_CASE("report.py without matplotlib writes the figures and the results and says why there are no plots") {
  TempDir dir;
  fs::create_directories(dir.file("run1"));
  std::ofstream(dir.file("run1/bench_net.json"))
      << R"({"bench": "net", "quick": true, "figures": [{"id": "rtt.status.p50", "what": "Status round trip", "value": 0.1,)"
      << R"( "unit": "ms"}], "distributions": [{"id": "rtt.status", "what": "Status", "unit": "ms", "samples": [0.1, 0.2]}], "curves": []})";
  // matplotlib made unimportable, as on a machine without python3-matplotlib.
  const std::string report_py = std::string(IMESS_SOURCE_DIR) + "/bench/report.py";
  const std::string script = "import sys, runpy; sys.modules['matplotlib'] = None; sys.argv[0] = '" + report_py +
                             "'; runpy.run_path(sys.argv[0], run_name='__main__')";
  auto run = run_program({"/usr/bin/python3", "-c", script, "--quick", "--out", dir.file("results.json"), "--plots", dir.file("plots"),
                          dir.file("run1")},
                         60s);
  INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
  CHECK(run.status == 0);
  CHECK(("\n" + run.out).find("\nrtt.status.p50 ") != std::string::npos);
  CHECK(run.err.find("report.py: no plots: python3-matplotlib is not installed") != std::string::npos);
  std::ifstream file(dir.file("results.json"));
  REQUIRE(file);
  const auto j = nlohmann::json::parse(file);
  CHECK(j.at("plots").empty());
  CHECK(j.at("plots_unavailable").get<std::string>().find("python3-matplotlib") != std::string::npos);
  CHECK(j.at("runs")[0].at("benches").at("net").at("figures").size() == 1);
}
