// The configuration's runtime-parameter keys: each registry entry with a key is read into the
// value Get/Set use, with the registry's range (the numbers are written once).
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>

#include "config.hpp"
#include "imess/net/params.hpp"
#include "param_config.hpp"

using namespace imess;
using namespace imess::app;

TEST_CASE("every configurable parameter is read from its key into the place Get reads") {
  for (const auto& p : net::param_table()) {
    if (p.config.empty()) continue;
    INFO(p.config);
    const auto dot = p.config.find('.');
    REQUIRE(dot != std::string_view::npos);
    const std::string section(p.config.substr(0, dot)), key(p.config.substr(dot + 1));
    char value[32];
    std::snprintf(value, sizeof value, "%.17g", p.max >= net::kUnbounded ? p.min + 1 : p.max);
    DaemonConfig cfg;
    load_config_text("{\"" + section + "\":{\"" + key + "\":" + value + "}}", "t.json", cfg);
    double* place = config_place(p, cfg);
    REQUIRE(place != nullptr);
    CHECK(*place == std::stod(value));
    DaemonConfig fresh;
    CHECK(*config_place(p, fresh) == p.initial);  // the registry's default is the code's
  }
}

TEST_CASE("a configured parameter outside the registry's range names the key and that range") {
  for (const auto& p : net::param_table()) {
    if (p.config.empty() || p.min <= -1e9) continue;
    INFO(p.config);
    const auto dot = p.config.find('.');
    const std::string section(p.config.substr(0, dot)), key(p.config.substr(dot + 1));
    DaemonConfig cfg;
    std::string error;
    try {
      load_config_text("{\"" + section + "\":{\"" + key + "\":" + std::to_string(p.min - 1) + "}}", "t.json", cfg);
    } catch (const ConfigError& e) {
      error = e.what();
    }
    char from[32];
    std::snprintf(from, sizeof from, "%g", p.min);
    CHECK(error.find("key '" + std::string(p.config) + "' must be a number from " + from) != std::string::npos);
  }
}

TEST_CASE("messdrc's SpeedLevel and TipRadius take the registry's ranges") {
  DaemonConfig cfg;
  CHECK_THROWS_WITH(load_messdrc_text("SpeedLevel 3\n", "rc", cfg), "rc:1: SpeedLevel takes one number from 0.01 to 2, got '3'");
  CHECK_THROWS_WITH(load_messdrc_text("TipRadius 51\n", "rc", cfg), "rc:1: TipRadius takes one number from 0 to 50, got '51'");
}
