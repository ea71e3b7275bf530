// Session I/O on the io thread: async read loop, one async write at a time.
#include "imess/net/session.hpp"

namespace imess::net {

namespace asio = boost::asio;

Session::Session(asio::ip::tcp::socket socket, std::uint32_t id, std::size_t max_queue_bytes, LineHandler on_line,
                 CloseHandler on_close)
    : socket_(std::move(socket)),
      id_(id),
      max_queue_bytes_(max_queue_bytes),
      on_line_(std::move(on_line)),
      on_close_(std::move(on_close)) {
  boost::system::error_code ec;
  auto ep = socket_.remote_endpoint(ec);
  peer_ = ec ? "unknown" : ep.address().to_string() + ":" + std::to_string(ep.port());
  socket_.set_option(asio::ip::tcp::no_delay(true), ec);
}

void Session::start() { read(); }

void Session::read() {
  socket_.async_read_some(asio::buffer(buffer_), [self = shared_from_this()](boost::system::error_code ec, std::size_t n) {
    if (ec) {
      self->close();
      return;
    }
    self->framer_.feed(std::string_view(self->buffer_.data(), n), [&](const protocol::FramedLine& line) {
      if (self->open_) self->on_line_(*self, line);
    });
    if (self->open_) self->read();
  });
}

void Session::send(std::string line) {
  if (!open_) return;
  if (queued_bytes_ + line.size() > max_queue_bytes_) {  // not reading: drop it, never block
    close();
    return;
  }
  queued_bytes_ += line.size();
  queue_.push_back(std::move(line));
  if (!writing_) write();
}

std::uint32_t Session::reserve_reply() {
  replies_.emplace_back(next_slot_, std::string{});
  return next_slot_++;
}

void Session::fill_reply(std::uint32_t slot, std::string lines) {
  for (auto& [id, text] : replies_)
    if (id == slot) text = std::move(lines);
  while (!replies_.empty() && !replies_.front().second.empty()) {
    send(std::move(replies_.front().second));
    replies_.pop_front();
  }
}

void Session::write() {
  if (queue_.empty()) {
    writing_ = false;
    if (close_when_flushed_ && replies_.empty()) close();
    return;
  }
  writing_ = true;
  asio::async_write(socket_, asio::buffer(queue_.front()), [self = shared_from_this()](boost::system::error_code ec, std::size_t) {
    if (ec || !self->open_) {
      self->close();
      return;
    }
    self->queued_bytes_ -= self->queue_.front().size();
    self->queue_.pop_front();
    self->write();
  });
}

void Session::close_after_flush() {
  if (!writing_ && queue_.empty() && replies_.empty()) {
    close();
    return;
  }
  close_when_flushed_ = true;
}

void Session::close() {
  if (!open_) return;
  open_ = false;
  boost::system::error_code ec;
  socket_.shutdown(asio::ip::tcp::socket::shutdown_both, ec);
  socket_.close(ec);
  queue_.clear();
  queued_bytes_ = 0;
  if (on_close_) on_close_(*this);
}

}  // namespace imess::net
