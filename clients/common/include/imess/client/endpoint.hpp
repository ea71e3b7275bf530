// Endpoint: the HOST[:PORT] a client connects to (default port 1066, IPv6 as [::1]:1066).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace imess::client {

inline constexpr std::uint16_t kDefaultPort = 1066;

struct Endpoint {
  std::string host = "localhost";
  std::uint16_t port = kDefaultPort;

  // "host:port", with brackets around an IPv6 literal ("[::1]:1066").
  std::string to_string() const;
  friend bool operator==(const Endpoint&, const Endpoint&) = default;
};

// Parses "HOST", "HOST:PORT", ":PORT", "[V6]" or "[V6]:PORT"; what the text leaves out (the
// port, or the host of ":PORT") comes from `defaults` — messd's 1066 unless a client talks to
// another of its ports (messipp: I++ DME on 1294). Throws UsageError naming the text and the
// accepted forms when it is malformed (empty host, port not 1..65535, ...).
Endpoint parse_endpoint(std::string_view text, const Endpoint& defaults = {});

// The one positional HOST[:PORT] argument of a client's command line: the first sets
// endpoint (its value so far gives the defaults) and seen; a second throws UsageError.
void take_host_argument(std::string_view arg, Endpoint& endpoint, bool& seen);

}  // namespace imess::client
