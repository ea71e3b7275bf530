// (c) Fifty clients at once: every one receives every measured point; a client that stops
// reading does not hold up the others.
#include <catch2/catch.hpp>

#include <memory>

#include "daemon_process.hpp"

using namespace imess::test;

TEST_CASE("50 clients each receive every MeasPt") {
  DaemonProcess messd;
  std::vector<std::unique_ptr<LineClient>> clients;
  for (int i = 0; i < 50; ++i) clients.push_back(std::make_unique<LineClient>(messd.port()));
  LineClient panel(messd.port());  // the jog panel drives; the 50 listen
  REQUIRE(panel.request("StartMv 0 0 -100") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(panel.until_prefix("State idle", 5.0));  // hit, retract, idle
  panel.send("ForcePt");
  auto forced = panel.until_prefix("MeasPt", 5.0);
  REQUIRE(forced);
  for (std::size_t i = 0; i < clients.size(); ++i) {
    INFO("client " << i);
    auto first = clients[i]->until_prefix("MeasPt", 5.0);
    REQUIRE(first);
    CHECK(*first == "MeasPt 430.000 330.000 80.000");
    auto second = clients[i]->until_prefix("MeasPt", 5.0);
    REQUIRE(second);
    CHECK(*second == *forced);
  }
}

TEST_CASE("a client that never reads does not stop the others") {
  DaemonProcess messd;
  LineClient stuck(messd.port());  // connected, never reads
  LineClient panel(messd.port());
  for (int i = 0; i < 200; ++i) panel.send("Help");  // lots of output to everyone who asks
  REQUIRE(panel.request("StartMv 0 0 -100", 10.0));
  CHECK(panel.until_prefix("MeasPt 430.000 330.000 80.000", 10.0));
}
