// messcard: the emulated servo card as a separate program, on a pseudo-terminal (or a tty)
// in real time — what messd's "servo-card" backend talks to when there is no card.
#include <sched.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <iostream>

#include "config.hpp"
#include "imess/hal/serial_line.hpp"
#include "options.hpp"
#include "pty.hpp"
#include "wall_card.hpp"

using namespace imess;

namespace {
constexpr int kPriority = 75;  // SCHED_FIFO: below messd's motion loop (80) and its link thread (82)
std::atomic<bool> g_stop{false};
std::atomic<bool> g_stall{false}, g_faults{false};
void on_stop(int) { g_stop = true; }
void on_stall(int) { g_stall = true; }
void on_faults(int) { g_faults = true; }

// The machine and the line's rate from the configuration's "sim" section and its backend.
app::DaemonConfig load(const messcard::Options& o) {
  app::DaemonConfig cfg;
  app::load_json_config(o.config, cfg);
  app::finish_config(cfg);
  return cfg;
}
}  // namespace

int main(int argc, char** argv) {
  messcard::Options o;
  try {
    o = messcard::parse_options(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "messcard: " << e.what() << "\n" << messcard::usage_text();
    return 2;
  }
  if (o.help) {
    std::cout << messcard::usage_text();
    return 0;
  }
  app::DaemonConfig cfg;
  try {
    cfg = load(o);
  } catch (const std::exception& e) {
    std::cerr << "messcard: " << e.what() << "\n";
    return 2;
  }
  const int baud = o.baud ? *o.baud : cfg.backend == "servo-card" ? cfg.card_line.baud : static_cast<int>(cfg.sim.line.baud);
  int fd = -1;
  std::string where;
  try {
    if (!o.pty.empty()) {
      fd = messcard::open_pty(o.pty).master;  // the slave stays open in this process
      where = o.pty;
    } else {
      fd = hal::open_serial_line(o.device, baud);
      where = o.device;
    }
  } catch (const std::exception& e) {
    std::cerr << "messcard: " << e.what() << "\n";
    return 1;
  }
  struct sigaction sa {};
  sa.sa_handler = on_stop;
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
  sa.sa_handler = on_stall;
  sigaction(SIGUSR1, &sa, nullptr);
  sa.sa_handler = on_faults;
  sigaction(SIGUSR2, &sa, nullptr);
  signal(SIGPIPE, SIG_IGN);

  std::string scheduling = "time-shared";
  if (o.realtime) {
    sched_param p{};
    p.sched_priority = kPriority;
    if (sched_setscheduler(0, SCHED_FIFO, &p) == 0) scheduling = "SCHED_FIFO " + std::to_string(kPriority);
  }
  messcard::Faults faults{o.drop, o.corrupt, o.faults_at_ms / 1e3, o.stall_ms / 1e3, o.stall_at_ms / 1e3, o.seed};
  messcard::WallCard card(cfg.sim, fd, baud, faults);
  std::printf("messcard: card on %s (%d baud)\n", where.c_str(), baud);
  std::printf("messcard: firmware at 10 kHz on the steady clock, %s\n", scheduling.c_str());
  std::fflush(stdout);
  card.run([&] {
    if (g_stall.exchange(false)) card.stall_now();
    if (g_faults.exchange(false)) card.faults_now();
    return g_stop.load();
  });
  if (!o.pty.empty()) ::unlink(o.pty.c_str());
  return 0;
}
