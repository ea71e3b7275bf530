// bench_net push --quick with a handful of samples against the build's messd: it exits 0 and
// its JSON holds the contract's keys, every push figure id, and values that are numbers >= 0.
// No timing is asserted.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "child_process.hpp"
#include "figure_ids.hpp"

using namespace imess::test;

TEST_CASE("bench_net push --quick writes the contract's JSON with every push figure") {
  TempDir dir;
  const std::string json_path = dir.file("push.json");
  auto run = run_program({client_binary("bench_net"), "push", "--quick", "--samples", "3", "--json", json_path}, 60s);
  INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
  REQUIRE(run.status == 0);

  std::ifstream file(json_path);
  REQUIRE(file);
  const auto j = nlohmann::json::parse(file);
  CHECK(j.at("bench") == "net");
  CHECK(j.at("quick") == true);

  std::set<std::string> ids;
  for (const auto& f : j.at("figures")) {
    const std::string id = f.at("id");
    ids.insert(id);
    INFO(id);
    REQUIRE(f.at("value").is_number());
    CHECK(f.at("value").get<double>() >= 0);
    CHECK(f.at("unit") == "ms");
    CHECK(f.at("virtual_time") == false);
    CHECK(f.at("what").is_string());
    if (!f.at("reference").is_null()) {
      CHECK(f.at("reference").get<double>() >= 0);
      CHECK(f.at("ratio").is_number());
      CHECK(f.at("reference_id").is_string());
    }
    if (!f.at("goal").is_null()) CHECK(f.at("met").is_boolean());
    // Every figure is printed on a line of its own, starting with its id.
    CHECK(run.out.find(id + " ") != std::string::npos);
  }
  for (const auto& id : bench_ids::net_push(true)) {
    INFO(id);
    CHECK(ids.count(id) == 1);
  }

  std::set<std::string> distributions;
  for (const auto& d : j.at("distributions")) {
    distributions.insert(d.at("id").get<std::string>());
    CHECK(d.at("samples").size() >= 1);
    for (const auto& s : d.at("samples")) CHECK(s.get<double>() >= 0);
  }
  CHECK(distributions.count("push.forcept.100") == 1);
  CHECK(distributions.count("push.probe.100") == 1);

  REQUIRE(j.at("curves").size() == 1);
  const auto& curve = j.at("curves")[0];
  CHECK(curve.at("id") == "push.clients");
  for (const char* series : {"messd", "floor"}) {
    REQUIRE(curve.at("series").at(series).size() == 3);  // quick: 1, 10, 100 clients
    for (const auto& point : curve.at("series").at(series)) CHECK(point.at(1).get<double>() >= 0);
  }
}

TEST_CASE("bench_net refuses a bad command line with what it accepts") {
  auto run = run_program({client_binary("bench_net"), "push", "--samples", "0"}, 10s);
  CHECK(run.status == 2);
  CHECK(run.err.find("--samples takes a whole number from 1 to 1000000, got '0'") != std::string::npos);
  run = run_program({client_binary("bench_net"), "fly"}, 10s);
  CHECK(run.status == 2);
  CHECK(run.err.find("accepted: push stream jog rtt memory load scan all") != std::string::npos);
  run = run_program({client_binary("bench_net"), "rtt", "--soak-seconds", "5"}, 10s);
  CHECK(run.status == 2);
  CHECK(run.err.find("'rtt' does not take '--soak-seconds'") != std::string::npos);
}
