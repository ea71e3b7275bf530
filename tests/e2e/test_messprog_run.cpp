// messprog run against a real messd (fast-cmm.json: the built-in simulated CMM, brisk, in loop
// time), as a child process — with stdin not a terminal, and in a pseudo-terminal where
// Ctrl-C pauses and asks. A second connection watches the events and asks Status: a program
// that ends ok, one messd refuses (nothing moves), one whose G38.2 finds nothing, a detached
// run that outlives its killed messprog and a plain one that does not, M0, and a Pause
// followed by an abort that must not hold the next run. Every program takes a few seconds.
#include <catch2/catch.hpp>

#include <poll.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

#include "child_process.hpp"
#include "daemon_process.hpp"

using namespace imess::test;

namespace {

// Generous for a loaded 2-vCPU machine; the programs themselves take a few seconds.
constexpr double kProgramTimeout = 60;


std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  const auto path = dir.file(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::vector<std::string> messprog_run(const std::string& file, int port, bool detached = false) {
  std::vector<std::string> a{client_binary("messprog"), "run", file, "127.0.0.1:" + std::to_string(port)};
  if (detached) a.push_back("--detached");
  return a;
}

bool has_prefix(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The "Pos x y z" of an Ok Status line, as text (three decimals: what "nothing moved" compares).
std::string pos_of(const std::string& status) {
  const auto at = status.find(" Pos ");
  if (at == std::string::npos) return {};
  std::istringstream in(status.substr(at + 5));
  std::string x, y, z;
  in >> x >> y >> z;
  return x + " " + y + " " + z;
}

// Asks Status until the machine stands (State idle or free); that Status line.
std::string at_rest(LineClient& c, double timeout_s = kProgramTimeout) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  std::string last;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto s = c.request("Status", 10);
    if (s) last = *s;
    if (s && (s->find(" State idle ") != std::string::npos || s->find(" State free ") != std::string::npos)) return *s;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  FAIL("the machine did not come to rest: " << last);
  return last;
}

// The Pos of an Ok Status line is within 0.01 mm of (x, y, z) on every axis: a servo at rest
// stands within a few micrometres of its target.
bool near(const std::string& status, double x, double y, double z) {
  std::istringstream in(pos_of(status));
  double p[3] = {};
  if (!(in >> p[0] >> p[1] >> p[2])) return false;
  return std::abs(p[0] - x) < 0.01 && std::abs(p[1] - y) < 0.01 && std::abs(p[2] - z) < 0.01;
}

// The machine at rest comes within 0.01 mm of (x, y, z) within `timeout_s`: the servo
// settles the last micrometres after the path's arrival (on a busy host it took longer than
// one Status round trip: 329.988 for 330). Returns the last Status seen.
std::string settles_near(LineClient& c, double x, double y, double z, double timeout_s = 3) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  std::string last = at_rest(c);
  while (!near(last, x, y, z) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (const auto s = c.request("Status", 10)) last = *s;
  }
  return last;
}

// Asks Queue until it says Held yes (the loop takes a Pause within a cycle or two).
bool held_soon(LineClient& c, double timeout_s = 10) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    const auto q = c.request("Queue", 10);
    if (q && q->size() >= 9 && q->compare(q->size() - 9, 9, " Held yes") == 0) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

bool seen_prefix(const LineClient& c, const std::string& prefix) {
  for (const auto& l : c.seen())
    if (has_prefix(l, prefix)) return true;
  return false;
}

// messprog in a pseudo-terminal (default settings): its stdin and stdout are a terminal, so
// Ctrl-C (a 0x03 byte written to the master: the line discipline sends SIGINT) pauses and
// asks. Typed the moment messprog says it runs, the SIGINT often lands while messprog writes
// its progress line — the case that once silenced it (interrupts.cpp, SA_RESTART).
class PtyProcess {
 public:
  explicit PtyProcess(std::vector<std::string> argv) {
    pid_ = forkpty(&fd_, nullptr, nullptr, nullptr);
    if (pid_ < 0) throw std::runtime_error("forkpty failed");
    if (pid_ == 0) {
      std::vector<char*> args;
      for (auto& a : argv) args.push_back(a.data());
      args.push_back(nullptr);
      execv(args[0], args.data());
      _exit(127);
    }
  }
  ~PtyProcess() {
    if (!status_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    close(fd_);
  }
  PtyProcess(const PtyProcess&) = delete;
  PtyProcess& operator=(const PtyProcess&) = delete;

  void type(const std::string& keys) {
    if (::write(fd_, keys.data(), keys.size()) != static_cast<ssize_t>(keys.size())) throw std::runtime_error("pty write");
  }
  // Waits until `text` appears after what an earlier wait_for matched; false on timeout or end
  // (and then the terminal's text so far goes with the failure).
  bool wait_for(const std::string& text, double timeout_s = kProgramTimeout) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    for (;;) {
      if (auto at = out_.find(text, mark_); at != std::string::npos) {
        mark_ = at + text.size();
        return true;
      }
      if (std::chrono::steady_clock::now() >= deadline || !read_some(50)) {
        UNSCOPED_INFO("waited for '" << text << "'; the terminal showed:\n" << out_);
        return false;
      }
    }
  }
  // The exit status (reading the terminal to its end), or nullopt after the timeout.
  std::optional<int> wait(double timeout_s = kProgramTimeout) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (!status_ && std::chrono::steady_clock::now() < deadline) {
      read_some(20);
      int raw = 0;
      if (waitpid(pid_, &raw, WNOHANG) == pid_) status_ = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    }
    while (status_ && read_some(0)) {
    }
    return status_;
  }
  const std::string& out() const { return out_; }

 private:
  // false once the terminal is closed (the child ended and everything was read)
  bool read_some(int timeout_ms) {
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, timeout_ms) <= 0) return true;
    char buf[4096];
    const auto n = ::read(fd_, buf, sizeof buf);
    if (n <= 0) return false;  // EIO: the child side is gone
    out_.append(buf, static_cast<std::size_t>(n));
    return true;
  }

  pid_t pid_ = -1;
  int fd_ = -1;
  std::optional<int> status_;
  std::string out_;
  std::size_t mark_ = 0;
};

// From the built-in CMM's start (430, 330, 100), high above the cube (x 400..520, y 300..400,
// z 0..80): lines and an arc in the air, back to the start. About a second.
const std::string kSquare =
    "G21 G90 G17\n"
    "G0 X440 Y340 Z100\n"
    "G1 X450 F1200\n"
    "G3 X440 Y340 I-5 J0\n"
    "G1 Y345\n"
    "G0 X430 Y330 Z100\n"
    "M2\n";

// Four 15 mm feed moves at 10 mm/s, back to the start: about six seconds, long enough to be
// interrupted or killed in the middle.
const std::string kSlowSquare =
    "G21 G90\n"
    "G1 X445 F600\n"
    "G1 Y345\n"
    "G1 X430\n"
    "G1 Y330\n"
    "M2\n";

}  // namespace

TEST_CASE("messprog run on a real messd: a program ends ok (exit 0), the machine back at its end point") {
  DaemonProcess messd({"--config", fast_cmm()});
  LineClient watch(messd.port());
  const auto before = at_rest(watch);
  INFO(before);
  REQUIRE(near(before, 430, 330, 100));
  TempDir dir;
  const auto file = write(dir, "square.ngc", kSquare);
  ChildProcess p(messprog_run(file, messd.port()));
  const auto status = p.wait(std::chrono::seconds(static_cast<int>(kProgramTimeout)));
  INFO(p.out() << p.err());
  REQUIRE(status);
  CHECK(*status == 0);
  CHECK_THAT(p.out(), Catch::Contains("messprog: messd checked square.ngc: gcode, 7 lines, 6 blocks"));
  CHECK_THAT(p.out(), Catch::Contains("messprog: running square.ngc; Ctrl-C aborts"));
  CHECK_THAT(p.out(), Catch::Contains("messprog: square.ngc ended ok at line 7"));
  CHECK(p.err().empty());
  REQUIRE(watch.until_prefix("ProgEnd square.ngc", 10) == "ProgEnd square.ngc ok 7 end");
  CHECK(seen_prefix(watch, "Block square.ngc "));
  const auto after = settles_near(watch, 430, 330, 100);
  INFO(after);
  CHECK(near(after, 430, 330, 100));
  const auto program = watch.request("Program");
  REQUIRE(program);
  CHECK_THAT(*program, Catch::StartsWith("Ok Program square.ngc ended Line "));
}

TEST_CASE("messprog run on a real messd: a program messd refuses is exit 1 with FILE:LINE:COL, and nothing moves") {
  DaemonProcess messd({"--config", fast_cmm()});
  LineClient watch(messd.port());
  const auto before = at_rest(watch);
  TempDir dir;
  // A syntax error on line 3, and a move out of this machine's travel on line 2 (which only
  // messd, knowing the machine, can find).
  const auto syntax = write(dir, "syntax.ngc", "G21 G90\nG0 X440\nG1 X450 Y#3 F600\nM2\n");
  const auto travel = write(dir, "travel.ngc", "G21 G90\nG0 X5000\nM2\n");
  for (const auto& [file, where] : {std::pair{syntax, ":3:9: bad number"}, std::pair{travel, ":2:4: out of travel"}}) {
    const auto r = run_program(messprog_run(file, messd.port()), std::chrono::seconds(30));
    INFO(r.out << r.err);
    CHECK(r.status == 1);
    CHECK_THAT(r.err, Catch::Contains("(Err 213):\n" + file + where));
  }
  const auto after = at_rest(watch);
  CHECK(pos_of(after) == pos_of(before));
  watch.request("Quit", 1);
  for (const auto& l : watch.seen()) {
    INFO(l);
    CHECK_FALSE(has_prefix(l, "Block "));
    CHECK_FALSE(has_prefix(l, "State move"));
  }
}

TEST_CASE("messprog run on a real messd: a G38.2 that finds nothing fails the program — exit 1, the line shown") {
  DaemonProcess messd({"--config", fast_cmm()});
  LineClient watch(messd.port());
  at_rest(watch);
  TempDir dir;
  // At Z100 the probe moves through air: nothing up to SearchDist past X420.
  const auto file = write(dir, "miss.ngc", "G21 G90\nG0 X430 Y330 Z100\nG38.2 X420 F1200\nG0 X430\nM2\n");
  const auto r = run_program(messprog_run(file, messd.port()), std::chrono::seconds(static_cast<int>(kProgramTimeout)));
  INFO(r.out << r.err);
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("messprog: miss.ngc failed at line 3: Failed PartNotFound\n  3 | G38.2 X420 F1200\n"));
  CHECK(watch.until_prefix("ProgEnd miss.ngc", 10) == "ProgEnd miss.ngc failed 3 Failed PartNotFound");
  at_rest(watch);
}

TEST_CASE("messprog run --detached killed mid-run: the program goes on and ends ok — without --detached it is aborted") {
  DaemonProcess messd({"--config", fast_cmm()});
  LineClient watch(messd.port());
  at_rest(watch);
  TempDir dir;
  const auto file = write(dir, "slow.ngc", kSlowSquare);
  {
    ChildProcess p(messprog_run(file, messd.port(), true));
    REQUIRE(watch.until_prefix("Block slow.ngc 3 ", 30));
    REQUIRE(p.wait_for_output("messprog: running slow.ngc (detached)", std::chrono::seconds(30)));
    p.signal(SIGKILL);
    REQUIRE(p.wait(std::chrono::seconds(10)) == 128 + SIGKILL);
    // Control is free again, the program runs on; another messprog may not start one meanwhile.
    REQUIRE(watch.until_prefix("Control none", 10));
    const auto running = watch.request("Program");
    REQUIRE(running);
    CHECK_THAT(*running, Catch::StartsWith("Ok Program slow.ngc running Line "));
    const auto other = write(dir, "other.ngc", "G21 G90\nG0 X440\nM2\n");
    const auto r = run_program(messprog_run(other, messd.port()), std::chrono::seconds(30));
    CHECK(r.status == 1);
    CHECK_THAT(r.err, Catch::Contains("messprog: messd refused other.ngc: Err 202 Upload: program slow.ngc is running"));
    CHECK(watch.until_prefix("ProgEnd slow.ngc", kProgramTimeout) == "ProgEnd slow.ngc ok 6 end");
    const auto back = settles_near(watch, 430, 330, 100);
    INFO(back);
    CHECK(near(back, 430, 330, 100));
  }
  {
    ChildProcess p(messprog_run(file, messd.port()));
    REQUIRE(watch.until_prefix("Block slow.ngc 3 ", 30));
    REQUIRE(p.wait_for_output("messprog: running slow.ngc; Ctrl-C aborts", std::chrono::seconds(30)));
    p.signal(SIGKILL);
    REQUIRE(p.wait(std::chrono::seconds(10)) == 128 + SIGKILL);
    const auto end = watch.until_prefix("ProgEnd slow.ngc", kProgramTimeout);
    REQUIRE(end);
    CHECK_THAT(*end, Catch::StartsWith("ProgEnd slow.ngc aborted ") && Catch::EndsWith(" disconnected"));
    const auto rest = at_rest(watch);
    INFO(rest);
    CHECK_FALSE(near(rest, 430, 330, 100));  // stopped on the way
    const auto program = watch.request("Program");
    REQUIRE(program);
    CHECK_THAT(*program, Catch::StartsWith("Ok Program slow.ngc ended Line "));
  }
}

TEST_CASE("messprog run in a terminal: Ctrl-C pauses and asks — r resumes to the end (100%), a aborts — M0 asks too") {
  DaemonProcess messd({"--config", fast_cmm()});
  LineClient watch(messd.port());
  at_rest(watch);
  TempDir dir;
  const auto file = write(dir, "slow.ngc", kSlowSquare);
  SECTION("resume") {
    PtyProcess p(messprog_run(file, messd.port()));
    REQUIRE(p.wait_for("messprog: running slow.ngc; Ctrl-C pauses"));
    p.type("\x03");  // at once: the program has a few seconds to go
    REQUIRE(p.wait_for("messprog: abort or resume? [a/r] "));
    CHECK(held_soon(watch));  // the Pause the Ctrl-C sent holds the path
    p.type("r\n");
    REQUIRE(p.wait_for("messprog: Resume sent"));
    const auto status = p.wait();
    INFO(p.out());
    REQUIRE(status);
    CHECK(*status == 0);
    CHECK_THAT(p.out(), Catch::Contains("100%") && Catch::Contains("messprog: slow.ngc ended ok at line 6"));
    CHECK(watch.until_prefix("ProgEnd slow.ngc", 10) == "ProgEnd slow.ngc ok 6 end");
  }
  SECTION("abort, then the next run is not held") {
    {
      PtyProcess p(messprog_run(file, messd.port()));
      REQUIRE(p.wait_for("messprog: running slow.ngc; Ctrl-C pauses"));
      p.type("\x03");
      REQUIRE(p.wait_for("messprog: abort or resume? [a/r] "));
      p.type("a\n");
      const auto status = p.wait();
      INFO(p.out());
      REQUIRE(status);
      CHECK(*status == 1);
      CHECK_THAT(p.out(), Catch::Contains("messprog: Abort sent") && Catch::Contains("messprog: slow.ngc aborted at line ") &&
                              Catch::Contains(": Abort"));
      const auto end = watch.until_prefix("ProgEnd slow.ngc", 10);
      REQUIRE(end);
      CHECK_THAT(*end, Catch::StartsWith("ProgEnd slow.ngc aborted ") && Catch::EndsWith(" Abort"));
    }
    at_rest(watch);
    // The Pause of the Ctrl-C ended with the stop: the next program moves (an M0 in it asks).
    const auto queue = watch.request("Queue");
    REQUIRE(queue);
    CHECK_THAT(*queue, Catch::EndsWith(" Held no"));
    const auto m0 = write(dir, "m0.ngc", "G21 G90\nG0 X440 Y340 Z100\nM0\nG0 X430 Y330 Z100\nM2\n");
    PtyProcess p(messprog_run(m0, messd.port()));
    REQUIRE(p.wait_for("messprog: M0 at line 3: the machine waits", 30));
    REQUIRE(p.wait_for("messprog: abort or resume? [a/r] "));
    CHECK(watch.until_prefix("ProgPause m0.ngc", 10) == "ProgPause m0.ngc 3 M0");
    const auto waiting = watch.request("Status");
    REQUIRE(waiting);
    INFO(*waiting);
    CHECK(near(*waiting, 440, 340, 100));
    p.type("r\n");
    const auto status = p.wait();
    INFO(p.out());
    REQUIRE(status);
    CHECK(*status == 0);
    CHECK_THAT(p.out(), Catch::Contains("messprog: m0.ngc ended ok at line 5"));
  }
  at_rest(watch);
}
