// Session I/O on the io thread: async read loop, one gathered async write at a time.
#include "imess/net/session.hpp"

#include <linux/sockios.h>
#include <sys/ioctl.h>

#include <algorithm>
#include <vector>

namespace imess::net {

namespace asio = boost::asio;

namespace {
constexpr std::size_t kMaxGather = 256;        // lines per write
constexpr std::size_t kMaxOpenRequests = 256;  // requests not yet answered; beyond it, reading pauses
}  // namespace

Session::Session(asio::ip::tcp::socket socket, std::uint32_t id, std::size_t max_queue_bytes, LineHandler on_line,
                 CloseHandler on_close)
    : socket_(std::move(socket)),
      id_(id),
      max_queue_bytes_(max_queue_bytes),
      on_line_(std::move(on_line)),
      on_close_(std::move(on_close)) {
  boost::system::error_code ec;
  auto ep = socket_.remote_endpoint(ec);
  if (!ec) set_peer(ep);
  else peer_ = "unknown";
  socket_.set_option(asio::ip::tcp::no_delay(true), ec);
}

void Session::set_peer(const asio::ip::tcp::endpoint& ep) {
  address_ = ep.address();
  if (address_.is_v6() && address_.to_v6().is_v4_mapped())  // an IPv4 client of a dual-stack "::" listener
    address_ = asio::ip::make_address_v4(asio::ip::v4_mapped, address_.to_v6());
  peer_ = address_.to_string() + ":" + std::to_string(ep.port());
}

void Session::start() { read(); }

void Session::read() {
  socket_.async_read_some(asio::buffer(buffer_), [self = shared_from_this()](boost::system::error_code ec, std::size_t n) {
    if (ec) {
      self->close();
      return;
    }
    self->last_received_ = Clock::now();
    if (self->discard_input_) {
      self->read();
      return;
    }
    if (!self->take_input(std::string_view(self->buffer_.data(), n))) {
      if (self->open_) self->read_paused_ = true;  // the client sends faster than it is answered: let TCP hold it back
      return;
    }
    self->read();
  });
}

bool Session::take_input(std::string_view bytes) {
  // A line at a time (up to each LF), not a whole read at a time: 4 KiB of short requests with
  // 5 KiB answers would otherwise queue 4 MiB before the first check.
  std::size_t at = 0;
  while (at < bytes.size()) {
    const std::size_t nl = bytes.find('\n', at);
    const std::size_t end = nl == std::string_view::npos ? bytes.size() : nl + 1;
    framer_.feed(bytes.substr(at, end - at), [&](const protocol::FramedLine& line) {
      if (open_ && !discard_input_) handle(line);
    });
    at = end;
    if (!open_ || discard_input_) {
      unread_.clear();
      return false;
    }
    if (backlogged()) break;
  }
  unread_.assign(bytes.substr(at));
  return at == bytes.size() && !backlogged();
}

// The last resort: whatever a line's handling throws ends this session, never the daemon
// (the exception would leave io_context::run and messd with it).
void Session::handle(const protocol::FramedLine& line) {
  try {
    on_line_(*this, line);
  } catch (const std::exception& e) {
    failed_ = true;
    close(std::string("ended by an unexpected error while handling its line: ") + e.what());
  } catch (...) {
    failed_ = true;
    close("ended by an unexpected error of unknown type while handling its line");
  }
}

bool Session::backlogged() const {
  return replies_.size() >= kMaxOpenRequests || queued_bytes_ + reply_bytes_ >= max_queue_bytes_ / 4;
}

void Session::resume_reading() {
  if (!read_paused_ || !open_ || backlogged()) return;
  read_paused_ = false;
  if (!unread_.empty()) {
    const std::string rest = std::move(unread_);
    unread_.clear();
    if (!take_input(rest)) {
      if (open_) read_paused_ = true;
      return;
    }
  }
  read();
}

void Session::send(std::string line) {
  if (!open_) return;
  send(std::make_shared<const std::string>(std::move(line)));
}

void Session::send(std::shared_ptr<const std::string> line) {
  if (!open_) return;
  if (queued_bytes_ + line->size() > max_queue_bytes_) {  // not reading: drop it, never block
    close("dropped: more than " + std::to_string(max_queue_bytes_) + " bytes of output waiting (not reading fast enough)");
    return;
  }
  queued_bytes_ += line->size();
  queue_.push_back(std::move(line));
  if (!writing_) {
    // Start the write after the current handler: everything it queues for this client (a
    // hit's Hit and MeasPt, a burst of events) then leaves in one gathered write.
    writing_ = true;
    asio::post(socket_.get_executor(), [self = shared_from_this()] { self->write(); });
  }
}

std::uint32_t Session::reserve_reply() {
  replies_.push_back({next_slot_, std::string{}, Clock::now()});
  return next_slot_++;
}

void Session::fill_reply(std::uint32_t slot, std::string lines) {
  for (auto& r : replies_)
    if (r.id == slot) {
      reply_bytes_ = reply_bytes_ - r.text.size() + lines.size();
      r.text = std::move(lines);
    }
  flush_replies();
}

std::size_t Session::expire_replies(Clock::time_point now, Clock::duration after, const std::string& line) {
  std::size_t expired = 0;
  for (auto& r : replies_)
    if (r.text.empty() && now - r.since >= after) {
      r.text = line;
      reply_bytes_ += line.size();
      ++expired;
    }
  if (expired > 0) flush_replies();
  return expired;
}

void Session::flush_replies() {
  while (!replies_.empty() && !replies_.front().text.empty()) {
    reply_bytes_ -= replies_.front().text.size();
    send(std::move(replies_.front().text));
    replies_.pop_front();
  }
}

void Session::write() {
  if (!open_) return;
  if (queue_.empty()) {
    writing_ = false;
    if (close_when_flushed_ && replies_.empty()) close();
    resume_reading();
    return;
  }
  writing_ = true;
  // Everything queued goes out in one gathered write (up to kMaxGather lines): one line per
  // write let a client that sends fast build up replies faster than they left. The handler
  // holds the lines it writes, so closing the session (which clears queue_) while the write
  // is in flight frees nothing the kernel call still reads.
  std::vector<asio::const_buffer> buffers;
  std::vector<std::shared_ptr<const std::string>> held;
  for (std::size_t i = 0; i < queue_.size() && i < kMaxGather; ++i) {
    buffers.push_back(asio::buffer(*queue_[i]));
    held.push_back(queue_[i]);
  }
  asio::async_write(socket_, buffers, [self = shared_from_this(), held = std::move(held)](boost::system::error_code ec, std::size_t n) {
    if (ec || !self->open_) {
      self->close();
      return;
    }
    self->bytes_written_ += n;
    for (std::size_t i = 0; i < held.size(); ++i) {  // lines queued meanwhile stay behind them
      self->queued_bytes_ -= self->queue_.front()->size();
      self->queue_.pop_front();
    }
    self->resume_reading();
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

void Session::drop(std::string line) {
  if (!open_ || discard_input_) return;
  discard_input_ = true;
  replies_.clear();  // unanswered requests are void: the line below is the last word
  reply_bytes_ = 0;
  unread_.clear();
  send(std::move(line));
  close_after_flush();
}

Session::Clock::duration Session::output_stalled_for(Clock::time_point now) {
  // The kernel takes megabytes into a socket's send buffer, so a client that stopped reading
  // shows as bytes the peer never acknowledged (SIOCOUTQ), not as an unfinished write. The
  // client makes progress when the count of bytes it acknowledged grows: a reading client's
  // waiting count can stay the same from sweep to sweep (its last reply not yet acknowledged,
  // delayed ACK) while everything flows.
  int unacked = 0;
  if (open_ && ::ioctl(socket_.native_handle(), SIOCOUTQ, &unacked) != 0) unacked = 0;
  const std::size_t in_kernel = std::min(static_cast<std::size_t>(std::max(unacked, 0)), bytes_written_);
  const std::size_t acknowledged = bytes_written_ - in_kernel;
  if (queued_bytes_ + in_kernel == 0 || acknowledged > last_acknowledged_)
    stall_start_.reset();  // drained, or draining: the client reads
  else if (!stall_start_)
    stall_start_ = now;
  last_acknowledged_ = acknowledged;
  return stall_start_ ? now - *stall_start_ : Clock::duration::zero();
}

void Session::close(std::string reason) {
  if (!open_) return;
  open_ = false;
  close_reason_ = std::move(reason);
  boost::system::error_code ec;
  socket_.shutdown(asio::ip::tcp::socket::shutdown_both, ec);
  socket_.close(ec);
  queue_.clear();
  queued_bytes_ = 0;
  unread_.clear();
  if (on_close_) on_close_(*this);
}

}  // namespace imess::net
