// UsageError: a bad command-line argument; the message says what was wrong and what is accepted.
// Exit codes shared by every client, documented in docs/clients.md.
#pragma once
#include <stdexcept>

namespace imess::client {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;     // messd unreachable, file or I/O error
inline constexpr int kExitUsage = 2;       // bad arguments
inline constexpr int kExitIncomplete = 3;  // messcap: stopped before N points arrived
inline constexpr int kExitLinkLost = 4;    // messcap: messd went away (without --reconnect)

}  // namespace imess::client
