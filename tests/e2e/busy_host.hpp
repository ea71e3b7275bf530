// A busy host for the stall tests (issue 27, section 3): CPU-bound processes beside messd,
// messd itself stopped for a while once a second (SIGSTOP / SIGCONT: a stalled VM, a swapping
// host), a watcher that keeps every Fault, Warn and Failed line, and the workload that must run
// through it all: 20 probe cycles, a G-code program and the cube inspection.
#pragma once
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "daemon_process.hpp"

namespace imess::test::busy_host {

using namespace std::chrono_literals;


// n processes that only compute, until destroyed.
class Hogs {
 public:
  explicit Hogs(int n) {
    for (int i = 0; i < n; ++i) {
      const pid_t pid = fork();
      REQUIRE(pid >= 0);
      if (pid == 0) {
        (void)setpriority(PRIO_PROCESS, 0, 19);
        volatile unsigned long x = 0;
        for (;;) x = x + 1;
      }
      pids_.push_back(pid);
    }
  }
  ~Hogs() {
    for (pid_t p : pids_) {
      kill(p, SIGKILL);
      waitpid(p, nullptr, 0);
    }
  }

 private:
  std::vector<pid_t> pids_;
};

// Stops `pid` for `stop` once every `every`, until destroyed; counts the stops.
class Stopper {
 public:
  Stopper(pid_t pid, std::chrono::milliseconds stop, std::chrono::milliseconds every)
      : thread_([=, this] {
          while (!done_) {
            for (auto until = std::chrono::steady_clock::now() + every; !done_ && std::chrono::steady_clock::now() < until;)
              std::this_thread::sleep_for(10ms);
            if (done_) break;
            kill(pid, SIGSTOP);
            std::this_thread::sleep_for(stop);
            kill(pid, SIGCONT);
            ++stops_;
          }
        }) {}
  ~Stopper() {
    done_ = true;
    thread_.join();
  }
  int stops() const { return stops_; }

 private:
  std::atomic<bool> done_{false};
  std::atomic<int> stops_{0};
  std::thread thread_;
};

// Reads every line messd sends an observer, keeping the faults, warnings and failures.
class Watcher {
 public:
  explicit Watcher(int port)
      : client_(port), thread_([this] {
          while (!done_) {
            auto l = client_.next(0.1);
            if (!l) continue;
            if (l->rfind("Fault ", 0) == 0 || l->rfind("Warn ", 0) == 0 || l->rfind("Failed ", 0) == 0) {
              std::lock_guard lock(mutex_);
              bad_.push_back(*l);
            }
          }
        }) {}
  ~Watcher() {
    done_ = true;
    thread_.join();
  }
  std::vector<std::string> bad() {
    std::lock_guard lock(mutex_);
    return bad_;
  }

 private:
  LineClient client_;
  std::atomic<bool> done_{false};
  std::mutex mutex_;
  std::vector<std::string> bad_;
  std::thread thread_;
};

inline std::string done_or_not(LineClient& c, int id, double timeout_s) {
  const std::string done = "Done " + std::to_string(id);
  const auto end = c.until(
      [&](const std::string& l) { return l == done || l.rfind("Failed ", 0) == 0 || l.rfind("Err ", 0) == 0 || l.rfind("Fault ", 0) == 0; },
      timeout_s);
  if (!end) return "nothing in time";
  if (end->rfind("Failed ", 0) == 0)  // the fault behind it, if one came, for the report
    if (const auto fault = c.until_prefix("Fault ", 0.5)) return *end + " (" + *fault + ")";
  return *end;
}

// The workload of the stall tests on messd at `port`, with messd (`pid`) stopped for 30 ms once
// a second beside two CPU-bound processes (nice 19, so the suite beside keeps its pace). Every
// step must end as it does on a quiet host, and no Fault, Warn or Failed line may come. The
// cube inspection (a minute) only when `inspection`.
inline void run_through_stalls(int port, pid_t pid, const char* what, bool inspection) {
  Watcher watch(port);
  Hogs hogs(2);
  Stopper stopper(pid, 30ms, 1000ms);
  const auto t0 = std::chrono::steady_clock::now();

  {  // 20 probe cycles on the cube's top face (z = 80; the ball touches at 82), each from above
    LineClient c(port);
    int id = 1;
    for (int i = 0; i < 20; ++i) {
      const double x = 420 + 4.0 * (i % 5), y = 320 + 5.0 * (i / 5);
      c.send("MoveTo " + std::to_string(id++) + " X" + std::to_string(x) + " Y" + std::to_string(y) + " Z100");
      c.send("Probe " + std::to_string(id) + " Z81 F20");  // the ball touches at 82
      const std::string end = done_or_not(c, id, 30);
      INFO("probe cycle " << i << ":\n" << c.raw());
      REQUIRE(end == "Done " + std::to_string(id));
      ++id;
    }
    c.send("MoveTo " + std::to_string(id) + " Z100");
    REQUIRE(done_or_not(c, id, 30) == "Done " + std::to_string(id));
  }
  {  // a G-code program: a rectangle with rounded corners above the cube, at feed
    LineClient c(port);
    REQUIRE(c.request("Upload stalls.ngc") == std::optional<std::string>("Ok Upload stalls.ngc send the lines, then a line '.'"));
    for (const char* line : {"G21 G90 G17", "G0 X420 Y320 Z100", "G1 X480 F3000", "G3 X490 Y330 R10", "G1 Y370",
                             "G3 X480 Y380 R10", "G1 X420", "G3 X410 Y370 R10", "G1 Y330", "G3 X420 Y320 R10", "G0 Z110", "M2"})
      c.send(line);
    const auto load = c.request(".");
    REQUIRE(load);
    REQUIRE(load->rfind("Ok Load stalls.ngc", 0) == 0);
    REQUIRE(c.request("Run") == std::optional<std::string>("Ok Run stalls.ngc"));
    const auto end = c.until_prefix("ProgEnd ", 60);
    INFO(c.raw());
    REQUIRE(end);
    CHECK(end->rfind("ProgEnd stalls.ngc ok", 0) == 0);
  }
  if (inspection) {  // the cube inspection, as an inspector runs it
    TempDir dir;
    const auto run = run_program({client_binary("messcap"), "inspect", std::string(IMESS_SOURCE_DIR) + "/examples/cube-1996.plan.json",
                                  "127.0.0.1:" + std::to_string(port), "--feed", "300", "--json", dir.file("cube.json")},
                                 240s);
    INFO("stdout:\n" << run.out << "\nstderr:\n" << run.err);
    REQUIRE(run.status == 0);
    CHECK(run.out.find("13 characteristics: 13 in tolerance, 0 out of tolerance") != std::string::npos);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  LineClient c(port);
  const auto stats = c.request("Stats");
  std::printf("%s: %d stops of 30 ms in %.0f s beside 2 CPU hogs; %s\n", what, stopper.stops(), seconds,
              stats ? stats->c_str() : "no Stats");
  CHECK(stopper.stops() >= (inspection ? 60 : 15));
  const auto bad = watch.bad();
  for (const auto& l : bad) INFO(l);
  CHECK(bad.empty());
}

}  // namespace imess::test::busy_host
