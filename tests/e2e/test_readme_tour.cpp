// The README's five-minute tour, walked with its own commands against a real messd on the
// default simulated machine (what scripts/run starts) and the real clients: telnet (a plain
// line client) takes control at step 2 and stays open, and every later step — messjog in a
// terminal, messcap, the queue, measure_cube.py, messcap inspect and qualify, Align by hand,
// the outputs, a program, messprog run, an I++ DME session — works without an Err 209,
// because telnet, idle, hands control over (docs/protocol.md, "Control"). One test per part,
// each with its own messd, so each stays within the suite's time per test. The long measuring
// parts run on config/sim-servo-card-loop-time.json, the README's own choice for a host that
// stalls (the suite runs other tests beside them): the same machine, its clock paused with the
// host instead of the emulated card faulting (on the real-time one a loaded host fails queued
// moves with HostStall, as the README says) — here at sim.speed 4 (tests/e2e/tour-loop-time.json),
// the machine's clock four times as fast as the wall clock, the wall-clock rules as they are.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>
#include <tuple>

#include "child_process.hpp"
#include "daemon_process.hpp"
#include "private_config.hpp"

using namespace imess::test;
using namespace std::chrono_literals;

namespace {

const std::string kSource = IMESS_SOURCE_DIR;

// messd as scripts/run starts it: the built-in simulated CMM, the examples as programs folder.
std::vector<std::string> as_scripts_run(std::vector<std::string> more = {}) {
  std::vector<std::string> args{"--programs", kSource + "/examples/programs"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The same in loop time: a loaded host pauses the simulated machine, so it needs no real-time
// scheduling (and takes none from the suite's timing tests); four times as fast.
std::vector<std::string> as_scripts_run_in_loop_time() {
  return as_scripts_run({"--config", kSource + "/tests/e2e/tour-loop-time.json"});
}

std::string at(const DaemonProcess& messd) { return "127.0.0.1:" + std::to_string(messd.port()); }

// The handover time: an operator turning from telnet to the next program takes longer.
void turn_to_the_next_program() { std::this_thread::sleep_for(2300ms); }

// Step 2: telnet's first StartMv touches the top of the cube and takes control.
void telnet_touches_the_top(LineClient& telnet) {
  REQUIRE(telnet.next() == std::optional<std::string>("CurrCor 430.000 330.000 100.000"));
  REQUIRE(telnet.request("StartMv 0 0 -20") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(telnet.until_prefix("Hit ", 15.0));
  REQUIRE(telnet.until_prefix("State idle", 10.0));
}

bool begins(const std::optional<std::string>& line, const std::string& prefix) {
  return line && line->rfind(prefix, 0) == 0;
}

bool saw(const LineClient& c, const std::string& prefix) {
  for (const auto& l : c.seen())
    if (l.rfind(prefix, 0) == 0) return true;
  return false;
}

// A program in a terminal of `cols` columns (messjog needs one): keys in, the screen's bytes out.
class PtyProcess {
 public:
  PtyProcess(const std::vector<std::string>& argv, int cols, int rows) {
    winsize ws{};
    ws.ws_col = static_cast<unsigned short>(cols);
    ws.ws_row = static_cast<unsigned short>(rows);
    pid_ = forkpty(&fd_, nullptr, nullptr, &ws);
    if (pid_ == 0) {
      setenv("TERM", "xterm", 1);
      std::vector<char*> a;
      for (const auto& s : argv) a.push_back(const_cast<char*>(s.c_str()));
      a.push_back(nullptr);
      execv(a[0], a.data());
      _exit(127);
    }
  }
  ~PtyProcess() {
    if (pid_ > 0 && !exited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (fd_ >= 0) close(fd_);
  }
  void keys(const std::string& k) { (void)!write(fd_, k.data(), k.size()); }
  // Reads the screen's bytes until `text` has appeared in them (or the time is up).
  bool shows(const std::string& text, std::chrono::milliseconds timeout = 15s) {  // a loaded host starts programs slowly
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (screen_.find(text) == std::string::npos) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
      if (left.count() <= 0) return false;
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      char buf[4096];
      const auto n = read(fd_, buf, sizeof buf);
      if (n <= 0) return false;
      screen_.append(buf, static_cast<std::size_t>(n));
    }
    return true;
  }
  std::optional<int> wait(std::chrono::milliseconds timeout) {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < until) {
      shows("\x01never", 50ms);  // keep the terminal drained
      int st = 0;
      if (waitpid(pid_, &st, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
      }
    }
    return std::nullopt;
  }
  const std::string& screen() const { return screen_; }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  bool exited_ = false;
  std::string screen_;
};

}  // namespace

TEST_CASE("README tour steps 1-6 and 8: telnet, messjog, messcap, messmon, the queue, the outputs", "[long]") {
  DaemonProcess messd(as_scripts_run_in_loop_time());  // step 1
  // Step 2: telnet. Help, a touch of the top, Replay, Status, Get, GoTo, Stats.
  LineClient telnet(messd.port());
  telnet_touches_the_top(telnet);
  CHECK(saw(telnet, "Control client1 127.0.0.1"));
  CHECK(saw(telnet, "Hit 1 0 430.0000 330.0000 80.0000 0.000000 0.000000 -1.000000 2.0000 "));
  CHECK(saw(telnet, "MeasPt 430.000 330.000 80.000"));
  CHECK(telnet.request("Help") == std::optional<std::string>("Ok Help"));
  CHECK(telnet.request("Replay 1") == std::optional<std::string>("Ok Replay 1 1"));
  const auto status = telnet.request("Status");  // idle, or free once the loops opened (IdleOpen 7 s)
  CHECK((begins(status, "Ok Status State idle") || begins(status, "Ok Status State free")));
  CHECK(begins(telnet.request("Get"), "Ok Get TipRadius"));
  REQUIRE(telnet.request("GoTo 460 350 120") == std::optional<std::string>("Ok GoTo"));
  REQUIRE(telnet.until_prefix("State idle", 10.0));
  CHECK(begins(telnet.request("Stats"), "Ok Stats Period"));

  // Step 3: messjog, in a terminal of 60 columns, telnet left open.
  turn_to_the_next_program();
  {
    PtyProcess jog({client_binary("messjog"), at(messd)}, 60, 30);
    REQUIRE(jog.shows("connected"));
    jog.keys("d");  // +X at 20 %
    CHECK(telnet.until_prefix("Control messjog 127.0.0.1", 5.0));
    CHECK(telnet.until_prefix("State jog", 5.0));
    jog.keys(" ");  // Space stops
    CHECK(telnet.until_prefix("State idle", 5.0));
    // Enter is the inspection software's key: refused with a long message, read whole at 60 columns.
    jog.keys("\r");
    CHECK(jog.shows("keys go to it only then"));
    CHECK(jog.screen().find("Err 209") == std::string::npos);
    jog.keys("q");
    CHECK(jog.wait(5s) == std::optional<int>(0));
  }
  REQUIRE(telnet.until_prefix("Control none", 5.0));

  // Step 4: messcap waits for three points; telnet measures them here.
  TempDir dir;
  {
    ChildProcess cap({client_binary("messcap"), at(messd), "-n", "3", "-o", dir.file("pts.csv")});
    std::this_thread::sleep_for(500ms);
    for (int i = 0; i < 3; ++i) REQUIRE(telnet.request("ForcePt") == std::optional<std::string>("Ok ForcePt"));
    REQUIRE(cap.wait(10s) == std::optional<int>(0));
    std::ifstream csv(dir.file("pts.csv"));
    int rows = 0;
    for (std::string l; std::getline(csv, l);)
      if (!l.empty() && (std::isdigit(static_cast<unsigned char>(l[0])) || l[0] == '-')) ++rows;
    CHECK(rows == 3);
  }

  // Step 5: messmon shows the wire.
  {
    ChildProcess mon({client_binary("messmon"), at(messd)});
    CHECK(mon.wait_for_output("CurrCor", 5s));
    mon.signal(SIGINT);
    CHECK(mon.wait(5s) == std::optional<int>(0));
  }

  // Step 6: a queued path in telnet; StopMv fails what is queued, in queue order.
  for (const char* line : {"MoveTo 1 X400 Y300 F50", "ArcTo 2 CW X450 Y300 I25", "Dwell 3 0.5", "MoveTo 4 X430 Y330"}) {
    INFO(line);
    const auto r = telnet.request(line);
    REQUIRE(r);
    CHECK(r->rfind("Ok ", 0) == 0);
  }
  const auto queued = telnet.until([](const std::string& l) { return l.rfind("Done 4", 0) == 0 || l.rfind("Failed ", 0) == 0; }, 30.0);
  CHECK(queued == std::optional<std::string>("Done 4"));
  REQUIRE(telnet.until_prefix("State idle", 5.0));
  for (const char* line : {"MoveTo 5 X400 Y300 F20", "MoveTo 6 X400 Y380", "MoveTo 7 X500 Y380"})
    REQUIRE(telnet.request(line) == std::optional<std::string>("Ok MoveTo"));
  std::this_thread::sleep_for(300ms);
  CHECK(telnet.request("StopMv") == std::optional<std::string>("Ok StopMv"));
  std::vector<std::string> failed;
  REQUIRE(telnet.until(
      [&](const std::string& l) {
        if (l.rfind("Failed ", 0) == 0) failed.push_back(l.substr(0, 8));
        return failed.size() == 3;
      },
      5.0));
  CHECK(failed == std::vector<std::string>{"Failed 5", "Failed 6", "Failed 7"});
  REQUIRE(telnet.until_prefix("State idle", 5.0));

  // Step 8: the probe's power.
  CHECK(begins(telnet.request("Outputs"), "Ok Outputs probe on"));
  REQUIRE(telnet.request("SetOut 1 probe off") == std::optional<std::string>("Ok SetOut"));
  CHECK(telnet.until_prefix("Done 1", 5.0));
  REQUIRE(telnet.request("Probe 8 Z100") == std::optional<std::string>("Ok Probe"));
  CHECK(telnet.until_prefix("Failed 8 ProbeOff", 5.0));
  REQUIRE(telnet.until_prefix("State idle", 5.0));
  REQUIRE(telnet.request("SetOut 2 probe on") == std::optional<std::string>("Ok SetOut"));
  CHECK(telnet.until_prefix("Done 2", 5.0));
}

TEST_CASE("README tour step 7: measure_cube.py and Align by hand, with telnet open", "[long]") {
  DaemonProcess messd(as_scripts_run_in_loop_time());
  LineClient telnet(messd.port());
  telnet_touches_the_top(telnet);
  turn_to_the_next_program();
  const auto run = run_program({"/usr/bin/python3", kSource + "/examples/cube/measure_cube.py", at(messd), "--messcap",
                                client_binary("messcap")},
                               200s);
  INFO(run.out << run.err);
  REQUIRE(run.status == 0);
  // Each figure with its unit and four decimals (0.1 um, 0.0001 deg), the part's within 1 um.
  const std::vector<std::tuple<std::string, double, std::string>> rows{
      {"length", 120, "mm"},          {"width", 100, "mm"},       {"height", 80, "mm"},
      {"bore diameter", 30, "mm"},    {"bore centre", 460, "mm"}, {"bore axis tilt", 0, "deg"},
      {"turn about z", 0.3, "deg"},   {"fillet radius", 10, "mm"}};
  for (const auto& [label, nominal, unit] : rows) {
    INFO(label);
    std::smatch m;
    REQUIRE(std::regex_search(run.out, m, std::regex("(^|\n)" + label + " +(-?\\d+\\.\\d{4})( -?\\d+\\.\\d{4})* " + unit + "\n")));
    CHECK(std::stod(m[2]) == Approx(nominal).margin(0.001));
  }
  CHECK(std::regex_search(run.out, std::regex("(^|\n)points +25\n")));
  CHECK(run.out.find("e-") == std::string::npos);

  // Align by hand: the top three times, the front twice, the left face once, then `last`.
  CHECK(telnet.until_prefix("Control none", 5.0));  // the script has gone
  // (Probe targets where the ball's centre meets each face: the script left SearchDist at 1.5 mm.)
  const std::vector<std::string> probing{
      "MoveTo 1 X430 Y330 Z100", "Probe 2 Z82",  "MoveTo 3 Z100",  "MoveTo 4 X500 Y330", "Probe 5 Z82",
      "MoveTo 6 Z100",           "MoveTo 7 X460 Y390", "Probe 8 Z82", "MoveTo 9 Z100",  "MoveTo 10 X420 Y280",
      "MoveTo 11 Z40",           "Probe 12 Y298", "MoveTo 13 Y280", "MoveTo 14 X500", "Probe 15 Y298",
      "MoveTo 16 Y280",          "MoveTo 17 Z100", "MoveTo 18 X380 Y350", "MoveTo 19 Z40", "Probe 20 X398",
      "MoveTo 21 X380",          "MoveTo 22 Z100"};
  for (const auto& line : probing) REQUIRE(begins(telnet.request(line), "Ok "));
  const auto end = telnet.until([](const std::string& l) { return l.rfind("Done 22", 0) == 0 || l.rfind("Failed ", 0) == 0; }, 90.0);
  REQUIRE(end == std::optional<std::string>("Done 22"));
  const auto align = telnet.request("Align cube 321 last");
  REQUIRE(align);
  INFO(*align);
  CHECK(std::regex_search(*align, std::regex(R"(^Ok Align cube Origin 400\.26\d\d 299\.68\d\d 80\.0000 .* Hits \d+-\d+ \d+,\d+ \d+$)")));
}

TEST_CASE("README tour step 7: messcap inspect, with telnet open", "[long]") {
  DaemonProcess messd(as_scripts_run_in_loop_time());
  LineClient telnet(messd.port());
  telnet_touches_the_top(telnet);
  turn_to_the_next_program();
  TempDir dir;
  const auto inspect = run_program({client_binary("messcap"), "inspect", kSource + "/examples/cube-1996.plan.json", at(messd),
                                    "--html", dir.file("cube.html"), "--json", dir.file("cube.json")},
                                   240s);
  INFO(inspect.out << inspect.err);
  REQUIRE(inspect.status == 0);
  CHECK(inspect.out.find("13 characteristics: 13 in tolerance, 0 out of tolerance") != std::string::npos);
  CHECK(telnet.until_prefix("Inspected ", 5.0) == std::optional<std::string>("Inspected cube-1996 13 0 pass"));
  CHECK(telnet.request("Frames") == std::optional<std::string>("Ok Frames Active cube-1996 Names machine cube-1996"));
}

TEST_CASE("README tour step 7: messcap qualify, with telnet open", "[long]") {
  DaemonProcess messd(as_scripts_run_in_loop_time());
  LineClient telnet(messd.port());
  telnet_touches_the_top(telnet);
  turn_to_the_next_program();
  TempDir dir;
  const auto qualify = run_program({client_binary("messcap"), "qualify", at(messd), "--sphere", "750,650,60", "--diameter",
                                    "25", "--rc", dir.file("stylus.rc")},
                                   120s);
  INFO(qualify.out << qualify.err);
  CHECK(qualify.status == 0);
  CHECK(telnet.until_prefix("Qualified TipRadius", 5.0));
}

TEST_CASE("README tour steps 9-10: a program in telnet, messprog run, an I++ DME session, with telnet open", "[long]") {
  {
    DaemonProcess messd(as_scripts_run_in_loop_time());
    LineClient telnet(messd.port());
    telnet_touches_the_top(telnet);
    const auto programs = telnet.request("Programs");
    REQUIRE(programs);
    CHECK(programs->find("bore-inspection.ngc") != std::string::npos);
    const auto load = telnet.request("Load bore-inspection.ngc");
    REQUIRE(load);
    CHECK(std::regex_search(*load, std::regex("^Ok Load bore-inspection.ngc .*Segments 20 Length .* Time ")));
    REQUIRE(telnet.request("Run") == std::optional<std::string>("Ok Run bore-inspection.ngc"));
    int hits = 0;
    const auto end = telnet.until(
        [&](const std::string& l) {
          if (l.rfind("Hit ", 0) == 0) ++hits;
          return l.rfind("ProgEnd ", 0) == 0;
        },
        90.0);
    REQUIRE(end);
    CHECK(end->rfind("ProgEnd bore-inspection.ngc ok", 0) == 0);
    CHECK(hits == 8);

    // Step 10: messipp, typed line by line (a pipe stands for the keyboard).
    turn_to_the_next_program();
    TempDir dir;
    const std::string keyboard = dir.file("keyboard");
    REQUIRE(mkfifo(keyboard.c_str(), 0600) == 0);
    ChildProcess ipp({client_binary("messipp"), "127.0.0.1:" + std::to_string(messd.ipp_port())}, keyboard);
    const int typing = open(keyboard.c_str(), O_WRONLY);
    REQUIRE(typing >= 0);
    auto type = [&](const std::string& line) { (void)!write(typing, (line + "\n").data(), line.size() + 1); };
    type("StartSession()");
    CHECK(telnet.until_prefix("Control ippdme 127.0.0.1", 5.0));
    type("GoTo(X(460), Y(350), Z(100))");
    type("GoTo(Z(40))");
    type("PtMeas(X(475), Y(350), Z(40), IJK(-1, 0, 0))");
    CHECK(ipp.wait_for_output("# X(475.0000)", 30s));
    CHECK(saw(telnet, "Hit ") );
    CHECK(begins(telnet.request("GoTo 460 350 120"), "Err 209 "));  // the session holds the machine
    // EnableUser: the jog panel takes the machine, the operator's key comes from telnet.
    type("EnableUser()");
    CHECK(telnet.until_prefix("Control none", 5.0));
    LineClient panel(messd.port());
    REQUIRE(begins(panel.request("Hello messjog"), "Ok Hello"));
    REQUIRE(panel.request("StartMv 0 0 20") == std::optional<std::string>("Ok StartMv"));
    REQUIRE(panel.request("StopMv") == std::optional<std::string>("Ok StopMv"));
    CHECK(telnet.request("Key Done") == std::optional<std::string>("Ok Key"));
    CHECK(ipp.wait_for_output("E0000 # KeyPress(\"Done\")", 5s));
    type("EndSession()");
    close(typing);
    CHECK(ipp.wait(10s).has_value());
  }
  {  // messprog run on the 3D-Step machine, telnet open there too (its port space a file of its
     // own: another test may run messd on the shipped file at the same time).
    const std::string config = private_port_config(kSource + "/config/sim-parport-3dstep.json");
    DaemonProcess messd(as_scripts_run({"--config", config}));
    LineClient telnet(messd.port());
    REQUIRE(telnet.next());
    REQUIRE(telnet.request("ForcePt") == std::optional<std::string>("Ok ForcePt"));  // takes control
    turn_to_the_next_program();
    const auto run = run_program({client_binary("messprog"), "run", kSource + "/examples/programs/pocket-helix.ngc", at(messd)},
                                 150s);
    INFO(run.out << run.err);
    CHECK(run.status == 0);
    CHECK(run.err.find("Err 209") == std::string::npos);
    std::filesystem::remove(config);
  }
}
