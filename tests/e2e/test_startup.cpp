// Start-up: bad configuration stops messd with one clear message; messdrc is honoured.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "shipped_config.hpp"
#include "daemon_process.hpp"
#include "private_config.hpp"

using namespace imess::test;

namespace {
struct Run {
  int status;
  std::string output;
};
Run run_messd(const std::string& args) {
  std::string cmd = std::string(IMESS_BIN_DIR) + "/messd " + args + " --port 0 --no-rt 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) out += buf;
  int st = pclose(p);
  return {WEXITSTATUS(st), out};
}
std::string temp_file(const std::string& name, const std::string& text) {
  auto path = std::filesystem::temp_directory_path() / ("imess-test-" + std::to_string(getpid()) + "-" + name);
  std::ofstream(path) << text;
  return path.string();
}
}  // namespace

TEST_CASE("an unknown configuration key stops start-up naming file and key") {
  auto f = temp_file("bad.json", R"({"motion": {"tip_radius": 2.0, "tip_radus": 3}})");
  auto r = run_messd("--config " + f);
  CHECK(r.status == 2);
  CHECK(r.output.find(f) != std::string::npos);
  CHECK(r.output.find("unknown key 'motion.tip_radus'") != std::string::npos);
}

TEST_CASE("a wrong value stops start-up saying what is expected") {
  auto f = temp_file("bad2.json", R"({"server": {"port": "http"}})");
  auto r = run_messd("--config " + f);
  CHECK(r.status == 2);
  CHECK(r.output.find("'server.port' must be a whole number from 0 to 65535") != std::string::npos);
  auto g = temp_file("bad3.json", R"({"motion": )");
  r = run_messd("--config " + g);
  CHECK(r.status == 2);
  CHECK(r.output.find("not valid JSON") != std::string::npos);
}

TEST_CASE("every shipped configuration loads") {
  for (const auto& entry : std::filesystem::directory_iterator(std::string(IMESS_SOURCE_DIR) + "/config")) {
    if (entry.path().extension() != ".json" || !simulated_config(entry.path())) continue;  // real hardware: below
    INFO(entry.path());
    const std::string config = private_config_if_ports(entry.path().string());  // another test may use the same port file
    DaemonProcess messd({"--config", config});
    LineClient c(messd.port());
    CHECK(c.request("Status")->rfind("Ok Status", 0) == 0);
    if (config != entry.path().string()) std::filesystem::remove(config);
  }
}

TEST_CASE("servo-card: a device that is missing or not a tty stops start-up with exit 2 naming it") {
  const std::string cfg = std::string(IMESS_SOURCE_DIR) + "/config/servo-card.json";
  auto r = run_messd_to_exit({"--config", cfg, "--device", "/nonexistent/ttyIMESS9"});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("/nonexistent/ttyIMESS9") && Catch::Contains("no such device"));
  r = run_messd_to_exit({"--config", cfg, "--device", cfg});  // a plain file
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("not a serial line"));
  r = run_messd_to_exit({"--device", "/dev/ttyUSB0"});  // the built-in simulated CMM has no device
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("--device") && Catch::Contains("servo-card"));
}

TEST_CASE("messdrc: values are used, unknown lines warned, bad values refused") {
  auto rc = temp_file("messdrc", "# stylus file\nSpeedLevel 0.8   # slower\nTipRadius 1.5\nFrobnicate yes\n");
  DaemonProcess messd({"--rc", rc});
  LineClient c(messd.port());
  CHECK(c.request("Get TipRadius") == std::optional<std::string>("Ok Get TipRadius 1.500"));
  CHECK(c.request("Get SpeedLevel") == std::optional<std::string>("Ok Get SpeedLevel 0.800"));
  auto bad = temp_file("messdrc-bad", "TipRadius two\n");
  auto r = run_messd("--rc " + bad);
  CHECK(r.status == 2);
  CHECK(r.output.find(":1: TipRadius takes one number") != std::string::npos);
}

TEST_CASE("command-line errors say what is accepted") {
  auto r = run_messd("--port nope");
  CHECK(r.status == 2);
  CHECK(r.output.find("--port takes a whole number from 0 to 65535") != std::string::npos);
  r = run_messd("--frobnicate");
  CHECK(r.status == 2);
  CHECK(r.output.find("usage: messd") != std::string::npos);
}

TEST_CASE("unusable configuration files stop start-up with exit 2 and a message, never an abort") {
  struct Case {
    std::string args, message;
  };
  auto dir = std::filesystem::temp_directory_path().string();
  std::vector<Case> cases{
      {"--config " + temp_file("huge.json", R"({"motion":{"max_speed":1e400}})"),
       "key 'motion.max_speed' must be a number from 0.1 to 1000, got \"1e400\""},
      {"--config " + dir, "is a directory, not a configuration file"},
      {"--config " + dir + "/imess-no-such-file.json", "cannot open the configuration file"},
      {"--config " + temp_file("empty.json", "  \n"), "is empty; a configuration is a JSON object"},
      {"--config " + temp_file("dup.json", R"({"axes":{"X":{"travel_min":0,"travel_min":1}}})"),
       "key 'axes.X.travel_min' appears twice in the same object"},
      {"--config " + temp_file("home.json", R"({"axes":{"X":{"home_position":5000}}})"),
       "key 'axes.X.home_position' must be a coordinate within the travel, from travel_min 0 to travel_max 1000"},
      {"--rc " + dir, "is a directory, not a messdrc file"},
      {"--rc " + temp_file("rc-dup", "TipRadius 1\nTipRadius 2\n"), ":2: TipRadius is set again (first on line 1)"},
      {"--rc " + temp_file("rc-huge", "TipRadius 1e400\n"), ":1: TipRadius takes one number from 0 to 50"},
      {"--listen nowhere", "--listen takes an IPv4 or IPv6 address"},
      {"--port 1e400", "--port takes a whole number from 0 to 65535"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    auto r = run_messd(c.args);
    CHECK(r.status == 2);
    CHECK(r.output.find(c.message) != std::string::npos);
  }
}

TEST_CASE("a messdrc value too small to represent is zero") {
  auto rc = temp_file("messdrc-tiny", "TipRadius 1e-400\n");
  DaemonProcess messd({"--rc", rc});
  LineClient c(messd.port());
  CHECK(c.request("Get TipRadius") == std::optional<std::string>("Ok Get TipRadius 0.000"));
}

TEST_CASE("a journal directory that cannot be created stops start-up with exit 2 and one message") {
  auto file = temp_file("not-a-dir", "x");
  auto r = run_messd("--journal " + file + "/journal");
  CHECK(r.status == 2);
  CHECK(r.output.find("cannot create the journal directory '" + file + "/journal'") != std::string::npos);
  CHECK(r.output.find("--journal DIR") != std::string::npos);
}

TEST_CASE("a bad control host list stops start-up naming the key and the accepted form") {
  auto f = temp_file("bad-control.json", R"({"control": {"hosts": ["127.0.0.0/8", "localhost"]}})");
  auto r = run_messd("--config " + f);
  CHECK(r.status == 2);
  CHECK(r.output.find("'control.hosts'") != std::string::npos);
  CHECK(r.output.find("'localhost' is not an IPv4 or IPv6 address") != std::string::npos);
  auto g = temp_file("bad-control2.json", R"({"control": {"observe_hosts": "0.0.0.0/0"}})");
  r = run_messd("--config " + g);
  CHECK(r.status == 2);
  CHECK(r.output.find("'control.observe_hosts' must be an array of strings") != std::string::npos);
  auto h = temp_file("bad-control3.json", R"({"control": {"reserved": 4}})");
  r = run_messd("--config " + h);
  CHECK(r.status == 2);
  CHECK(r.output.find("unknown key 'control.reserved'") != std::string::npos);
}
