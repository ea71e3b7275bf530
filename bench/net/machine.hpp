// The owner's moves on the simulated machine that the figures need, made robust against the
// one fault a loaded host causes: without real-time scheduling a starved motion loop lets the
// simulated card's link time out (Fault CommLost); Reset clears it and the move is tried again.
#pragma once
#include <string>

#include "client_pool.hpp"

namespace imess::bench {

// Moves with `MoveTo <id> <words>` and waits for State idle; after a fault or a refusal it sends
// Reset and tries again, up to three times. Returns the number of faults met; throws
// std::runtime_error saying what came when the third try fails.
int move_to_rest(ClientPool& pool, int owner, std::uint32_t id, const std::string& words);

// Sends Reset and waits for its reply (Ok also when there was no fault).
void reset_fault(ClientPool& pool, int owner);

// The hint for errors after a fault.
inline const char* kFaultHint =
    " (a loaded host starves messd's motion loop without real-time scheduling: Fault CommLost; try --rt)";

}  // namespace imess::bench
