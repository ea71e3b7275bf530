// The parameter registry: one entry per parameter, defaults as the code starts with them,
// and docs/protocol.md's parameter table agreeing with it row by row.
#include <catch2/catch.hpp>

#include <cstdio>
#include <set>

#include "doc_table.hpp"
#include "imess/net/params.hpp"
#include "imess/net/server.hpp"

using namespace imess;
using net::ParamHome;

namespace {
std::string g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

TEST_CASE("every core parameter has exactly one registry entry, with the core's default") {
  const core::CoreParams defaults;
  std::set<int> ids;
  for (const auto& p : net::param_table()) {
    INFO(p.name);
    if (p.home != ParamHome::Core) continue;
    CHECK(ids.insert(static_cast<int>(p.core_id)).second);
    CHECK(core::param_value(defaults, p.core_id) == p.initial);
    CHECK_FALSE(p.read_only);
  }
  CHECK(ids.size() == static_cast<std::size_t>(core::ParamId::ScanSpeed) + 1);  // ScanSpeed: the last ParamId
}

TEST_CASE("net-side parameters are ordinary entries: ReportHz settable, Period, Axes, Backend read-only") {
  const net::ServerConfig server;
  auto find = [](std::string_view n) {
    auto* p = net::find_param(n);
    REQUIRE(p != nullptr);
    return *p;
  };
  CHECK(find("reporthz").initial == server.report_hz);
  CHECK_FALSE(find("ReportHz").read_only);
  CHECK(find("Period").initial == server.period_us);
  for (auto n : {"Period", "Axes", "Backend"}) CHECK(find(n).read_only);
  CHECK(find("Axes").initial == 3);  // the X Y Z machine when axes.letters is absent
  CHECK(find("Axes").max == core::kMaxAxes);
  CHECK(find("Backend").text);
  CHECK(net::find_param("Nonsense") == nullptr);
}

TEST_CASE("a Set value outside the registry's range names the range") {
  std::string error;
  const auto& tip = *net::find_param("TipRadius");
  CHECK(net::parse_param_value(tip, "2.5", error) == 2.5);
  CHECK_FALSE(net::parse_param_value(tip, "51", error));
  CHECK(error == "TipRadius takes a number from 0 to 50 mm, got '51'");
  CHECK_FALSE(net::parse_param_value(*net::find_param("IdleOpen"), "0", error));
  CHECK(error == "IdleOpen takes a number from 0.1 to any s, got '0'");
}

TEST_CASE("docs/protocol.md's parameter table and the registry agree: names, units, ranges, defaults") {
  auto documented = imess::testing::doc_table(imess::testing::read_source_file("docs/protocol.md"),
                                              "## Runtime parameters");
  REQUIRE(documented.size() >= 10);
  for (const auto& p : net::param_table()) {
    INFO(p.name);
    REQUIRE(documented.count(std::string(p.name)) == 1);
    const auto& cells = documented[std::string(p.name)];
    REQUIRE(cells.size() >= 3);
    std::string unit(p.unit);
    if (unit == "mm/s2") unit = "mm/s²";  // the wire is ASCII, the docs need not be
    CHECK(cells[0] == unit);
    const std::string range = p.read_only ? "read-only" : p.max >= net::kUnbounded ? "≥ " + g(p.min) : g(p.min) + " … " + g(p.max);
    CHECK(cells[1] == range);
    if (!p.text) CHECK(cells[2] == g(p.initial));
  }
  for (const auto& [name, cells] : documented) {
    INFO("documented but not in the registry: " << name);
    CHECK(net::find_param(name) != nullptr);
  }
}
