// bench_rt loop --quick runs and writes the benchmarks' JSON with the expected figure ids.
// It starts messd and (when installed) cyclictest for a second each; no value is checked.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "figure_ids.hpp"

TEST_CASE("bench_rt loop --quick --seconds 1 writes well-formed JSON with the loop's figure ids") {
  const std::string dir = "/tmp/imess-bench-rt-smoke-" + std::to_string(getpid());
  const std::string json = dir + ".json", log = dir + ".log";
  const std::string cmd = std::string(IMESS_BIN_DIR) + "/bench_rt loop --quick --seconds 1 --json " + json + " > " + log + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(json);
  std::string printed((std::istreambuf_iterator<char>(std::ifstream(log).rdbuf())), std::istreambuf_iterator<char>());
  INFO(printed);
  REQUIRE(status == 0);
  REQUIRE(in);
  const auto j = nlohmann::json::parse(in);
  CHECK(j.at("bench") == "rt");
  CHECK(j.at("quick") == true);
  REQUIRE(j.at("figures").is_array());
  CHECK(j.at("curves").is_array());
  std::set<std::string> ids;
  for (const auto& f : j.at("figures")) {
    INFO(f.dump());
    ids.insert(f.at("id").get<std::string>());
    CHECK(f.at("what").is_string());
    CHECK(f.at("unit").is_string());
    CHECK((f.at("value").is_number() || (f.at("value").is_null() && f.at("unavailable").is_string())));
    CHECK((f.at("reference").is_number() || f.at("reference").is_null()));
    CHECK((f.at("ratio").is_number() || f.at("ratio").is_null()));
    CHECK(f.at("virtual_time") == false);
    if (f.contains("goal")) CHECK((f.at("met").is_boolean() || f.at("met").is_null()));
  }
  for (const auto& id : imess::test::bench_ids::rt_loop()) {
    INFO(id);
    CHECK(ids.count(id) == 1);
  }
  std::set<std::string> distributions;
  for (const auto& d : j.at("distributions")) {
    distributions.insert(d.at("id").get<std::string>());
    CHECK(d.at("samples").is_array());
  }
  CHECK(distributions.count("rt.loop.idle") == 1);  // messd's loop ran; the floor's only with cyclictest
  // messd's distribution names cyclictest's as the one to draw beside it, when there is one.
  for (const auto& d : j.at("distributions")) {
    const std::string id = d.at("id");
    const std::string floor = "floor" + id.substr(id.find('.'));
    INFO(id);
    if (id.rfind("rt.", 0) == 0 && distributions.count(floor)) CHECK(d.value("reference_id", "") == floor);
    if (id.rfind("floor.", 0) == 0) CHECK_FALSE(d.contains("reference_id"));
  }
  std::remove(json.c_str());
  std::remove(log.c_str());
}
