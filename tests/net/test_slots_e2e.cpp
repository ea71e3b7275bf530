// Slots and fairness against a real messd: observers cannot lock out a controller, a flood
// earns Err 203 only for the flooder, a client that stops reading is dropped.
#include <catch2/catch.hpp>

#include <memory>
#include <thread>

#include "net_fixture.hpp"

using namespace imess::test;

TEST_CASE("110 observer sockets cannot lock out a controller from the machine's host") {
  TempConfig config(R"({ "server": { "max_clients": 20 },
                         "control": { "hosts": ["127.0.0.1/32"], "observe_hosts": ["127.0.0.0/8"], "reserved_slots": 4 } })");
  DaemonProcess messd({"--config", config.path()});
  std::vector<std::unique_ptr<LineClient>> crowd;
  int admitted = 0, refused = 0;
  for (int i = 0; i < 110; ++i) {
    crowd.push_back(std::make_unique<LineClient>(messd.port(), "127.0.0.2", 0));
    auto first = crowd.back()->next(3.0);
    REQUIRE(first);
    if (first->rfind("CurrCor", 0) == 0) ++admitted;
    else if (first->rfind("Err 208 ", 0) == 0) ++refused;
  }
  CHECK(admitted == 16);
  CHECK(refused == 94);
  LineClient panel(messd.port());  // 127.0.0.1
  REQUIRE(starts_with(panel.next(3.0), "CurrCor"));
  CHECK(panel.request("StartMv 0 0 20") == std::optional<std::string>("Ok StartMv"));
  CHECK(panel.request("StopMv") == std::optional<std::string>("Ok StopMv"));
}

TEST_CASE("observers flooding StopMv never cause Err 203 for the owner, whose own flood is capped") {
  DaemonProcess messd;
  LineClient owner(messd.port());
  REQUIRE(owner.request("StartMv 0 0 0") == std::optional<std::string>("Ok StartMv"));  // take control
  std::vector<std::unique_ptr<LineClient>> crowd;
  std::string stops;
  for (int i = 0; i < 1000; ++i) stops += "StopMv\n";
  for (int i = 0; i < 5; ++i) crowd.push_back(std::make_unique<LineClient>(messd.port()));
  std::string gotos;
  for (int i = 0; i < 20; ++i) gotos += "GoTo 430 330 " + std::to_string(100 + i % 2) + "\n";
  for (auto& c : crowd) c->send_raw(stops);
  owner.send_raw(gotos);
  int owner_ok = 0;
  for (int i = 0; i < 20; ++i) {
    auto r = owner.until([](const std::string& l) { return l.rfind("Ok ", 0) == 0 || l.rfind("Err ", 0) == 0; }, 10.0);
    REQUIRE(r);
    INFO(*r);
    CHECK(r->rfind("Err 203", 0) != 0);
    owner_ok += r->rfind("Ok GoTo", 0) == 0;
  }
  CHECK(owner_ok == 20);
  for (auto& c : crowd)
    for (int i = 0; i < 1000; ++i) REQUIRE(c->until_prefix("Ok StopMv", 10.0));
  // The owner's own flood: 5000 GoTo lines at once. Beyond its share of the command ring it
  // gets Err 203 itself; reading pauses while answers wait, so every line is answered and the
  // flooder is not dropped.
  std::string flood;
  for (int i = 0; i < 5000; ++i) flood += "GoTo 430 330 " + std::to_string(100 + i % 2) + "\n";
  owner.send_raw(flood);
  int full = 0, ok = 0;
  for (int i = 0; i < 5000; ++i) {
    auto r = owner.until([](const std::string& l) { return l.rfind("Ok ", 0) == 0 || l.rfind("Err ", 0) == 0; }, 10.0);
    REQUIRE(r);
    full += r->rfind("Err 203 ", 0) == 0;
    ok += *r == "Ok GoTo";
  }
  CHECK(full > 0);
  CHECK(ok + full == 5000);
  // Set travels in the parameter lane: 20000 of them take no ring slot and are all answered Ok.
  std::string sets;
  for (int i = 0; i < 20000; ++i) sets += "Set SpeedLevel 1\n";
  owner.send_raw(sets);
  int set_ok = 0;
  for (int i = 0; i < 20000; ++i) {
    auto r = owner.until([](const std::string& l) { return l.rfind("Ok ", 0) == 0 || l.rfind("Err ", 0) == 0; }, 10.0);
    REQUIRE(r);
    set_ok += *r == "Ok Set";
  }
  CHECK(set_ok == 20000);
  LineClient other(messd.port());
  CHECK(other.request("StopMv") == std::optional<std::string>("Ok StopMv"));
}

TEST_CASE("a client that stops reading is dropped after control.write_stall_s") {
  TempConfig config(R"({ "control": { "write_stall_s": 1 } })");
  DaemonProcess messd({"--config", config.path()});
  LineClient checker(messd.port());
  LineClient stuck(messd.port(), "", 4096);  // small receive buffer, never reads
  // Replies filling the socket buffers, yet well under the 1 MiB queue cap: about 600 KB.
  std::size_t one_help = 0;
  checker.send("Help");
  checker.until([&](const std::string& l) {
    one_help += l.size() + 1;
    return l.rfind("Ok Help", 0) == 0;
  });
  std::string helps;
  for (std::size_t bytes = 0; bytes < 600000; bytes += one_help) helps += "Help\n";
  stuck.send_raw(helps);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  auto before = checker.request("Status");
  REQUIRE(before);
  CHECK(status_field(*before, "Clients") == "2");
  std::string clients;
  for (int i = 0; i < 40 && clients != "1"; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    auto s = checker.request("Status");
    REQUIRE(s);
    clients = status_field(*s, "Clients");
  }
  CHECK(clients == "1");
}

TEST_CASE("a client that reads everything while polling Status every 20 ms is never dropped as stalled") {
  // Its last reply is usually still unacknowledged (delayed ACK) when the sweep looks, so the
  // kernel's count of waiting bytes stays the same from sweep to sweep although everything is
  // read: progress is judged by bytes acknowledged, not by the waiting count going down.
  TempConfig config(R"({ "control": { "write_stall_s": 0.5 } })");
  DaemonProcess messd({"--config", config.path()});
  LineClient poller(messd.port());
  REQUIRE(starts_with(poller.next(3.0), "CurrCor"));
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(4);
  int answered = 0;
  while (std::chrono::steady_clock::now() < until) {
    auto s = poller.request("Status", 2.0);
    REQUIRE(s);  // a drop ends the replies
    ++answered;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  CHECK(answered > 100);
  LineClient checker(messd.port());
  auto s = checker.request("Status");
  REQUIRE(s);
  CHECK(status_field(*s, "Clients") == "2");
}

TEST_CASE("a silent client holding control is dropped with Err 211 and the machine stops") {
  TempConfig config(R"({ "control": { "idle_drop_s": 1 } })");
  DaemonProcess messd({"--config", config.path()});
  LineClient observer(messd.port());
  LineClient owner(messd.port());
  REQUIRE(owner.request("StartMv 20 0 0") == std::optional<std::string>("Ok StartMv"));
  auto dropped = owner.until_prefix("Err 211 ", 4.0);
  REQUIRE(dropped);
  CHECK(dropped->find("holding control") != std::string::npos);
  CHECK(observer.until_prefix("Control none", 2.0));  // announced first, then the stop arrives
  CHECK(observer.until_prefix("State idle", 2.0));
  // A passive monitor is never dropped for silence.
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  auto s = observer.request("Status");
  REQUIRE(s);
  CHECK(status_field(*s, "Clients") == "1");
}

// Issue 26, 8: 100 connections from a control host that never send a command filled every
// slot for good. control.no_command_drop_s closes them; a client that sent a command, and an
// observer-only host (capped by reserved_slots), stay.
TEST_CASE("a connection from a control host that sends no command is dropped after control.no_command_drop_s") {
  TempConfig config(R"({ "control": { "hosts": ["127.0.0.1/32"], "observe_hosts": ["127.0.0.0/8"],
                                       "no_command_drop_s": 1 } })");
  DaemonProcess messd({"--config", config.path()});
  LineClient silent(messd.port());
  LineClient blank(messd.port());
  LineClient speaker(messd.port());
  LineClient observer(messd.port(), "127.0.0.2", 0);
  REQUIRE(starts_with(observer.next(3.0), "CurrCor"));
  REQUIRE(speaker.request("Hello panel"));
  blank.send("");  // a keep-alive is no command
  auto dropped = silent.until_prefix("Err 211 ", 4.0);
  REQUIRE(dropped);
  CHECK(dropped->find("no command within 1 s of connecting") != std::string::npos);
  CHECK(blank.until_prefix("Err 211 ", 2.0));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  auto s = speaker.request("Status");
  REQUIRE(s);
  CHECK(status_field(*s, "Clients") == "2");  // the speaker and the observer
}

TEST_CASE("max_clients above the descriptor limit is lowered at start with one warning") {
  TempConfig config(R"({ "server": { "max_clients": 1000 } })");
  // A hard limit of 200 descriptors: room for 200 - 64 clients; messd is stopped after 1.5 s.
  std::string cmd = "sh -c 'ulimit -n 200 && exec timeout -s TERM 1.5 " + std::string(IMESS_BIN_DIR) +
                    "/messd --config " + config.path() + " --port 0 --listen 127.0.0.1 --no-rt' 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  INFO(out);
  CHECK(out.find("max_clients lowered from 1000 to 136") != std::string::npos);
  CHECK(out.find("messd: OK") != std::string::npos);
}
