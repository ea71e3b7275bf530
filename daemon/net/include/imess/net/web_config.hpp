// The web panel's server (docs/configuration.md, "server.http_port"; docs/web.md).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace imess::net {

struct WebConfig {
  // false: no HTTP listener. Off for a net::Server built in a test; messd turns it on
  // (app::DaemonConfig; http_port 0 turns it off there).
  bool on = false;
  std::uint16_t port = 8080;    // 0 with on: any free port (tests)
  std::string root;             // the panel's files (index.html ...); empty: messd's default
  std::string token;            // non-empty: a page must give it (ws?token=...) to control
  std::size_t max_connections = 64;  // HTTP connections at once (WebSocket sessions count as clients)
};

}  // namespace imess::net
