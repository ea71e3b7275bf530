// The handover against a real messd (control.handover_s, docs/protocol.md "Control"): an owner
// that left the machine at rest and sent nothing for handover_s hands control to the next client
// that asks, by a command that needs it or by Take; a moving machine, a queue (running or
// paused) or an I++ DME session keeps control where it is.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "net_fixture.hpp"

using namespace imess::test;
using namespace std::chrono_literals;

namespace {
// The default simulated CMM, its handover time written out (what the default is).
constexpr const char* kHandover = R"({ "control": { "handover_s": 2 } })";
}  // namespace

TEST_CASE("an owner idle for handover_s hands control to the next client that asks") {
  TempConfig config(kHandover);
  DaemonProcess messd({"--config", config.path()});
  LineClient telnet(messd.port()), panel(messd.port()), watcher(messd.port());
  REQUIRE(starts_with(telnet.request("Hello telnet"), "Ok Hello"));
  REQUIRE(starts_with(panel.request("Hello messjog"), "Ok Hello"));
  REQUIRE(watcher.until_prefix("CurrCor", 2.0));
  REQUIRE(telnet.request("StartMv 0 0 -20") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(telnet.until_prefix("MeasPt", 10.0));  // the top face: a point, the retract, then idle
  REQUIRE(telnet.until_prefix("State idle", 5.0));
  // At once it is still telnet's: it touched the part a moment ago.
  auto r = panel.request("StartMv 20 0 0");
  REQUIRE(starts_with(r, "Err 209 "));
  CHECK(r->find("telnet at 127.0.0.1") != std::string::npos);
  std::this_thread::sleep_for(2200ms);  // telnet silent, the machine at rest, nothing queued
  CHECK(panel.request("StartMv 20 0 0") == std::optional<std::string>("Ok StartMv"));
  CHECK(watcher.until_prefix("Control messjog 127.0.0.1", 2.0));
  CHECK(telnet.until_prefix("Control messjog 127.0.0.1", 2.0));
  // The jogging panel keeps it: telnet is refused while the machine moves, whatever the time.
  std::this_thread::sleep_for(2200ms);
  CHECK(starts_with(telnet.request("GoTo 430 330 120"), "Err 209 "));
  CHECK(starts_with(telnet.request("Take"), "Err 209 "));
  // Anyone may stop; stopping takes nothing.
  CHECK(telnet.request("StopMv") == std::optional<std::string>("Ok StopMv"));
  REQUIRE(watcher.until_prefix("State idle", 3.0));
  CHECK(status_field(*watcher.request("Status"), "Control") == "messjog@127.0.0.1");
  // Take asks as well: once the panel has been idle, telnet gets it back without force.
  std::this_thread::sleep_for(2200ms);
  CHECK(telnet.request("Take") == std::optional<std::string>("Ok Take"));
  CHECK(watcher.until_prefix("Control telnet 127.0.0.1", 2.0));
  CHECK(starts_with(panel.request("StartMv 20 0 0"), "Err 209 "));
}

TEST_CASE("queued moves, running or paused, keep control with their owner however long it is silent", "[long]") {
  TempConfig config(kHandover);
  DaemonProcess messd({"--config", config.path()});
  LineClient script(messd.port()), other(messd.port());
  REQUIRE(starts_with(script.request("Hello script"), "Ok Hello"));
  // A slow path of some seconds: the owner says nothing while it runs.
  REQUIRE(script.request("MoveTo 1 X430 Y330 Z120 F10") == std::optional<std::string>("Ok MoveTo"));
  REQUIRE(script.request("MoveTo 2 X470 F10") == std::optional<std::string>("Ok MoveTo"));
  std::this_thread::sleep_for(2500ms);
  auto r = other.request("GoTo 500 300 120");
  REQUIRE(starts_with(r, "Err 209 "));
  CHECK(r->find("script at 127.0.0.1") != std::string::npos);
  // Paused: the machine stands, but the queue waits for its owner.
  REQUIRE(script.request("Pause") == std::optional<std::string>("Ok Pause"));
  std::this_thread::sleep_for(2500ms);
  CHECK(starts_with(other.request("Take"), "Err 209 "));
  CHECK(starts_with(other.request("ForcePt"), "Err 209 "));
  REQUIRE(script.request("Resume") == std::optional<std::string>("Ok Resume"));
  REQUIRE(script.until_prefix("Done 2", 30.0));
  // Idle (asked: the State line may come before the Done line is read).
  bool idle = false;
  for (int i = 0; i < 100 && !idle; ++i) {
    idle = starts_with(script.request("Status"), "Ok Status State idle");
    if (!idle) std::this_thread::sleep_for(50ms);
  }
  REQUIRE(idle);
  // Done and idle: after handover_s the queue's owner lets go.
  std::this_thread::sleep_for(2200ms);
  CHECK(other.request("GoTo 470 330 110") == std::optional<std::string>("Ok GoTo"));
  CHECK(script.until_prefix("Control client2 127.0.0.1", 2.0));
}

TEST_CASE("handover_s 0 keeps control with its owner until it releases it") {
  TempConfig config(R"({ "control": { "handover_s": 0 } })");
  DaemonProcess messd({"--config", config.path()});
  LineClient a(messd.port()), b(messd.port());
  REQUIRE(a.request("ForcePt") == std::optional<std::string>("Ok ForcePt"));
  std::this_thread::sleep_for(2500ms);
  CHECK(starts_with(b.request("ForcePt"), "Err 209 "));
  CHECK(starts_with(b.request("Take"), "Err 209 "));
  REQUIRE(a.request("Release") == std::optional<std::string>("Ok Release"));
  CHECK(b.request("Take") == std::optional<std::string>("Ok Take"));
}

TEST_CASE("a bad handover_s stops messd at start naming the key and the range") {
  TempConfig config(R"({ "control": { "handover_s": -1 } })");
  auto run = run_messd_to_exit({"--config", config.path()});
  CHECK(run.status == 2);
  CHECK(run.err.find("handover_s") != std::string::npos);
  CHECK(run.err.find("0") != std::string::npos);
}
