// Stop requests by signal for the clients' poll loops: the handler only sets a flag, and is
// installed without SA_RESTART so a waiting poll() returns at once.
#pragma once
#include <csignal>
#include <initializer_list>

namespace imess::client {

void install_stop_signals(std::initializer_list<int> signals = {SIGINT, SIGTERM});
bool stop_requested() noexcept;

}  // namespace imess::client
