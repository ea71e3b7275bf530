// The card link over a serial device: the I/O thread's loop (poll, read, decode, write), the
// lock-free crossings to the motion thread and set-up request/reply with retries.
#include "imess/hal/serial_card_link.hpp"

#include <poll.h>
#include <pthread.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <ctime>

#include "imess/hal/serial_line.hpp"

namespace imess::hal {

namespace {
constexpr auto kReopenEvery = std::chrono::milliseconds(100);
constexpr long kPollNs = 500'000;  // the I/O thread looks at the send ring at least this often
}  // namespace

SerialCardLink::SerialCardLink(SerialLinkSettings settings)
    : settings_(std::move(settings)), receiver_(settings_.max_rx_payload) {
  fd_ = open_serial_line(settings_.device, settings_.baud);
  connected_ = true;
  thread_ = std::thread([this] { run(); });
}

SerialCardLink::~SerialCardLink() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  if (fd_ >= 0) ::close(fd_);
}

bool SerialCardLink::send(std::span<const std::uint8_t> frame) noexcept {
  std::array<std::uint8_t, kMaxWireFrame> wire{};
  const std::size_t n = encode_frame(frame, wire);
  return n > 0 && tx_.push_all(std::span<const std::uint8_t>(wire.data(), n));
}

int SerialCardLink::poll(std::span<std::uint8_t> frame) noexcept {
  RxFrame f;
  if (!rx_.pop(f)) return 0;
  if (f.len == 0 || f.len > frame.size()) return -1;
  std::copy_n(f.bytes.begin(), f.len, frame.begin());
  return f.len;
}

void SerialCardLink::discard_received() noexcept {
  RxFrame f;
  while (rx_.pop(f)) {}
}

int SerialCardLink::transact(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept {
  if (request.empty() || request.size() + 1 > kMaxPayload) return -1;
  const double line = 2.0 * kMaxWireFrame * 10.0 / settings_.baud;  // both frames at their longest
  const auto timeout = std::chrono::duration<double>(settings_.setup_timeout + line);
  std::unique_lock lock(mutex_);
  for (int attempt = 0; attempt < settings_.setup_tries; ++attempt) {
    if (attempt > 0) ++setup_retries_;
    std::array<std::uint8_t, kMaxPayload> payload{};
    payload[0] = ++tag_;
    std::copy(request.begin(), request.end(), payload.begin() + 1);
    std::array<std::uint8_t, kMaxWireFrame> wire{};
    const std::size_t n = encode_frame(std::span<const std::uint8_t>(payload.data(), request.size() + 1), wire, kSetupSync);
    setup_out_.insert(setup_out_.end(), wire.begin(), wire.begin() + static_cast<long>(n));
    wanted_tag_ = tag_;
    waiting_ = true;
    reply_len_ = -1;
    if (replied_.wait_for(lock, timeout, [this] { return reply_len_ >= 0; })) {
      waiting_ = false;
      if (static_cast<std::size_t>(reply_len_) > reply.size()) return -1;
      std::copy_n(reply_.begin(), reply_len_, reply.begin());
      return reply_len_;
    }
  }
  waiting_ = false;
  return -1;
}

SerialLinkCounters SerialCardLink::counters() const noexcept {
  SerialLinkCounters c;
  c.bytes_in = bytes_in_;
  c.bytes_out = bytes_out_;
  c.frames_in = frames_in_;
  c.damaged = damaged_;
  c.overflows = overflows_;
  c.setup_retries = setup_retries_;
  c.hangups = hangups_;
  c.reopens = reopens_;
  c.connected = connected_;
  c.realtime = realtime_;
  return c;
}

// A byte from the line (resynchronising after a damaged frame: hal::FrameReceiver).
void SerialCardLink::received(std::uint8_t byte) noexcept {
  receiver_.feed(byte, [this](FrameDecoder::Result r, const FrameDecoder& d) { take(r, d); });
}

// Stream frames to the motion thread, set-up replies to transact().
void SerialCardLink::take(FrameDecoder::Result r, const FrameDecoder& d) noexcept {
  if (r == FrameDecoder::Result::Damaged) {
    ++damaged_;
    if (!d.setup() && !rx_.push(RxFrame{})) ++overflows_;
    return;
  }
  ++frames_in_;
  const auto p = d.payload();
  if (d.setup()) {
    std::lock_guard lock(mutex_);
    if (waiting_ && reply_len_ < 0 && p.size() >= 2 && p[0] == wanted_tag_) {  // a late reply to an earlier try is not it
      reply_len_ = static_cast<int>(p.size() - 1);
      std::copy(p.begin() + 1, p.end(), reply_.begin());
      replied_.notify_all();
    }
    return;
  }
  RxFrame f;
  f.len = static_cast<std::uint8_t>(p.size());
  std::copy(p.begin(), p.end(), f.bytes.begin());
  if (!rx_.push(f)) ++overflows_;
}

bool SerialCardLink::fill_out() noexcept {
  if (out_off_ < out_len_) return true;
  out_off_ = out_len_ = 0;
  {
    std::lock_guard lock(mutex_);
    if (!setup_out_.empty()) {
      out_len_ = std::min(setup_out_.size(), out_.size());
      std::copy_n(setup_out_.begin(), out_len_, out_.begin());
      setup_out_.erase(setup_out_.begin(), setup_out_.begin() + static_cast<long>(out_len_));
      return true;
    }
  }
  out_len_ = tx_.pop_some(out_);
  return out_len_ > 0;
}

void SerialCardLink::hang_up() noexcept {
  ::close(fd_);
  fd_ = -1;
  connected_ = false;
  ++hangups_;
  receiver_.reset();
  out_off_ = out_len_ = 0;
}

bool SerialCardLink::reopen() noexcept {
  try {
    fd_ = open_serial_line(settings_.device, settings_.baud);
  } catch (const std::exception&) {
    return false;
  }
  connected_ = true;
  ++reopens_;
  return true;
}

void SerialCardLink::run() noexcept {
  if (settings_.realtime_priority > 0) {  // refused without the permission: then time-shared, as the loop
    sched_param p{};
    p.sched_priority = settings_.realtime_priority;
    realtime_ = pthread_setschedparam(pthread_self(), SCHED_FIFO, &p) == 0;
  }
  auto next_open = std::chrono::steady_clock::now();
  while (!stop_.load(std::memory_order_relaxed)) {
    if (fd_ < 0) {  // the device went away: what is sent meanwhile is for nobody
      std::array<std::uint8_t, 512> drop{};
      while (tx_.pop_some(drop) > 0) {}
      {
        std::lock_guard lock(mutex_);
        setup_out_.clear();
      }
      const auto now = std::chrono::steady_clock::now();
      if (now >= next_open) {
        next_open = now + kReopenEvery;
        if (reopen()) continue;
      }
      const timespec ts{0, kPollNs};
      nanosleep(&ts, nullptr);
      continue;
    }
    const bool sending = fill_out();
    pollfd p{fd_, static_cast<short>(POLLIN | (sending ? POLLOUT : 0)), 0};
    const timespec ts{0, kPollNs};
    if (ppoll(&p, 1, &ts, nullptr) < 0) continue;
    if (p.revents & POLLIN) {
      std::array<std::uint8_t, 512> in{};
      const ssize_t n = ::read(fd_, in.data(), in.size());
      if (n > 0) {
        bytes_in_ += static_cast<unsigned long>(n);
        for (ssize_t i = 0; i < n; ++i) received(in[static_cast<std::size_t>(i)]);
      } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
        hang_up();
        next_open = std::chrono::steady_clock::now() + kReopenEvery;
        continue;
      }
    } else if (p.revents & (POLLHUP | POLLERR | POLLNVAL)) {
      hang_up();
      next_open = std::chrono::steady_clock::now() + kReopenEvery;
      continue;
    }
    if (sending && (p.revents & POLLOUT)) {
      const ssize_t n = ::write(fd_, out_.data() + out_off_, out_len_ - out_off_);
      if (n > 0) {
        out_off_ += static_cast<std::size_t>(n);
        bytes_out_ += static_cast<unsigned long>(n);
      } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
        hang_up();
        next_open = std::chrono::steady_clock::now() + kReopenEvery;
      }
    }
  }
}

}  // namespace imess::hal
