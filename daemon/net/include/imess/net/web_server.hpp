// WebServer: the web panel's front end on server.http_port (docs/web.md). HTTP serves the
// panel's files; a WebSocket on /ws is one MESSD client: its JSON messages become lines
// (imess::webjson) on one end of a socket pair whose other end SessionHub adopts as a
// session like any on TCP 1066, and that session's lines come back as JSON events. So the
// control rules, host lists, dead-man (Watch), slots, in-flight and output limits are those
// very sessions'; the panel is one more client, not a copy of the protocol.
#pragma once
#include <boost/asio.hpp>

#include <cstdint>
#include <memory>
#include <string>

#include "imess/net/log_limiter.hpp"
#include "imess/net/server_config.hpp"
#include "imess/net/session_hub.hpp"

namespace imess::net {

class ProgramRunner;

class WebServer {
 public:
  // programs: the program runner whose loaded program's path the page may ask for (or null).
  WebServer(boost::asio::io_context& io, const ServerConfig& config, SessionHub& sessions, LogLimiter& log,
            const ProgramRunner* programs = nullptr);
  ~WebServer();
  void start();  // binds and accepts; throws std::runtime_error naming the address
  void stop();
  std::uint16_t port() const { return port_; }
  const std::string& root() const { return root_; }

  struct Shared;  // what the connections share (config, hub, counts), alive while any connection is

 private:
  void accept();
  boost::asio::ip::tcp::acceptor acceptor_;
  std::shared_ptr<Shared> shared_;
  std::string root_;
  std::uint16_t port_ = 0;
  bool running_ = false;
};

// Where messd finds the panel's files when server.http_root does not say: the installed
// share/imess/web beside the binary's bin/, else the source tree's web/ it was built from.
std::string default_web_root();

}  // namespace imess::net
