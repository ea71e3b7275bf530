// The floor server: accept, read lines, write them back / to all / on a timer.
#include "echo_server.hpp"

#include <cstdio>

#include "clock.hpp"

namespace imess::bench {

namespace asio = boost::asio;
using asio::ip::tcp;

// One connection: a read loop splitting lines, a queue of shared lines written one gathered
// write at a time.
class EchoServer::Peer : public std::enable_shared_from_this<Peer> {
 public:
  Peer(tcp::socket socket, std::uint32_t id, EchoServer& server) : socket_(std::move(socket)), id_(id), server_(server) {
    boost::system::error_code ec;
    socket_.set_option(tcp::no_delay(true), ec);
  }
  std::uint32_t id() const { return id_; }

  void start() { read(); }

  void send(std::shared_ptr<const std::string> line) {
    if (!open_) return;
    queue_.push_back(std::move(line));
    if (queue_.size() > 100000) {  // a client that stopped reading: drop it, never grow without end
      close();
      return;
    }
    if (!writing_) write();
  }

 private:
  void read() {
    socket_.async_read_some(asio::buffer(buffer_), [self = shared_from_this()](boost::system::error_code ec, std::size_t n) {
      if (ec) {
        self->close();
        return;
      }
      self->partial_.append(self->buffer_.data(), n);
      std::size_t start = 0;
      for (std::size_t nl; (nl = self->partial_.find('\n', start)) != std::string::npos; start = nl + 1) {
        self->server_.on_line(*self, self->partial_.substr(start, nl + 1 - start));
        if (!self->open_) return;
      }
      self->partial_.erase(0, start);
      if (self->partial_.size() > 4096) self->partial_.clear();  // no line that long: not a line client
      self->read();
    });
  }

  void write() {
    writing_ = true;
    buffers_.clear();
    held_.clear();
    for (std::size_t i = 0; i < queue_.size() && i < 256; ++i) {
      buffers_.push_back(asio::buffer(*queue_[i]));
      held_.push_back(queue_[i]);
    }
    asio::async_write(socket_, buffers_, [self = shared_from_this()](boost::system::error_code ec, std::size_t) {
      if (ec || !self->open_) {
        self->close();
        return;
      }
      for (std::size_t i = 0; i < self->held_.size(); ++i) self->queue_.pop_front();
      self->held_.clear();
      if (self->queue_.empty()) {
        self->writing_ = false;
        return;
      }
      self->write();
    });
  }

  void close() {
    if (!open_) return;
    open_ = false;
    boost::system::error_code ec;
    socket_.close(ec);
    queue_.clear();
    server_.peers_.erase(id_);
  }

  tcp::socket socket_;
  std::uint32_t id_;
  EchoServer& server_;
  std::array<char, 4096> buffer_{};
  std::string partial_;
  std::deque<std::shared_ptr<const std::string>> queue_;
  std::vector<asio::const_buffer> buffers_;
  std::vector<std::shared_ptr<const std::string>> held_;
  bool open_ = true, writing_ = false;
};

EchoServer::EchoServer(asio::io_context& io, EchoMode mode, double hz, std::uint16_t port)
    : io_(io), mode_(mode), acceptor_(io, tcp::endpoint(asio::ip::make_address("127.0.0.1"), port)), timer_(io) {
  accept();
  if (mode_ == EchoMode::Timer) {
    period_ = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 / hz));
    timer_.expires_after(period_);
    tick();
  }
}

std::uint16_t EchoServer::port() const { return acceptor_.local_endpoint().port(); }

void EchoServer::accept() {
  acceptor_.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
    if (!ec) {
      auto peer = std::make_shared<Peer>(std::move(socket), next_id_++, *this);
      peers_[peer->id()] = peer;
      peer->start();
      peer->send(std::make_shared<const std::string>("CurrCor 0.000 0.000 0.000\n"));  // as messd's position on connect
    }
    accept();
  });
}

void EchoServer::on_line(Peer& from, std::string line) {
  auto shared = std::make_shared<const std::string>(std::move(line));
  if (mode_ == EchoMode::Echo)
    from.send(std::move(shared));
  else if (mode_ == EchoMode::Broadcast)
    broadcast(shared);
}

void EchoServer::broadcast(const std::shared_ptr<const std::string>& line) {
  // A send may drop a client (and erase it from peers_): walk a snapshot of the ids.
  std::vector<std::shared_ptr<Peer>> all;
  all.reserve(peers_.size());
  for (auto& [id, p] : peers_) all.push_back(p);
  for (auto& p : all) p->send(line);
}

// Fixed schedule (the next deadline is the previous one plus the period), as messd's reporter.
void EchoServer::tick() {
  timer_.async_wait([this](boost::system::error_code ec) {
    if (ec) return;
    char line[64];
    const std::int64_t now = mono_ns();
    std::snprintf(line, sizeof line, "CurrCor %lld.%06lld 0.000 0.000\n", static_cast<long long>(now / 1'000'000'000),
                  static_cast<long long>(now % 1'000'000'000 / 1000));
    broadcast(std::make_shared<const std::string>(line));
    auto next = timer_.expiry() + period_;
    if (next + period_ < asio::steady_timer::clock_type::now()) next = asio::steady_timer::clock_type::now() + period_;
    timer_.expires_at(next);
    tick();
  });
}

}  // namespace imess::bench
