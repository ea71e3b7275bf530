// messcap: file formats, and the built program against a fake daemon — exactly N points,
// open-ended capture ended by the daemon or by Ctrl-C, never losing a point.
#include <catch2/catch.hpp>

#include <csignal>
#include <fstream>
#include <thread>

#include "capture_options.hpp"
#include "child_process.hpp"
#include "fake_daemon.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/exchange/export_format.hpp"
#include "point_file.hpp"

using namespace imess::messcap;
using imess::test::ChildProcess;
using imess::test::client_binary;
using imess::test::FakeDaemon;
using imess::test::FakeDaemonScript;
using imess::test::read_file;
using imess::test::TempDir;

namespace {

// MeasPt lines among the noise a real messd sends while someone measures.
const std::vector<std::string> kSession = {
    "CurrCor 0.000 0.000 0.000", "State jog",      "CurrCor 10.000 0.000 0.000",
    "MeasPt 10.250 0.000 0.000", "State retract",  "Warn TipNotFree Could not free the tip",
    "MeasPt 1 2",  // malformed: not a point
    "CurrCor 9.750 0.000 0.000", "MeasPt -1.500 20.000 3.125", "Ok ForcePt",
    "MeasPt 0.000 0.000 -7.000", "MeasPt 99.000 99.000 99.000",
};

std::vector<std::string> args(std::initializer_list<const char*> list) {
  std::vector<std::string> a{client_binary("messcap")};
  for (const char* s : list) a.emplace_back(s);
  return a;
}

}  // namespace

TEST_CASE("export_format_for: by extension, case-insensitive - others rejected naming all") {
  using imess::exchange::export_format_for;
  CHECK(export_format_for("points.csv").extension == ".csv");
  CHECK(export_format_for("dir.x/Points.CSV").extension == ".csv");
  CHECK(export_format_for("a.xyz").appendable());
  CHECK_FALSE(export_format_for("a.DXF").appendable());
  CHECK_THROWS_WITH(export_format_for("a.txt"), Catch::Contains("'.txt'") && Catch::Contains(".csv") &&
                                                     Catch::Contains(".xyz") && Catch::Contains(".dmi"));
  CHECK_THROWS_AS(export_format_for("dir.csv/noext"), imess::exchange::FormatError);
}

TEST_CASE("line formats: 3 decimals, comma or blank separated, never -0.000") {
  const auto& csv = imess::exchange::export_format_for("p.csv");
  const auto& xyz = imess::exchange::export_format_for("p.xyz");
  CHECK(csv.point_line({1.5, -2, 0.0004}, 3) == "1.500,-2.000,0.000\n");
  CHECK(xyz.point_line({1.5, -2, -0.0004}, 3) == "1.500 -2.000 0.000\n");
}

TEST_CASE("parse_capture_options: -n and -o in their spellings, errors name the argument") {
  const char* a1[] = {"messcap", "localhost:1067", "-n", "3", "-o", "p.xyz"};
  auto o = parse_capture_options(6, a1);
  CHECK(o.endpoint.port == 1067);
  CHECK(o.count == 3);
  CHECK(o.out.output == "p.xyz");
  CHECK(o.out.mode == OpenMode::New);
  const char* a2[] = {"messcap", "-n5", "--output=q.csv", "--append"};
  o = parse_capture_options(4, a2);
  CHECK(o.count == 5);
  CHECK(o.out.output == "q.csv");
  CHECK(o.out.mode == OpenMode::Append);
  CHECK(o.endpoint.host == "localhost");
  const char* a3[] = {"messcap", "-n", "0"};
  CHECK_THROWS_WITH(parse_capture_options(3, a3), Catch::Contains("-n '0'") && Catch::Contains("whole number"));
  const char* a4[] = {"messcap", "-n"};
  CHECK_THROWS_WITH(parse_capture_options(2, a4), Catch::Contains("-n needs a value"));
  const char* a5[] = {"messcap", "--frobnicate"};
  CHECK_THROWS_WITH(parse_capture_options(2, a5), Catch::Contains("'--frobnicate'"));
  const char* a6[] = {"messcap", "--force"};
  CHECK_THROWS_WITH(parse_capture_options(2, a6), Catch::Contains("needs -o"));
}

TEST_CASE("messcap -n 3 -o x.csv: exactly the first three points, amid noise") {
  TempDir dir;
  auto csv = dir.file("x.csv");
  FakeDaemon daemon({0, kSession, {}});
  ChildProcess cap(args({daemon.address().c_str(), "-n", "3", "-o", csv.c_str()}));
  auto status = cap.wait();
  REQUIRE(status);
  CHECK(*status == 0);
  CHECK(read_file(csv) == "hit,x,y,z,scan\n,10.250,0.000,0.000,\n,-1.500,20.000,3.125,\n,0.000,0.000,-7.000,\n");  // MeasPt: no number
  CHECK(cap.out() ==
        "point 1: 10.250 0.000 0.000\npoint 2: -1.500 20.000 3.125\npoint 3: 0.000 0.000 -7.000\n");
  CHECK(daemon.wait_for_line("Hello messcap"));
}

TEST_CASE("messcap: a point split across TCP segments is still one point") {
  TempDir dir;
  auto xyz = dir.file("p.xyz");
  FakeDaemon daemon({0, {"CurrCor 0.000 0.000 0.000"}, {}});
  ChildProcess cap(args({daemon.address().c_str(), "-n", "2", "-o", xyz.c_str()}));
  REQUIRE(daemon.wait_for_line("Hello messcap"));
  daemon.send_raw("MeasPt 1.0");
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  daemon.send_raw("00 2.000 3.000\nCurrCor 1.000 2.000 3.000\nMeasPt 4.000 5.000 6.000\n");
  REQUIRE(cap.wait() == 0);
  CHECK(read_file(xyz) == "1.000 2.000 3.000\n4.000 5.000 6.000\n");
}

TEST_CASE("messcap without --reconnect: messd going away is exit 4 with a clear message, every point written") {
  TempDir dir;
  auto xyz = dir.file("all.xyz");
  FakeDaemon daemon({0, kSession, {}});
  ChildProcess cap(args({daemon.address().c_str(), "-o", xyz.c_str()}));
  REQUIRE(daemon.wait_for_line("Hello messcap"));
  daemon.drop_clients();
  auto status = cap.wait();
  REQUIRE(status);
  CHECK(*status == imess::client::kExitLinkLost);
  CHECK_THAT(cap.err(), Catch::Contains("messd went away") && Catch::Contains("--reconnect"));
  CHECK(read_file(xyz) ==
        "10.250 0.000 0.000\n-1.500 20.000 3.125\n0.000 0.000 -7.000\n99.000 99.000 99.000\n");
  CHECK_THAT(cap.err(), Catch::Contains("4 points written") && Catch::Contains("closed by messd"));
}

TEST_CASE("messcap without -n: Ctrl-C (SIGINT) ends the capture, every point written") {
  TempDir dir;
  auto csv = dir.file("int.csv");
  FakeDaemon daemon({0, kSession, {}});
  ChildProcess cap(args({daemon.address().c_str(), "-o", csv.c_str()}));
  REQUIRE(cap.wait_for_output("point 4:"));
  daemon.send("MeasPt 5.000 5.000 5.000");
  REQUIRE(cap.wait_for_output("point 5:"));
  cap.signal(SIGINT);
  auto status = cap.wait();
  REQUIRE(status);
  CHECK(*status == 0);
  CHECK(read_file(csv) ==
        "hit,x,y,z,scan\n,10.250,0.000,0.000,\n,-1.500,20.000,3.125,\n,0.000,0.000,-7.000,\n,99.000,99.000,99.000,\n"
        ",5.000,5.000,5.000,\n");
  CHECK_THAT(cap.err(), Catch::Contains("5 points written") && Catch::Contains("interrupted"));
}

TEST_CASE("messcap -n: stopped early keeps the points and exits 3") {
  TempDir dir;
  auto csv = dir.file("short.csv");
  FakeDaemon daemon({0, kSession, {}});
  ChildProcess cap(args({daemon.address().c_str(), "-n", "10", "-o", csv.c_str()}));
  REQUIRE(cap.wait_for_output("point 4:"));
  cap.signal(SIGINT);
  CHECK(cap.wait() == 3);
  CHECK(read_file(csv) == "hit,x,y,z,scan\n,10.250,0.000,0.000,\n,-1.500,20.000,3.125,\n,0.000,0.000,-7.000,\n"
                          ",99.000,99.000,99.000,\n");
  CHECK_THAT(cap.err(), Catch::Contains("before all 10 points"));
}

TEST_CASE("messcap: never overwrites a capture unless told - --append continues it") {
  TempDir dir;
  auto csv = dir.file("keep.csv");
  FakeDaemon daemon({0, {"MeasPt 1.000 1.000 1.000"}, {}});
  REQUIRE(imess::test::run_program(args({daemon.address().c_str(), "-n", "1", "-o", csv.c_str()})).status == 0);
  auto again = imess::test::run_program(args({daemon.address().c_str(), "-n", "1", "-o", csv.c_str()}));
  CHECK(again.status == 1);
  CHECK_THAT(again.err, Catch::Contains("exists") && Catch::Contains("--append"));
  CHECK(imess::test::run_program(args({daemon.address().c_str(), "-n", "1", "-o", csv.c_str(), "--append"}))
            .status == 0);
  CHECK(read_file(csv) == "hit,x,y,z,scan\n,1.000,1.000,1.000,\n,1.000,1.000,1.000,\n");  // one header
  CHECK(imess::test::run_program(args({daemon.address().c_str(), "-n", "1", "-o", csv.c_str(), "--force"}))
            .status == 0);
  CHECK(read_file(csv) == "hit,x,y,z,scan\n,1.000,1.000,1.000,\n");
}

namespace {
std::string hit(int seq, double z) {
  char line[120];
  std::snprintf(line, sizeof line, "Hit %d 0 430.0000 330.0000 %.4f 0.000000 0.000000 -1.000000 2.0000 %d.000000", seq, z,
                seq);
  return line;
}
std::string meas(double z) {
  char line[60];
  std::snprintf(line, sizeof line, "MeasPt 430.000 330.000 %.3f", z);
  return line;
}
}  // namespace

TEST_CASE("messcap takes Hit lines, keeps their numbers in .xyz and on screen, and does not count their MeasPt twice") {
  TempDir dir;
  auto xyz = dir.file("hits.xyz");
  FakeDaemonScript script{0, {"CurrCor 0.000 0.000 0.000", hit(5, 80), meas(80), "State retract", hit(6, 81.25), meas(81.25)},
                          [](const std::string& line) -> std::vector<std::string> {
                            if (line == "Replay 9007199254740991") return {"Ok Replay 0 6"};  // the start probe
                            return {};
                          }};
  FakeDaemon daemon(script);
  auto r = imess::test::run_program(args({daemon.address().c_str(), "-n", "2", "-o", xyz.c_str()}));
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(read_file(xyz) == "430.000 330.000 80.000 # hit 5\n430.000 330.000 81.250 # hit 6\n");
  CHECK(r.out == "point 1: 430.000 330.000 80.000 (hit 5)\npoint 2: 430.000 330.000 81.250 (hit 6)\n");  // numbers for Align
  // messcap fit reads the file back: the numbers are comments.
  auto fit = imess::test::run_program({client_binary("messcap"), "fit", "line", xyz});
  CHECK(fit.status == 0);
}

TEST_CASE("messcap --append continues after the file's last hit, fetching the missed ones with Replay") {
  TempDir dir;
  auto xyz = dir.file("more.xyz");
  { std::ofstream(xyz) << "430.000 330.000 79.000 # hit 4\n430.000 330.000 80.000 # hit 5\n"; }
  FakeDaemonScript script{0, {"CurrCor 0.000 0.000 0.000"}, [](const std::string& line) -> std::vector<std::string> {
                            if (line == "Replay 6") return {hit(6, 81), hit(7, 82), "Ok Replay 2 7"};
                            return {};
                          }};
  FakeDaemon daemon(script);
  auto r = imess::test::run_program(args({daemon.address().c_str(), "-n", "2", "-o", xyz.c_str(), "--append"}));
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(read_file(xyz) == "430.000 330.000 79.000 # hit 4\n430.000 330.000 80.000 # hit 5\n"
                          "430.000 330.000 81.000 # hit 6\n430.000 330.000 82.000 # hit 7\n");
  CHECK_THAT(r.err, Catch::Contains("continuing after hit 5"));
}

TEST_CASE("messcap --reconnect catches up after messd comes back: no hit twice, none skipped") {
  TempDir dir;
  auto xyz = dir.file("rc.xyz");
  // Each connection gets hits 1 and 2 again (as a restarted messd would not, but a Replay
  // overlapping the live stream does); Replay 3 gives 3 and 4, the first reply capped.
  FakeDaemonScript script{0, {"CurrCor 0.000 0.000 0.000", hit(1, 80), meas(80), hit(2, 81), meas(81)},
                          [](const std::string& line) -> std::vector<std::string> {
                            if (line == "Replay 9007199254740991") return {"Ok Replay 0 2"};  // the start probe
                            if (line == "Replay 3") return {hit(2, 81), hit(3, 82), "Ok Replay 2 4"};
                            if (line == "Replay 4") return {hit(4, 83), "Ok Replay 1 4"};
                            return {};
                          }};
  FakeDaemon daemon(script);
  ChildProcess cap(args({daemon.address().c_str(), "-n", "4", "-o", xyz.c_str(), "--reconnect"}));
  REQUIRE(cap.wait_for_output("point 2:"));
  daemon.drop_clients();
  auto status = cap.wait(std::chrono::seconds(10));
  INFO(cap.err());
  REQUIRE(status);
  CHECK(*status == 0);
  CHECK(read_file(xyz) == "430.000 330.000 80.000 # hit 1\n430.000 330.000 81.000 # hit 2\n"
                          "430.000 330.000 82.000 # hit 3\n430.000 330.000 83.000 # hit 4\n");
  CHECK_THAT(cap.err(), Catch::Contains("reconnect"));
  CHECK(daemon.accepted() == 2);
}
