// The MESSD connections: accepting, refusing, session bookkeeping, replies and broadcasts.
#include "imess/net/session_hub.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "imess/protocol/messages.hpp"

namespace imess::net {

namespace asio = boost::asio;
using asio::ip::tcp;

// Opens, binds and listens; the port bound. Throws std::runtime_error naming the address,
// with `busy_hint` when the port is taken.
std::uint16_t open_listener(tcp::acceptor& acceptor, const std::string& listen, std::uint16_t port, std::string_view what,
                            std::string_view busy_hint) {
  boost::system::error_code ec;
  auto address = asio::ip::make_address(listen, ec);
  if (ec) throw std::runtime_error("listen address '" + listen + "' is not an IPv4 or IPv6 address");
  tcp::endpoint ep(address, port);
  const std::string where = listen + ":" + std::to_string(port);
  acceptor.open(ep.protocol(), ec);
  if (!ec) acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor.bind(ep, ec);
  if (!ec) acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec)
    throw std::runtime_error("cannot listen" + std::string(what) + " on " + where + ": " + ec.message() +
                             (ec == asio::error::address_in_use ? std::string(busy_hint) : std::string()));
  return acceptor.local_endpoint().port();
}

void SessionHub::accept() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (!running_) return;
    if (!ec) {
      admit(std::move(socket));
      accept();
      return;
    }
    // Out of descriptors or memory: accepting again at once would spin on the same error
    // (100 % of a core, a log line each time), so pause; the backlog keeps the callers waiting.
    const bool exhausted = ec == asio::error::no_descriptors || ec.value() == ENFILE ||
                           ec == asio::error::no_buffer_space || ec == asio::error::no_memory;
    log_limited(log_, spdlog::level::warn, "accept", "accept failed: " + ec.message() + (exhausted ? "; pausing 100 ms" : ""));
    if (!exhausted) {
      accept();
      return;
    }
    accept_timer_.expires_after(std::chrono::milliseconds(100));
    accept_timer_.async_wait([this](boost::system::error_code tec) {
      if (!tec && running_) accept();
    });
  });
}

void SessionHub::refuse(tcp::socket& socket, std::string line) {
  boost::system::error_code ec;
  socket.non_blocking(true, ec);  // one line into an empty socket buffer; never wait for it
  asio::write(socket, asio::buffer(line), ec);
  socket.close(ec);
}

void SessionHub::admit(tcp::socket socket) {
  boost::system::error_code ec;
  auto remote = socket.remote_endpoint(ec);
  if (ec) return;  // already gone
  admit(std::move(socket), remote, "", "");
}

void SessionHub::adopt(tcp::socket socket, const tcp::endpoint& peer, std::string via, std::string observe_reason) {
  admit(std::move(socket), peer, via, std::move(observe_reason));
}

void SessionHub::admit(tcp::socket socket, const tcp::endpoint& remote, const std::string& via, std::string observe_reason) {
  const auto& rules = config_.control;
  auto address = remote.address();
  if (address.is_v6() && address.to_v6().is_v4_mapped())  // a dual-stack "::" listener: show and match as IPv4
    address = asio::ip::make_address_v4(asio::ip::v4_mapped, address.to_v6());
  const bool host_may_control = rules.hosts.contains(address);
  const bool may_control = host_may_control && observe_reason.empty();
  const std::string host = address.to_string();
  if (!host_may_control && !rules.observe_hosts.contains(address)) {
    log_limited(log_, spdlog::level::warn, "refused-host", "refused a connection from " + host + ": not in control.hosts or control.observe_hosts");
    refuse(socket, protocol::format_err(protocol::ErrorCode::HostNotAllowed,
                                        "host " + host + " may not connect: it is in neither control.hosts nor "
                                        "control.observe_hosts of the daemon's configuration"));
    return;
  }
  // Observers may fill only max_clients - reserved_slots, so they never lock out a controller.
  const std::size_t reserved = std::min(rules.reserved_slots, config_.max_clients - 1);
  const std::size_t limit = may_control ? config_.max_clients : config_.max_clients - reserved;
  if (sessions_.size() >= limit) {
    log_limited(log_, spdlog::level::warn, "refused-full",
                "refused a connection from " + host + ": " + std::to_string(sessions_.size()) + " clients connected");
    refuse(socket, protocol::format_err(protocol::ErrorCode::TooManyClients,
                                        "connection limit of " + std::to_string(limit) + " clients reached" +
                                            (may_control ? "" : " for hosts that may only observe")));
    return;
  }
  auto id = next_id_++;
  auto session = std::make_shared<Session>(
      std::move(socket), id, config_.max_queue_bytes,
      [this](Session& s, const protocol::FramedLine& l) { handlers_.line(s, l); },
      [this](Session& s) { closed(s); });
  if (!via.empty()) session->set_peer(tcp::endpoint(address, remote.port()));
  session->info().may_control = may_control;
  if (host_may_control) session->info().observe_reason = std::move(observe_reason);
  session->info().may_force = may_control && rules.force_hosts.contains(address);
  session->info().connected_at = Session::Clock::now();
  sessions_[id] = session;
  log_limited(log_, spdlog::level::info, "connect",
              "client " + std::to_string(id) + " connected from " + session->peer() + (via.empty() ? "" : " " + via) +
                  (may_control ? "" : host_may_control ? " (observer: " + session->info().observe_reason + ")" : " (observer host)"));
  session->start();
  handlers_.admitted(*session);  // the position on connect; changes only from then on
}

void SessionHub::closed(Session& s) {
  const std::string text = "client " + std::to_string(s.id()) + " (" + s.peer() + ") " + s.close_reason();
  if (s.failed())  // a bug met by this client's line: the session ended, the daemon did not
    log_limited(log_, spdlog::level::err, "session-error", text + "; messd goes on");
  else
    log_limited(log_, spdlog::level::info, "disconnect", text);
  auto keep = sessions_[s.id()];  // s lives until this handler returns
  sessions_.erase(s.id());
  handlers_.gone(s);
}

void SessionHub::send(Session& s, std::string line) {
  if (config_.log_traffic) spdlog::info("[{}] < {}", s.id(), std::string_view(line).substr(0, line.size() - 1));
  s.send(std::move(line));
}

void SessionHub::reply(Session& s, std::uint32_t slot, std::string lines) {
  if (config_.log_traffic) spdlog::info("[{}] < {}", s.id(), std::string_view(lines).substr(0, lines.size() - 1));
  s.fill_reply(slot, std::move(lines));
}

void SessionHub::broadcast(const std::string& line) {
  if (config_.log_traffic) spdlog::info("[all] < {}", std::string_view(line).substr(0, line.size() - 1));
  auto shared = std::make_shared<const std::string>(line);  // one buffer in every queue
  auto sessions = sessions_;  // a send may drop a slow client and erase it
  for (auto& [id, s] : sessions) s->send(shared);
}

SessionHub::SessionHub(asio::io_context& io, const ServerConfig& config, LogLimiter& log)
    : io_(io), config_(config), log_(log), acceptor_(io), accept_timer_(io) {}

void SessionHub::start() {
  port_ = open_listener(acceptor_, config_.listen, config_.port, "", " - is another messd running? (--port chooses another)");
  running_ = true;
  accept();
}

void SessionHub::stop() {
  running_ = false;
  boost::system::error_code ec;
  acceptor_.close(ec);
  accept_timer_.cancel();
  auto sessions = sessions_;
  for (auto& [id, s] : sessions) s->close();
}

Session* SessionHub::find(std::uint32_t id) const {
  auto it = sessions_.find(id);
  return it == sessions_.end() ? nullptr : it->second.get();
}

}  // namespace imess::net
