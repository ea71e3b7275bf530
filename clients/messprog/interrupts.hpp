// Ctrl-C and SIGTERM for messprog run: each SIGINT is counted, so every press is handled
// (pause, then abort); the handlers only count. They are installed with SA_RESTART, so an
// interrupted write to the terminal goes on instead of failing; a waiting poll() returns
// at once all the same (poll is never restarted).
#pragma once

namespace imess::messprog {

void install_interrupts();
// SIGINTs since the last call (0 when none).
int take_interrupts() noexcept;
bool terminate_requested() noexcept;  // SIGTERM came

}  // namespace imess::messprog
