// messmon: timestamp format, JSON line contents, and the built program against a fake daemon.
#include <catch2/catch.hpp>

#include <cctype>
#include <csignal>
#include <nlohmann/json.hpp>
#include <sstream>

#include "child_process.hpp"
#include "fake_daemon.hpp"
#include "iso_time.hpp"
#include "monitor_line.hpp"

using namespace imess::messmon;
using imess::test::ChildProcess;
using imess::test::client_binary;
using imess::test::FakeDaemon;
using nlohmann::json;

namespace {

// "2024-05-01T14:03:07.042+02:00": 'd' a digit, 's' a sign, anything else itself.
bool is_iso_time(const std::string& s) {
  const std::string pattern = "dddd-dd-ddTdd:dd:dd.ddds" "dd:dd";
  if (s.size() != pattern.size()) return false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    bool ok = pattern[i] == 'd'   ? std::isdigit(static_cast<unsigned char>(s[i])) != 0
              : pattern[i] == 's' ? (s[i] == '+' || s[i] == '-')
                                  : s[i] == pattern[i];
    if (!ok) return false;
  }
  return true;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

}  // namespace

TEST_CASE("iso_local_time: ISO 8601 with milliseconds and UTC offset") {
  auto t = std::chrono::system_clock::time_point{} + std::chrono::milliseconds(1714572187042);
  auto s = iso_local_time(t);
  CHECK(is_iso_time(s));
  CHECK(s.substr(19, 4) == ".042");
  auto whole = std::chrono::system_clock::time_point{} + std::chrono::seconds(1714572187);
  CHECK(iso_local_time(whole).substr(19, 4) == ".000");
}

TEST_CASE("json_line: type and parsed fields per message") {
  auto j = json::parse(json_line("T", "MeasPt 1.500 -2.000 3.000"));
  CHECK(j["t"] == "T");
  CHECK(j["line"] == "MeasPt 1.500 -2.000 3.000");
  CHECK(j["type"] == "MeasPt");
  CHECK(j["x"] == 1.5);
  CHECK(j["y"] == -2.0);
  CHECK(j["z"] == 3.0);
  CHECK(json::parse(json_line("T", "State jog"))["state"] == "jog");
  auto limit = json::parse(json_line("T", "Limit Z neg"));
  CHECK(limit["axis"] == "Z");
  CHECK(limit["side"] == "neg");
  auto warn = json::parse(json_line("T", "Warn TipNotFree do it by hand"));
  CHECK(warn["name"] == "TipNotFree");
  CHECK(warn["text"] == "do it by hand");
  auto err = json::parse(json_line("T", "Err 101 StartMv takes 3 numbers"));
  CHECK(err["code"] == 101);
  CHECK(err["text"] == "StartMv takes 3 numbers");
  auto ok = json::parse(json_line("T", "Ok Hello IMESS 1"));
  CHECK(ok["verb"] == "Hello");
  CHECK(ok["args"] == json::array({"IMESS", "1"}));
  CHECK(json::parse(json_line("T", "Homed"))["type"] == "Homed");
  CHECK(json::parse(json_line("T", "Help Hello [name] - hi"))["type"] == "Data");
  CHECK(json::parse(json_line("T", "bla \"quoted\" \\"))["line"] == "bla \"quoted\" \\");
  CHECK(json::parse(json_line("T", "bad \xff byte"))["type"] == "Other");  // still valid JSON
  CHECK(json_line("T", "Homed").rfind(R"({"t":"T","line":"Homed","type":"Homed")", 0) == 0);  // key order
}

TEST_CASE("messmon --json: one parseable object per received line - exit 0 when messd closes") {
  FakeDaemon daemon({0,
                     {"CurrCor 1.000 2.000 3.000", "MeasPt 4.000 5.000 -6.500", "State idle",
                      "Warn TipNotFree Could not free the tip", "not a message"},
                     [](const std::string& line) -> std::vector<std::string> {
                       if (line == "Hello messmon") return {"Ok Hello IMESS 1"};
                       return {};
                     }});
  ChildProcess mon({client_binary("messmon"), daemon.address(), "--json"});
  REQUIRE(daemon.wait_for_line("Hello messmon"));
  REQUIRE(mon.wait_for_output("Ok Hello"));
  daemon.drop_clients();
  auto status = mon.wait();
  REQUIRE(status);
  CHECK(*status == 0);
  CHECK_THAT(mon.err(), Catch::Contains("closed by messd"));

  auto lines = split_lines(mon.out());
  REQUIRE(lines.size() == 6);
  std::vector<std::string> types;
  for (const auto& l : lines) {
    auto j = json::parse(l);  // throws, failing the test, on anything that is not JSON
    CHECK(is_iso_time(j["t"].get<std::string>()));
    types.push_back(j["type"]);
  }
  CHECK(types == std::vector<std::string>{"CurrCor", "MeasPt", "State", "Warn", "Other", "Ok"});
  auto meas = json::parse(lines[1]);
  CHECK(meas["line"] == "MeasPt 4.000 5.000 -6.500");
  CHECK(meas["x"] == 4.0);
  CHECK(meas["y"] == 5.0);
  CHECK(meas["z"] == -6.5);
}

TEST_CASE("messmon: text lines are '<ISO time> <line>'") {
  FakeDaemon daemon({0, {"CurrCor 1.000 2.000 3.000"}, {}});
  ChildProcess mon({client_binary("messmon"), daemon.address()});
  REQUIRE(mon.wait_for_output("CurrCor"));
  daemon.drop_clients();
  REQUIRE(mon.wait() == 0);
  auto lines = split_lines(mon.out());
  REQUIRE(lines.size() == 1);
  auto blank = lines[0].find(' ');
  REQUIRE(blank != std::string::npos);
  CHECK(is_iso_time(lines[0].substr(0, blank)));
  CHECK(lines[0].substr(blank) == " CurrCor 1.000 2.000 3.000");
}

TEST_CASE("messmon --reconnect: keeps printing across a messd restart, ends on SIGINT") {
  auto daemon = std::make_unique<FakeDaemon>(imess::test::FakeDaemonScript{0, {"State idle"}, {}});
  auto port = daemon->port();
  ChildProcess mon({client_binary("messmon"), daemon->address(), "--reconnect"});
  REQUIRE(mon.wait_for_output("State idle"));
  daemon.reset();
  daemon = std::make_unique<FakeDaemon>(imess::test::FakeDaemonScript{port, {"State home"}, {}});
  REQUIRE(mon.wait_for_output("State home"));
  mon.signal(SIGINT);
  CHECK(mon.wait() == 0);
  CHECK_THAT(mon.err(), Catch::Contains("reconnected"));
}
