// Control against a real messd: one client moves the machine, observers are refused naming
// it, anyone may stop, control changes are announced, host rules hold.
#include <catch2/catch.hpp>

#include "net_fixture.hpp"

using namespace imess::test;

TEST_CASE("an observer's commands that move or change the machine are refused naming the owner") {
  DaemonProcess messd;
  LineClient panel(messd.port()), other(messd.port());
  REQUIRE(starts_with(panel.request("Hello panel"), "Ok Hello"));
  REQUIRE(panel.request("StartMv 20 0 0") == std::optional<std::string>("Ok StartMv"));
  for (auto line : {"StartMv -20 0 0", "GoTo 500 300 100", "Home", "Free", "Reset", "Set MaxSpeed 1000",
                    "Set TipRadius 50", "HandMv 1 0 0", "ForcePt", "Take"}) {
    INFO(line);
    auto r = other.request(line);
    REQUIRE(starts_with(r, "Err 209 "));
    CHECK(r->find("panel at 127.0.0.1") != std::string::npos);
  }
  // Reading stays open to all; nothing was changed.
  CHECK(other.request("Get MaxSpeed") == std::optional<std::string>("Ok Get MaxSpeed 100.000"));
  CHECK(other.request("Get TipRadius") == std::optional<std::string>("Ok Get TipRadius 2.000"));
  auto status = other.request("Status");
  REQUIRE(starts_with(status, "Ok Status State jog "));
  CHECK(status_field(*status, "Control") == "panel@127.0.0.1");
  CHECK(starts_with(other.request("Stats"), "Ok Stats "));
  CHECK(starts_with(other.request("Help"), "Ok Help"));
  CHECK(panel.request("StopMv") == std::optional<std::string>("Ok StopMv"));
}

TEST_CASE("StopMv from an observer stops the owner's jog and does not take control") {
  DaemonProcess messd;
  LineClient panel(messd.port()), observer(messd.port());
  REQUIRE(observer.until_prefix("CurrCor", 2.0));  // admitted before the jog's State line
  REQUIRE(panel.request("StartMv 20 0 0") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(observer.until_prefix("State jog", 2.0));
  CHECK(observer.request("StopMv") == std::optional<std::string>("Ok StopMv"));
  CHECK(panel.until_prefix("State idle", 2.0));
  auto status = observer.request("Status");
  REQUIRE(status);
  CHECK(status_field(*status, "Control") == "client1@127.0.0.1");  // still the panel's
  CHECK(panel.request("StartMv 0 20 0") == std::optional<std::string>("Ok StartMv"));  // the owner goes on
  CHECK(panel.request("StopMv") == std::optional<std::string>("Ok StopMv"));
}

TEST_CASE("control changes are announced to everyone, Take force stops the machine and tells the old owner") {
  DaemonProcess messd;
  LineClient a(messd.port()), b(messd.port()), watcher(messd.port());
  REQUIRE(starts_with(a.request("Hello panel"), "Ok Hello"));
  REQUIRE(starts_with(b.request("Hello operator"), "Ok Hello"));
  REQUIRE(a.request("StartMv 0 20 0") == std::optional<std::string>("Ok StartMv"));
  CHECK(watcher.until_prefix("Control ", 2.0) == std::optional<std::string>("Control panel 127.0.0.1"));
  CHECK(starts_with(b.request("Take"), "Err 209 "));
  REQUIRE(b.request("Take force") == std::optional<std::string>("Ok Take"));
  CHECK(a.until_prefix("Warn ControlTaken", 2.0) == std::optional<std::string>("Warn ControlTaken operator 127.0.0.1 took over; machine stopped"));
  CHECK(watcher.until_prefix("Control ", 2.0) == std::optional<std::string>("Control operator 127.0.0.1"));
  CHECK(watcher.until_prefix("State idle", 2.0));  // the take-over stopped the jog
  CHECK(starts_with(a.request("StartMv 0 20 0"), "Err 209 "));  // the old owner observes now
  CHECK(starts_with(a.request("Release"), "Err 209 "));         // and cannot release another's control
  CHECK(b.request("Release") == std::optional<std::string>("Ok Release"));
  CHECK(watcher.until_prefix("Control ", 2.0) == std::optional<std::string>("Control none"));
  CHECK(a.request("StartMv 0 -20 0") == std::optional<std::string>("Ok StartMv"));  // free again: taken implicitly
  CHECK(a.request("StopMv") == std::optional<std::string>("Ok StopMv"));
}

TEST_CASE("a host allowed only to observe may stop but never control, force needs a force host") {
  TempConfig config(R"({ "control": { "hosts": ["127.0.0.1/32", "127.0.0.2/32"], "observe_hosts": ["127.0.0.0/8"],
                                       "force_hosts": ["127.0.0.1/32"] } })");
  DaemonProcess messd({"--config", config.path()});
  LineClient far(messd.port(), "127.0.0.3", 0);     // observer host
  LineClient second(messd.port(), "127.0.0.2", 0);  // may control, may not force
  LineClient panel(messd.port());                   // 127.0.0.1: may force
  auto r = far.request("StartMv 20 0 0");
  REQUIRE(starts_with(r, "Err 210 "));
  CHECK(r->find("127.0.0.3") != std::string::npos);
  CHECK(starts_with(far.request("Take"), "Err 210 "));
  REQUIRE(second.request("StartMv 20 0 0") == std::optional<std::string>("Ok StartMv"));
  CHECK(far.request("StopMv") == std::optional<std::string>("Ok StopMv"));
  CHECK(second.until_prefix("State idle", 2.0));  // the observer host stopped the jog
  REQUIRE(panel.request("Take") != std::nullopt);
  CHECK(starts_with(panel.request("StartMv 1 0 0"), "Err 209 "));
  CHECK(panel.request("Take force") == std::optional<std::string>("Ok Take"));
  CHECK(starts_with(second.request("Take force"), "Err 210 "));
}

TEST_CASE("a host in neither list is refused at connect with a line saying why") {
  TempConfig config(R"({ "control": { "hosts": ["127.0.0.1/32"], "observe_hosts": ["127.0.0.2/32"] } })");
  DaemonProcess messd({"--config", config.path()});
  LineClient stranger(messd.port(), "127.0.0.3", 0);
  auto line = stranger.next(3.0);
  REQUIRE(starts_with(line, "Err 210 "));
  CHECK(line->find("127.0.0.3") != std::string::npos);
  CHECK_FALSE(stranger.next(3.0));
  CHECK(stranger.closed());
  LineClient watcher(messd.port(), "127.0.0.2", 0);
  CHECK(starts_with(watcher.until_prefix("CurrCor", 3.0), "CurrCor"));
}

TEST_CASE("Release and Quit stop the machine and free control") {
  DaemonProcess messd;
  LineClient watcher(messd.port());
  LineClient a(messd.port());
  REQUIRE(a.request("StartMv 20 0 0") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(watcher.until_prefix("State jog", 2.0));
  CHECK(a.request("Release") == std::optional<std::string>("Ok Release"));
  CHECK(watcher.until_prefix("Control none", 2.0));
  CHECK(watcher.until_prefix("State idle", 2.0));
  REQUIRE(a.request("StartMv 0 20 0") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(watcher.until_prefix("State jog", 2.0));
  CHECK(a.request("Quit") == std::optional<std::string>("Ok Quit"));
  CHECK(watcher.until_prefix("Control none", 2.0));
  CHECK(watcher.until_prefix("State idle", 2.0));
}

TEST_CASE("a Hello after taking control announces the owner under its new name") {
  DaemonProcess messd;
  LineClient panel(messd.port()), observer(messd.port());
  REQUIRE(observer.until_prefix("CurrCor", 2.0));  // admitted (else the Control line may precede it)
  REQUIRE(panel.request("Take") == std::optional<std::string>("Ok Take"));
  REQUIRE(observer.until_prefix("Control client1 127.0.0.1", 2.0));
  REQUIRE(starts_with(panel.request("Hello panel"), "Ok Hello"));
  CHECK(observer.until_prefix("Control panel 127.0.0.1", 2.0));
}

TEST_CASE("Set with a value that is no number is BadNumber, out of range BadValue") {
  DaemonProcess messd;
  LineClient c(messd.port());
  CHECK(starts_with(c.request("Set TipRadius abc"), "Err 102 "));
  CHECK(starts_with(c.request("Set TipRadius 99"), "Err 105 "));
  CHECK(c.request("Set TipRadius 1e-400") == std::optional<std::string>("Ok Set"));
}
