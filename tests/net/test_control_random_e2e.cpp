// Property against a real messd: seeded random commands from three sessions, one at a time;
// every reply is exactly what the control rules predict — only the owner's commands that move
// or change the machine are accepted, StopMv always is, and a disconnect frees control.
#include <catch2/catch.hpp>

#include <memory>
#include <random>

#include "net_fixture.hpp"

using namespace imess::test;

TEST_CASE("random commands from three sessions: only the owner moves the machine") {
  DaemonProcess messd;
  const std::vector<std::string> controlling{"StartMv 1 0 0", "StartMv 0 -1 0", "Set SpeedLevel 1", "ForcePt"};
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    std::vector<std::unique_ptr<LineClient>> s;
    for (int i = 0; i < 3; ++i) s.push_back(std::make_unique<LineClient>(messd.port()));
    int owner = -1;  // the model: index into s, -1 = nobody
    for (int step = 0; step < 150; ++step) {
      int i = static_cast<int>(rng() % 3);
      auto pick = rng() % 10;
      INFO("step " << step << " session " << i << " owner " << owner);
      if (pick < 4) {
        auto r = s[i]->request(controlling[rng() % controlling.size()]);
        REQUIRE(r);
        if (owner == -1 || owner == i) {
          REQUIRE(r->rfind("Ok ", 0) == 0);
          owner = i;
        } else {
          REQUIRE(r->rfind("Err 209 ", 0) == 0);
        }
      } else if (pick < 6) {
        REQUIRE(s[i]->request("StopMv") == std::optional<std::string>("Ok StopMv"));
      } else if (pick == 6) {
        auto r = s[i]->request("Take");
        REQUIRE(r);
        REQUIRE((r->rfind("Ok Take", 0) == 0) == (owner == -1 || owner == i));
        if (owner == -1) owner = i;
      } else if (pick == 7) {
        auto r = s[i]->request("Release");
        REQUIRE(r);
        REQUIRE((r->rfind("Ok Release", 0) == 0) == (owner == -1 || owner == i));
        if (owner == i) owner = -1;
      } else if (pick == 8) {
        s[i] = std::make_unique<LineClient>(messd.port());  // the old connection closes
        if (owner == i) owner = -1;
        REQUIRE(s[i]->until_prefix("CurrCor", 3.0));
        auto st = s[i]->request("Status");  // the close has been handled before this answer
        REQUIRE(st);
        CHECK((status_field(*st, "Control") == "none") == (owner == -1));
      } else {
        auto st = s[i]->request("Status");
        REQUIRE(st);
        CHECK((status_field(*st, "Control") == "none") == (owner == -1));
      }
    }
    for (auto& c : s) c->request("StopMv");
  }
}
