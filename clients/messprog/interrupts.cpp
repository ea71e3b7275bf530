// Signal counters of messprog run.
#include "interrupts.hpp"

#include <csignal>

namespace imess::messprog {
namespace {
volatile std::sig_atomic_t g_interrupts = 0;
volatile std::sig_atomic_t g_terminate = 0;
int g_taken = 0;
extern "C" void on_interrupt(int) { g_interrupts = g_interrupts + 1; }
extern "C" void on_terminate(int) { g_terminate = 1; }

// SA_RESTART: a write to the terminal that the signal interrupts is restarted. Without it a
// Ctrl-C landing while the progress line was written failed that write with EINTR, which
// puts std::cout in its bad state for good: the question "abort or resume?" and all that
// followed was never shown, while messd held the program. poll() is never restarted
// (signal(7)), so the loop still wakes at once.
void install(int sig, void (*handler)(int)) {
  struct sigaction sa {};
  sa.sa_handler = handler;
  sa.sa_flags = SA_RESTART;
  sigemptyset(&sa.sa_mask);
  sigaction(sig, &sa, nullptr);
}
}  // namespace

void install_interrupts() {
  install(SIGINT, on_interrupt);
  install(SIGTERM, on_terminate);
}

int take_interrupts() noexcept {
  const int now = g_interrupts;
  const int fresh = now - g_taken;
  g_taken = now;
  return fresh;
}

bool terminate_requested() noexcept { return g_terminate != 0; }

}  // namespace imess::messprog
