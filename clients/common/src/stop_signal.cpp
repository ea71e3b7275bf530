// The one stop flag of a client process.
#include "imess/client/stop_signal.hpp"

namespace imess::client {
namespace {
volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_stop_signal(int) { g_stop = 1; }
}  // namespace

void install_stop_signals(std::initializer_list<int> signals) {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  for (int s : signals) sigaction(s, &sa, nullptr);
}

bool stop_requested() noexcept { return g_stop != 0; }

}  // namespace imess::client
