// HOST[:PORT] parsing and printing.
#include "imess/client/endpoint.hpp"

#include <charconv>

#include "imess/client/usage_error.hpp"

namespace imess::client {
namespace {

// The accepted forms, with the examples' port the client's default.
[[noreturn]] void reject(std::string_view text, std::string_view what, std::uint16_t default_port) {
  const std::string p = std::to_string(default_port);
  throw UsageError("bad address '" + std::string(text) + "': " + std::string(what) +
                   "; expected HOST[:PORT] with PORT 1..65535, e.g. localhost, localhost:" + p +
                   ", 192.168.0.5:" + p + " or [::1]:" + p);
}

std::uint16_t parse_port(std::string_view all, std::string_view port, std::uint16_t default_port) {
  if (port.empty()) reject(all, "the port after ':' is missing", default_port);
  unsigned value = 0;
  auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (ec != std::errc{} || end != port.data() + port.size() || value == 0 || value > 65535)
    reject(all, "port '" + std::string(port) + "' is not a number 1..65535", default_port);
  return static_cast<std::uint16_t>(value);
}

bool has_blank(std::string_view s) { return s.find_first_of(" \t\r\n") != std::string_view::npos; }

}  // namespace

std::string Endpoint::to_string() const {
  bool v6 = host.find(':') != std::string::npos;
  return (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

Endpoint parse_endpoint(std::string_view text, const Endpoint& defaults) {
  const std::uint16_t dp = defaults.port;
  if (text.empty()) reject(text, "it is empty", dp);
  if (has_blank(text)) reject(text, "it contains blanks", dp);
  Endpoint e = defaults;
  if (text.front() == '[') {  // [v6] or [v6]:port
    auto close = text.find(']');
    if (close == std::string_view::npos) reject(text, "'[' without a closing ']'", dp);
    e.host = std::string(text.substr(1, close - 1));
    if (e.host.empty()) reject(text, "the host inside [] is empty", dp);
    auto rest = text.substr(close + 1);
    if (!rest.empty()) {
      if (rest.front() != ':') reject(text, "expected ':' after ']'", dp);
      e.port = parse_port(text, rest.substr(1), dp);
    }
    return e;
  }
  auto first = text.find(':');
  if (first == std::string_view::npos) {
    e.host = std::string(text);
    return e;
  }
  if (text.find(':', first + 1) != std::string_view::npos) {  // bare IPv6 literal, no port
    e.host = std::string(text);
    return e;
  }
  if (first > 0) e.host = std::string(text.substr(0, first));  // ":1066": the default host
  e.port = parse_port(text, text.substr(first + 1), dp);
  return e;
}

void take_host_argument(std::string_view arg, Endpoint& endpoint, bool& seen) {
  if (seen) throw UsageError("unexpected argument '" + std::string(arg) + "'; expected a single HOST[:PORT]");
  endpoint = parse_endpoint(arg, endpoint);
  seen = true;
}

}  // namespace imess::client
