// Accepting, session bookkeeping, broadcasting and the periodic timers.
#include "imess/net/server.hpp"

#include <spdlog/spdlog.h>

#include "imess/protocol/messages.hpp"

namespace imess::net {

namespace asio = boost::asio;
using asio::ip::tcp;

Server::Server(asio::io_context& io, ServerConfig config, core::MotionCore& core, core::LoopRunner* runner,
               journal::Journal& journal)
    : io_(io),
      config_(std::move(config)),
      core_(core),
      runner_(runner),
      journal_(journal),
      acceptor_(io),
      event_timer_(io),
      report_timer_(io),
      log_timer_(io) {}

void Server::start() {
  boost::system::error_code ec;
  auto address = asio::ip::make_address(config_.listen, ec);
  if (ec) throw std::runtime_error("listen address '" + config_.listen + "' is not an IPv4 or IPv6 address");
  tcp::endpoint ep(address, config_.port);
  std::string where = config_.listen + ":" + std::to_string(config_.port);
  acceptor_.open(ep.protocol(), ec);
  if (!ec) acceptor_.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor_.bind(ep, ec);
  if (!ec) acceptor_.listen(asio::socket_base::max_listen_connections, ec);
  if (ec)
    throw std::runtime_error("cannot listen on " + where + ": " + ec.message() +
                             (ec == asio::error::address_in_use ? " - is another messd running? (--port chooses another)" : ""));
  port_ = acceptor_.local_endpoint().port();
  running_ = true;
  const auto& snap = core_.snapshot();  // clients get the position on connect; report changes only
  last_curr_cor_ = protocol::format_curr_cor({snap.position.x(), snap.position.y(), snap.position.z()});
  accept();
  schedule(event_timer_, std::chrono::microseconds(1000), &Server::pump_events);
  schedule(report_timer_, std::chrono::microseconds(static_cast<long>(1e6 / config_.report_hz)), &Server::report_position);
  if (config_.log_status || config_.log_timing) schedule(log_timer_, std::chrono::seconds(5), &Server::log_periodic);
}

void Server::stop() {
  running_ = false;
  boost::system::error_code ec;
  acceptor_.close(ec);
  event_timer_.cancel();
  report_timer_.cancel();
  log_timer_.cancel();
  auto sessions = sessions_;
  for (auto& [id, s] : sessions) s->close();
}

void Server::schedule(asio::steady_timer& t, std::chrono::microseconds every, void (Server::*fn)()) {
  t.expires_after(every);
  t.async_wait([this, &t, every, fn](boost::system::error_code ec) {
    if (ec || !running_) return;
    (this->*fn)();
    // The report rate may change at run time (Set ReportHz).
    auto next = &t == &report_timer_ ? std::chrono::microseconds(static_cast<long>(1e6 / config_.report_hz)) : every;
    schedule(t, next, fn);
  });
}

void Server::accept() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (!running_) return;
    if (!ec) {
      if (sessions_.size() >= config_.max_clients) {
        std::string line = protocol::format_err(protocol::ErrorCode::TooManyClients,
                                                "connection limit of " + std::to_string(config_.max_clients) + " clients reached");
        boost::system::error_code wec;
        asio::write(socket, asio::buffer(line), wec);
        spdlog::warn("refused a connection: {} clients already connected", sessions_.size());
      } else {
        auto id = next_id_++;
        auto session = std::make_shared<Session>(
            std::move(socket), id, config_.max_queue_bytes,
            [this](Session& s, const protocol::FramedLine& l) { on_line(s, l); },
            [this](Session& s) {
              spdlog::info("client {} ({}) disconnected", s.id(), s.peer());
              sessions_.erase(s.id());
            });
        sessions_[id] = session;
        spdlog::info("client {} connected from {}", id, session->peer());
        session->start();
        const auto& snap = core_.snapshot();
        send(*session, protocol::format_curr_cor({snap.position.x(), snap.position.y(), snap.position.z()}));
      }
    } else {
      spdlog::warn("accept failed: {}", ec.message());
    }
    accept();
  });
}

void Server::send(Session& s, std::string line) {
  if (config_.log_traffic) spdlog::info("[{}] < {}", s.id(), std::string_view(line).substr(0, line.size() - 1));
  s.send(std::move(line));
}

void Server::reply(Session& s, std::uint32_t slot, std::string lines) {
  if (config_.log_traffic) spdlog::info("[{}] < {}", s.id(), std::string_view(lines).substr(0, lines.size() - 1));
  s.fill_reply(slot, std::move(lines));
}

void Server::broadcast(const std::string& line) {
  if (config_.log_traffic) spdlog::info("[all] < {}", std::string_view(line).substr(0, line.size() - 1));
  auto sessions = sessions_;  // a send may drop a slow client and erase it
  for (auto& [id, s] : sessions) s->send(line);
}

}  // namespace imess::net
