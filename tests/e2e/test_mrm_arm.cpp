// The MRM arm end to end: messd started on config/sim-mrm-arm.json, one MoveTo moving X Y C U
// V together over TCP. AxPos (every axis by its letter, at the CurrCor rate) shows all five
// at the same fraction of their way at every report, and at their targets at the end.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "daemon_process.hpp"
#include "private_config.hpp"

using namespace imess::test;

namespace {

// "AxPos X200.000 Y150.000 C0.000 U0.000 V0.000" -> letter -> value.
std::map<char, double> ax_pos(const std::string& line) {
  std::map<char, double> out;
  std::istringstream words(line.substr(6));
  std::string w;
  while (words >> w) out[w[0]] = std::stod(w.substr(1));
  return out;
}

}  // namespace

TEST_CASE("the MRM arm over TCP: one MoveTo moves X Y C U V together — AxPos shows all five") {
  // a port space of its own: another test may run messd on the shipped file at the same time
  const std::string config = private_port_config(std::string(IMESS_SOURCE_DIR) + "/config/sim-mrm-arm.json");
  DaemonProcess messd({"--config", config});
  LineClient c(messd.port());
  REQUIRE(c.until_prefix("CurrCor ") == std::string("CurrCor 200.000 150.000 0.000"));  // no Z: 0
  auto first = c.until_prefix("AxPos ");
  REQUIRE(first);
  const auto start = ax_pos(*first);
  REQUIRE(start.size() == 5);
  const std::map<char, double> target{{'X', 320}, {'Y', 90}, {'C', 120}, {'U', -60}, {'V', 75}};

  REQUIRE(c.request("MoveTo 1 X320 Y90 C120 U-60 V75 F40") == std::string("Ok MoveTo"));
  std::vector<std::map<char, double>> reports;
  auto done = c.until([&](const std::string& l) {
    if (l.rfind("AxPos ", 0) == 0) reports.push_back(ax_pos(l));
    return l == "Done 1" || l.rfind("Failed 1", 0) == 0;
  }, 30);
  REQUIRE(done == std::string("Done 1"));
  CHECK(reports.size() >= 10);  // 10 Hz over about 3 s of motion
  // Coordinated: at every report every axis is the same fraction of its way (servo lag and a
  // count of 0.01 apart).
  double worst = 0;
  for (const auto& r : reports) {
    double lo = 2, hi = -2;
    for (const auto& [letter, goal] : target) {
      const double f = (r.at(letter) - start.at(letter)) / (goal - start.at(letter));
      lo = std::min(lo, f);
      hi = std::max(hi, f);
    }
    worst = std::max(worst, hi - lo);
  }
  CHECK(worst < 0.02);
  WARN("arm over TCP: " << reports.size() << " AxPos reports, fractions of the way within " << worst);

  // At rest on the target: Status gives every axis in the machine's order (X Y C U V).
  const std::array<double, 5> goal{320, 90, 120, -60, 75};
  bool there = false;
  std::string last;
  for (int i = 0; i < 50 && !there; ++i) {
    auto st = c.request("Status");
    REQUIRE(st);
    last = *st;
    std::istringstream words(st->substr(st->find(" Pos ") + 5));
    there = true;
    for (double g : goal) {
      double v = 0;
      words >> v;
      there = there && std::abs(v - g) <= 0.05;  // in position (0.02) and the PID on a real clock
    }
  }
  INFO(last);
  CHECK(there);

  // A letter the arm lacks is refused, naming its axes.
  CHECK(c.request("MoveTo 2 Z10") == std::string("Err 105 this machine has no axis Z; its axes are X Y C U V"));
  // JogAx of the rotary C: it turns, then stands.
  REQUIRE(c.request("JogAx C-40") == std::string("Ok JogAx"));
  auto turning = c.until([&](const std::string& l) { return l.rfind("AxPos ", 0) == 0 && ax_pos(l).at('C') < 115; }, 10);
  CHECK(turning);
  CHECK(c.request("JogAx C0") == std::string("Ok JogAx"));
  c.send("Quit");
  std::filesystem::remove(config);
}
