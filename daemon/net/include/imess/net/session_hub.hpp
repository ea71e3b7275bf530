// SessionHub: the MESSD front end's connections on TCP 1066 — accepting (who may connect,
// the slots kept for controllers), the sessions by number, and the three ways a line leaves:
// a reply into a slot, an event to one client, a broadcast to all.
#pragma once
#include <boost/asio.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "imess/net/log_limiter.hpp"
#include "imess/net/server_config.hpp"
#include "imess/net/session.hpp"

namespace imess::net {

class SessionHub {
 public:
  using Map = std::map<std::uint32_t, std::shared_ptr<Session>>;
  struct Handlers {
    Session::LineHandler line;                 // every line a client sends
    std::function<void(Session&)> admitted;    // a new client (the position on connect)
    std::function<void(Session&)> gone;        // after it left and was forgotten (control is lost)
  };

  SessionHub(boost::asio::io_context& io, const ServerConfig& config, LogLimiter& log);
  void set_handlers(Handlers h) { handlers_ = std::move(h); }
  void start();  // binds and accepts; throws std::runtime_error naming the address
  // A client that reached messd another way (the web panel: a WebSocket bridged to `socket`,
  // one end of a socket pair) from `peer`: admitted by the same rules as a TCP client of
  // 1066 (hosts, slots), and served by the same session code. A non-empty `observe_reason`
  // makes it an observer whatever its host, saying why (the panel's token was not given).
  void adopt(boost::asio::ip::tcp::socket socket, const boost::asio::ip::tcp::endpoint& peer, std::string via,
             std::string observe_reason);
  void stop();
  std::uint16_t port() const { return port_; }
  std::size_t size() const { return sessions_.size(); }
  Session* find(std::uint32_t id) const;
  // Every session; a caller whose sends may drop a client (and erase it) iterates a copy.
  const Map& all() const { return sessions_; }

  void broadcast(const std::string& line);
  void send(Session& s, std::string line);                        // an event line for one client
  void reply(Session& s, std::uint32_t slot, std::string lines);  // fills a reply slot

 private:
  void accept();
  void admit(boost::asio::ip::tcp::socket socket);
  void admit(boost::asio::ip::tcp::socket socket, const boost::asio::ip::tcp::endpoint& remote, const std::string& via,
             std::string observe_reason);
  void refuse(boost::asio::ip::tcp::socket& socket, std::string line);
  void closed(Session& s);

  boost::asio::io_context& io_;
  const ServerConfig& config_;
  LogLimiter& log_;
  Handlers handlers_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer accept_timer_;
  Map sessions_;
  std::uint32_t next_id_ = 1;
  std::uint16_t port_ = 0;
  bool running_ = false;
};

}  // namespace imess::net
