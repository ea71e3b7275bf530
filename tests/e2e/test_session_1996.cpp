// (a) A 1996 session byte for byte: the client sends only 1996 verbs with bare LF and reads
// only CurrCor / MeasPt lines; everything else it gets is a line it may ignore.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <regex>
#include <thread>

#include "daemon_process.hpp"

using namespace imess::test;

namespace {
// The 1996 grammar of the two messages a 1996 client understands.
const std::regex k1996Line(R"((CurrCor|MeasPt) -?\d+\.\d{3} -?\d+\.\d{3} -?\d+\.\d{3})");
}

TEST_CASE("a 1996 client jogs onto the cube top and receives the exact surface point") {
  DaemonProcess messd;
  LineClient c(messd.port());
  // Sent on connect: the current position, exactly as in 1996.
  REQUIRE(c.next() == std::optional<std::string>("CurrCor 430.000 330.000 100.000"));
  c.send_raw("StartMv 0 0 -20\n");
  auto pt = c.until_prefix("MeasPt ", 10.0);
  REQUIRE(pt);
  // Ball centre latched at z = 82 (radius 2 above the top at 80); compensated along -Z.
  CHECK(*pt == "MeasPt 430.000 330.000 80.000");
  // The retract ends 0.5 mm behind the latched point: position reports settle at 82.500.
  REQUIRE(c.until([](const std::string& l) { return l == "CurrCor 430.000 330.000 82.500"; }, 5.0));
  // ForcePt: the current position, no radius correction.
  c.send_raw("ForcePt\n");
  auto forced = c.until_prefix("MeasPt ", 3.0);
  REQUIRE(forced);
  CHECK(*forced == "MeasPt 430.000 330.000 82.500");
  c.send_raw("StopMv\n");
  REQUIRE(c.until_prefix("Ok StopMv", 3.0));
  // Every line was either one a 1996 client understands, or one it ignores: never a line
  // that starts like a 1996 message but breaks its grammar.
  for (const auto& l : c.seen()) {
    INFO(l);
    if (l.rfind("CurrCor", 0) == 0 || l.rfind("MeasPt", 0) == 0) CHECK(std::regex_match(l, k1996Line));
  }
  // And the wire carries only LF-terminated ASCII.
  for (unsigned char ch : c.raw()) CHECK((ch == '\n' || (ch >= 0x20 && ch < 0x7f)));
}

TEST_CASE("CurrCor is sent only when the position changed") {
  DaemonProcess messd;
  LineClient c(messd.port());
  REQUIRE(c.next());
  // Standing still (loops open, nobody pushing): no further CurrCor for a second.
  CHECK_FALSE(c.until_prefix("CurrCor", 1.2));
}

TEST_CASE("while the tip is touched, StartMv toward or along the part gets Err 200, and away from it moves") {
  DaemonProcess messd;
  LineClient c(messd.port());
  REQUIRE(c.request("HandMv 0 0 -18.5 20") == std::optional<std::string>("Ok HandMv"));
  REQUIRE(c.until_prefix("CurrCor 430.000 330.000 81.500", 5.0));
  for (const char* toward : {"StartMv 0 0 -20", "StartMv 20 0 0"}) {
    auto r = c.request(toward);
    REQUIRE(r);
    CHECK(r->rfind("Err 200 ", 0) == 0);
  }
  auto st = c.request("Status");
  REQUIRE(st);
  CHECK(st->find("Tip touched") != std::string::npos);
  CHECK(c.request("StartMv 0 0 20") == std::optional<std::string>("Ok StartMv"));  // back out along the approach
  REQUIRE(c.until_prefix("CurrCor 430.000 330.000 9", 5.0));
  c.request("StopMv");
  st = c.request("Status");
  REQUIRE(st);
  CHECK(st->find("Tip free") != std::string::npos);
}

TEST_CASE("measuring by hand through the protocol: Free, push onto the top, a compensated point") {
  DaemonProcess messd;
  LineClient c(messd.port());
  REQUIRE(c.request("GoTo 430 330 90") == std::optional<std::string>("Ok GoTo"));
  REQUIRE(c.until_prefix("State idle", 5.0));
  CHECK(c.request("HandMv 0 0 -5")->rfind("Err 205 ", 0) == 0);  // the loops hold the machine
  REQUIRE(c.request("Free") == std::optional<std::string>("Ok Free"));
  REQUIRE(c.request("HandMv 3 4 -9 10") == std::optional<std::string>("Ok HandMv"));  // obliquely down
  auto pt = c.until_prefix("MeasPt ", 5.0);
  REQUIRE(pt);
  // Contact with the ball centre at z = 82; compensated by r = 2 along the push direction
  // (3, 4, -9)/|..|: z = 82 - 2 * 9 / sqrt(106).
  double z = 82.0 - 2.0 * 9.0 / std::sqrt(106.0);
  char expect_z[32];
  std::snprintf(expect_z, sizeof expect_z, "%.3f", z);
  CHECK(pt->substr(pt->rfind(' ') + 1) == expect_z);
}

// The 1996 jog panel's own button code: press = `StartMv 0.000 0.000 -20.000`, the probe hits,
// the button is released (`StopMv`) 0-200 ms after the hit — often during the automatic
// retract — and pressed again. The retract must finish with the tip free, and the second
// press must move the machine into a second, identical hit (never a dead machine).
TEST_CASE("the 1996 panel's press, hit, release within 0-200 ms, press again") {
  DaemonProcess messd;
  LineClient c(messd.port());
  for (int delay_ms : {0, 20, 50, 100, 150, 200}) {
    INFO("released " << delay_ms << " ms after the hit");
    c.send_raw("StartMv 0.000 0.000 -20.000\n");
    auto first = c.until_prefix("MeasPt ", 10.0);
    REQUIRE(first);
    CHECK(*first == "MeasPt 430.000 330.000 80.000");
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    c.send_raw("StopMv\n");
    REQUIRE(c.until_prefix("State idle", 5.0));
    c.send_raw("StartMv 0.000 0.000 -20.000\n");  // pressed again, toward the part
    auto again = c.until([](const std::string& l) { return l.rfind("MeasPt ", 0) == 0 || l.rfind("Err ", 0) == 0 ||
                                                           l.rfind("Warn ", 0) == 0; }, 10.0);
    REQUIRE(again);
    CHECK(*again == "MeasPt 430.000 330.000 80.000");
    c.send_raw("StopMv\n");
    REQUIRE(c.until_prefix("State idle", 5.0));
    auto st = c.request("Status");
    REQUIRE(st);
    INFO(*st);
    CHECK(st->find("Tip free") != std::string::npos);
    auto pos = st->find(" Pos ");
    REQUIRE(pos != std::string::npos);
    double x = 0, y = 0, z = 0;
    REQUIRE(std::sscanf(st->c_str() + pos, " Pos %lf %lf %lf", &x, &y, &z) == 3);
    CHECK(std::abs(z - 82.5) < 0.006);  // retracted 0.5 mm behind the hit, within the in-position window
  }
}
