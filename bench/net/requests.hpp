// Request and reply over a ClientPool: send a command from one client and serve every
// client until that one's reply (its first "Ok …" or "Err …" line) arrives.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "client_pool.hpp"

namespace imess::bench {

struct Reply {
  std::string line;
  std::int64_t sent_ns = 0, arrived_ns = 0;
  bool ok() const { return line.rfind("Ok", 0) == 0; }
};

// The reply, or nullopt when none came within timeout_s (or the client was closed). Lines of
// every client still go to the pool's handler meanwhile.
std::optional<Reply> request(ClientPool& pool, int client, const std::string& line, double timeout_s = 5.0);
// The reply, which must be Ok: throws std::runtime_error quoting the command and what came.
Reply request_ok(ClientPool& pool, int client, const std::string& line, double timeout_s = 5.0);

// Sends `line` from `client`, which must be answered Ok (else std::runtime_error), and serves
// until that client also received a line starting with `until` after the send (a "State
// idle", a "Done 7"); false when it did not within timeout_s.
bool request_until(ClientPool& pool, int client, const std::string& line, std::string_view until, double timeout_s = 10.0);

bool starts_with(std::string_view line, std::string_view prefix);
// The n-th blank-separated word of a line (0: the verb), empty when there is none.
std::string_view word(std::string_view line, int n);
// The value after `name` in a line of name-value pairs ("Ok Status State idle Pos 1 2 3 …").
std::string_view value_after(std::string_view line, std::string_view name);

}  // namespace imess::bench
