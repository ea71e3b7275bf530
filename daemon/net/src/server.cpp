// Accepting, session bookkeeping, broadcasting and the periodic timers.
#include "imess/net/server.hpp"

#include "imess/core/path_machine.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "imess/protocol/messages.hpp"

namespace imess::net {

namespace asio = boost::asio;
using asio::ip::tcp;

Server::Server(asio::io_context& io, ServerConfig config, core::MotionCore& core, core::LoopRunner* runner,
               journal::Journal& journal, core::EventFd* wake)
    : io_(io),
      config_(std::move(config)),
      core_(core),
      runner_(runner),
      journal_(journal),
      acceptor_(io),
      wake_(wake),
      event_timer_(io),
      housekeeping_timer_(io),
      report_timer_(io),
      log_timer_(io),
      clients_timer_(io),
      accept_timer_(io),
      planner_(core::path_machine(core.config()), core::path_options(core.config())) {}

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

void Server::start() {
  frames_ = PartFrames(config_.frames_file);  // a store that does not load is a start-up error naming it
  port_ = open_listener(acceptor_, config_.listen, config_.port, "", " - is another messd running? (--port chooses another)");
  if (config_.ippdme.on) {
    if (layout().cartesian_axis(0) >= 0 && layout().cartesian_axis(1) >= 0 && layout().cartesian_axis(2) >= 0) {
      ipp_ = std::make_unique<IppServer>(io_, *this, config_.ippdme);
      ipp_->start(config_.listen);
    } else {
      spdlog::info("I++ DME: off, this machine has no linear X Y Z axes (axes {})", layout().names());
    }
  }
  running_ = true;
  const auto& snap = core_.snapshot();  // clients get the position on connect; report changes only
  const hal::Vec3 p = layout().cartesian(snap.position);
  last_curr_cor_ = protocol::format_curr_cor({p.x(), p.y(), p.z()});
  if (!layout().is_xyz()) last_ax_pos_ = ax_pos_line();
  accept();
  if (wake_) {
    int fd = ::dup(wake_->fd());  // the descriptor object closes its own copy
    if (fd < 0) throw std::runtime_error("cannot duplicate the event descriptor: " + std::string(std::strerror(errno)));
    wake_wait_.emplace(io_, fd);
    wait_for_events();
  }
  // Without an EventFd the timer is the only drain, so it keeps the old millisecond.
  const double drain_ms = wake_ ? config_.event_backstop_ms : 1.0;
  schedule(event_timer_, std::chrono::microseconds(static_cast<long>(drain_ms * 1000)), &Server::backstop_events);
  schedule(clients_timer_, std::chrono::microseconds(250000), &Server::check_clients);
  if (config_.stream_position)
    schedule(report_timer_, std::chrono::microseconds(static_cast<long>(1e6 / config_.report_hz)), &Server::report_position);
  if (config_.log_status || config_.log_timing) schedule(log_timer_, std::chrono::seconds(5), &Server::log_periodic);
}

void Server::stop() {
  running_ = false;
  boost::system::error_code ec;
  acceptor_.close(ec);
  if (ipp_) ipp_->stop();
  event_timer_.cancel();
  housekeeping_timer_.cancel();
  if (wake_wait_) wake_wait_->close(ec);
  report_timer_.cancel();
  log_timer_.cancel();
  clients_timer_.cancel();
  accept_timer_.cancel();
  auto sessions = sessions_;
  for (auto& [id, s] : sessions) s->close();
}

void Server::schedule(asio::steady_timer& t, std::chrono::microseconds every, void (Server::*fn)()) {
  t.expires_after(every);
  rearm(t, every, fn);
}

// Fixed schedule: the next deadline is the previous one plus the period, not "now" plus the
// period (that lost the handler's own time each round: ReportHz 100 to 200 clients gave 84
// lines a second). More than a whole period late, it skips ahead instead of bursting.
void Server::rearm(asio::steady_timer& t, std::chrono::microseconds every, void (Server::*fn)()) {
  t.async_wait([this, &t, every, fn](boost::system::error_code ec) {
    if (ec || !running_) return;
    (this->*fn)();
    // The report rate may change at run time (Set ReportHz).
    // The report timer runs at the fastest rate a client needs (ReportHz, Stream).
    auto period = &t == &report_timer_ ? std::chrono::microseconds(static_cast<long>(1e6 / report_timer_hz())) : every;
    auto next = t.expiry() + period;
    const auto now = asio::steady_timer::clock_type::now();
    if (next + period < now) next = now + period;
    t.expires_at(next);
    rearm(t, every, fn);
  });
}

void Server::accept() {
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
    log_limited(spdlog::level::warn, "accept", "accept failed: " + ec.message() + (exhausted ? "; pausing 100 ms" : ""));
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

void Server::refuse(tcp::socket& socket, std::string line) {
  boost::system::error_code ec;
  socket.non_blocking(true, ec);  // one line into an empty socket buffer; never wait for it
  asio::write(socket, asio::buffer(line), ec);
  socket.close(ec);
}

void Server::admit(tcp::socket socket) {
  boost::system::error_code ec;
  auto remote = socket.remote_endpoint(ec);
  if (ec) return;  // already gone
  const auto& rules = config_.control;
  auto address = remote.address();
  if (address.is_v6() && address.to_v6().is_v4_mapped())  // a dual-stack "::" listener: show and match as IPv4
    address = asio::ip::make_address_v4(asio::ip::v4_mapped, address.to_v6());
  const bool may_control = rules.hosts.contains(address);
  const std::string host = address.to_string();
  if (!may_control && !rules.observe_hosts.contains(address)) {
    log_limited(spdlog::level::warn, "refused-host", "refused a connection from " + host + ": not in control.hosts or control.observe_hosts");
    refuse(socket, protocol::format_err(protocol::ErrorCode::HostNotAllowed,
                                        "host " + host + " may not connect: it is in neither control.hosts nor "
                                        "control.observe_hosts of the daemon's configuration"));
    return;
  }
  // Observers may fill only max_clients - reserved_slots, so they never lock out a controller.
  const std::size_t reserved = std::min(rules.reserved_slots, config_.max_clients - 1);
  const std::size_t limit = may_control ? config_.max_clients : config_.max_clients - reserved;
  if (sessions_.size() >= limit) {
    log_limited(spdlog::level::warn, "refused-full",
                "refused a connection from " + host + ": " + std::to_string(sessions_.size()) + " clients connected");
    refuse(socket, protocol::format_err(protocol::ErrorCode::TooManyClients,
                                        "connection limit of " + std::to_string(limit) + " clients reached" +
                                            (may_control ? "" : " for hosts that may only observe")));
    return;
  }
  auto id = next_id_++;
  auto session = std::make_shared<Session>(
      std::move(socket), id, config_.max_queue_bytes,
      [this](Session& s, const protocol::FramedLine& l) {
        on_line(s, l);
        arm_housekeeping();  // a Watch, a new owner, a hit to sync: each may bring a deadline
      },
      [this](Session& s) { closed(s); });
  session->info().may_control = may_control;
  session->info().may_force = may_control && rules.force_hosts.contains(address);
  session->info().connected_at = Session::Clock::now();
  sessions_[id] = session;
  log_limited(spdlog::level::info, "connect",
              "client " + std::to_string(id) + " connected from " + session->peer() + (may_control ? "" : " (observer host)"));
  session->start();
  send_position(*session, position_lines());  // the position on connect; changes only from then on
}

void Server::closed(Session& s) {
  const std::string text = "client " + std::to_string(s.id()) + " (" + s.peer() + ") " + s.close_reason();
  if (s.failed())  // a bug met by this client's line: the session ended, the daemon did not
    log_limited(spdlog::level::err, "session-error", text + "; messd goes on");
  else
    log_limited(spdlog::level::info, "disconnect", text);
  auto keep = sessions_[s.id()];  // s lives until this handler returns
  sessions_.erase(s.id());
  lose_control(s, "disconnected", true);
}

void Server::log_limited(spdlog::level::level_enum level, std::string_view message_class, const std::string& text) {
  auto held = log_limiter_.admit(message_class, LogLimiter::Clock::now());
  if (!held) return;
  if (*held > 0) spdlog::log(level, "... suppressed {} similar '{}' lines", *held, message_class);
  spdlog::log(level, "{}", text);
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
  auto shared = std::make_shared<const std::string>(line);  // one buffer in every queue
  auto sessions = sessions_;  // a send may drop a slow client and erase it
  for (auto& [id, s] : sessions) s->send(shared);
}

}  // namespace imess::net
