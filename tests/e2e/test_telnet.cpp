// (b) A telnet session: negotiation bytes, CRLF, garbage and an overlong line each get
// exactly one Err, and the session and the machine keep working.
#include <catch2/catch.hpp>

#include "daemon_process.hpp"
#include "imess/protocol/verbs.hpp"

using namespace imess::test;

TEST_CASE("telnet bytes, garbage and overlong lines get Err and the session goes on") {
  DaemonProcess messd;
  LineClient c(messd.port());
  REQUIRE(c.next());  // CurrCor on connect
  // What a telnet client sends first: IAC DO SGA, IAC WILL TTYPE, IAC SB NAWS ... IAC SE.
  c.send_raw(std::string("\xff\xfd\x03\xff\xfb\x18\xff\xfa\x1f\x00\x50\x00\x18\xff\xf0", 15));
  auto r = c.request("status\r");  // CRLF, lower case
  REQUIRE(r);
  CHECK(r->rfind("Ok Status State free", 0) == 0);

  CHECK(c.request("Fly 1 2 3\r")->rfind("Err 100 ", 0) == 0);
  CHECK(c.request("StartMv 1 x 3\r")->rfind("Err 102 ", 0) == 0);
  CHECK(c.request("StartMv 1 2\r")->rfind("Err 101 ", 0) == 0);
  CHECK(c.request("StartMv 0 0 500\r")->rfind("Err 105 ", 0) == 0);
  CHECK(c.request(std::string("Stat\x01us\r"))->rfind("Err 104 ", 0) == 0);
  CHECK(c.request(std::string("\xc3\xa4\xc3\xb6\r"))->rfind("Err 104 ", 0) == 0);
  CHECK(c.request("Set Nonsense 3\r")->rfind("Err 300 ", 0) == 0);
  CHECK(c.request("Set SpeedLevel 9\r")->rfind("Err 105 ", 0) == 0);
  CHECK(c.request(std::string(5000, 'A') + "\r")->rfind("Err 103 ", 0) == 0);
  // Exactly one reply per bad line: the next reply belongs to the next request.
  CHECK(c.request("Get SpeedLevel\r") == std::optional<std::string>("Ok Get SpeedLevel 1.000"));
  // Blank lines are no commands and get no reply.
  c.send_raw("\r\n  \r\n");
  CHECK(c.request("Hello telnet\r")->rfind("Ok Hello IMESS 1", 0) == 0);

  // The machine still works: a jog to the cube top measures a point.
  REQUIRE(c.request("StartMv 0 0 -100\r") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(c.until_prefix("MeasPt 430.000 330.000 80.000", 5.0));
  CHECK(messd.running());
}

TEST_CASE("Help lists every command and ends with Ok Help") {
  DaemonProcess messd;
  LineClient c(messd.port());
  c.send("Help");
  std::vector<std::string> help;
  REQUIRE(c.until([&](const std::string& l) {
    if (l.rfind("Help ", 0) == 0) help.push_back(l);
    return l == "Ok Help";
  }));
  // One line per declared verb; JogAx only on machines whose axes are not exactly X Y Z (the
  // 1996 machine keeps the 1996 list; tests/golden/sim-mrm-arm.txt shows the arm's).
  CHECK(help.size() == imess::protocol::verb_table().size() - 1);
  for (const auto& l : help) CHECK(l.rfind("Help JogAx", 0) != 0);
  CHECK(help[0].rfind("Help StartMv vx vy vz - ", 0) == 0);
}

TEST_CASE("Quit closes only this connection") {
  DaemonProcess messd;
  LineClient a(messd.port()), b(messd.port());
  CHECK(a.request("Quit") == std::optional<std::string>("Ok Quit"));
  CHECK_FALSE(a.next(1.0));
  CHECK(a.closed());
  CHECK(b.request("Status")->rfind("Ok Status", 0) == 0);
}

TEST_CASE("replies come in the order of the requests, whoever answers them") {
  DaemonProcess messd;
  LineClient c(messd.port());
  // Motion commands are answered by the motion loop, the others by the io thread at once.
  c.send_raw("StartMv 0 0 20\nStatus\nGet TipRadius\nBogus\nStopMv\nHello\nForcePt\nStats\n");
  std::vector<std::string> replies;
  REQUIRE(c.until([&](const std::string& l) {
    if (l.rfind("Ok ", 0) == 0 || l.rfind("Err ", 0) == 0) replies.push_back(l.substr(0, l.find(' ', 4)));
    return replies.size() == 8;
  }));
  CHECK(replies == std::vector<std::string>{"Ok StartMv", "Ok Status", "Ok Get", "Err 100", "Ok StopMv", "Ok Hello",
                                            "Ok ForcePt", "Ok Stats"});
}

TEST_CASE("hostile telnet bytes never silence a session or merge two lines") {
  DaemonProcess messd;
  LineClient c(messd.port());
  REQUIRE(c.next());  // CurrCor on connect
  // IAC SB with no IAC SE: abandoned after 64 bytes, the line is refused, the session goes on.
  c.send_raw(std::string("\xff\xfa\x18", 3) + std::string(100, 'x') + "\n");
  CHECK(c.until_prefix("Err 104 ", 2.0));
  CHECK(c.request("Get SpeedLevel") == std::optional<std::string>("Ok Get SpeedLevel 1.000"));
  // IAC SB cut by an LF: that line is refused, the next one is read on its own.
  c.send_raw(std::string("\xff\xfa\x18", 3) + "\n");
  CHECK(c.until_prefix("Err 104 ", 2.0));
  // IAC LF: two lines, not 'StatusHello'.
  c.send_raw("Status\xff\nHello\n");
  CHECK(c.until_prefix("Err 104 ", 2.0));
  CHECK(c.until_prefix("Ok Hello IMESS", 2.0));
  // NUL and a lone CR inside a line: Err 104, as promised for control bytes.
  CHECK(c.request(std::string("Sta\0tus", 7))->rfind("Err 104 ", 0) == 0);
  CHECK(c.request("Sta\rtus")->rfind("Err 104 ", 0) == 0);
  // Telnet's CR NUL ends a line.
  c.send_raw(std::string("Get TipRadius\r\0", 15));
  CHECK(c.until_prefix("Ok Get TipRadius", 2.0) == std::optional<std::string>("Ok Get TipRadius 2.000"));
}

TEST_CASE("a number that underflows is zero, one that overflows is not a number (Err 102)") {
  DaemonProcess messd;
  LineClient c(messd.port());
  CHECK(c.request("Set TipRadius 1e-400") == std::optional<std::string>("Ok Set"));
  CHECK(c.request("Get TipRadius") == std::optional<std::string>("Ok Get TipRadius 0.000"));
  CHECK(c.request("Set TipRadius 1e400")->rfind("Err 102 TipRadius takes a number from 0 to 50", 0) == 0);  // not a finite number
  CHECK(c.request("Get TipRadius") == std::optional<std::string>("Ok Get TipRadius 0.000"));
  CHECK(c.request("GoTo 1e400 0 0")->rfind("Err 102 ", 0) == 0);
  CHECK(c.request("StartMv 1e-400 0 0") == std::optional<std::string>("Ok StartMv"));
}

TEST_CASE("read-only parameters: Get reads them, Set answers Err 301, Get alone lists them") {
  DaemonProcess messd;
  LineClient c(messd.port());
  CHECK(c.request("Get Period") == std::optional<std::string>("Ok Get Period 1000"));
  CHECK(c.request("Get axes") == std::optional<std::string>("Ok Get Axes 3"));
  CHECK(c.request("Get Backend") == std::optional<std::string>("Ok Get Backend sim-servo-card"));
  CHECK(c.request("Set Period 500") ==
        std::optional<std::string>("Err 301 Period can be read but not set: the motion loop's period, from the "
                                   "configuration's motion.period_us; Get reads it"));
  CHECK(c.request("Set Backend x")->rfind("Err 301 Backend can be read but not set", 0) == 0);
  auto all = c.request("Get");
  REQUIRE(all);
  CHECK(all->rfind("Ok Get TipRadius 2.000 ", 0) == 0);
  CHECK(all->find(" ReportHz 10.000 Period 1000 Axes 3 Backend sim-servo-card") != std::string::npos);
  CHECK(c.request("Get Period")->rfind("Ok Get Period 1000", 0) == 0);  // a refused Set changed nothing
}

TEST_CASE("Version answers the daemon's version, as Hello does, to anyone") {
  DaemonProcess messd;
  LineClient owner(messd.port()), observer(messd.port());
  REQUIRE(owner.request("Take") == std::optional<std::string>("Ok Take"));
  auto version = observer.request("Version");
  REQUIRE(version);
  CHECK(version->rfind("Ok Version ", 0) == 0);
  CHECK(observer.request("Hello")->find("messd " + version->substr(11) + " Caps") != std::string::npos);
}
