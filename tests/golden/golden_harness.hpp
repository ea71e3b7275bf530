// GoldenHarness: replays a transcript's inputs against messd's own parts — the machine of a
// configuration built as messd builds it, the motion core stepped by hand in virtual time,
// net::Server on an io_context that only the harness runs (poll, never a thread), clients on
// loopback TCP — and records what every client received. No real-time loop, no sleeping.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "transcript.hpp"

namespace imess::test {
class ConfigRig;
}

namespace imess::golden {

// The transcript as it comes out today: the inputs and comments of `script` in order, each
// followed by what messd sent (its observed entries are ignored). Throws std::runtime_error
// when the script cannot be run (no configuration, a client that does not exist, ...).
std::vector<Entry> replay(const std::vector<Entry>& script, const std::string& name);

// The same, and `inspect` sees the configuration's machine after the last entry (the
// simulated machine behind the backend: step counts, lost steps, outputs ...).
std::vector<Entry> replay(const std::vector<Entry>& script, const std::string& name,
                          const std::function<void(test::ConfigRig&)>& inspect);

}  // namespace imess::golden
