// SerialCardLink: the servo card on a real serial device (docs/servo-card-link.md, "A card on
// a serial device"). One I/O thread owns the descriptor and does every read() and write();
// the motion thread only touches two lock-free SPSC rings — encoded frame bytes out, whole
// received stream frames in — so send() and poll() never wait. Set-up (hal::Link) goes over
// the same line as set-up frames (kSetupSync, a tag byte matching reply to request), retried
// after a timeout: a serial line loses and damages bytes. When the device hangs up (the
// adapter unplugged, messcard ended) the thread closes it and opens the path again every
// 100 ms, so a card that comes back is found without restarting messd.
#pragma once
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "imess/hal/card_stream.hpp"
#include "imess/hal/link.hpp"
#include "imess/hal/spsc_ring.hpp"
#include "imess/hal/stream_frame.hpp"
#include "imess/hal/stream_link.hpp"

namespace imess::hal {

struct SerialLinkSettings {
  std::string device;         // a tty path
  int baud = 115200;
  double setup_timeout = 0.1;  // s to wait for a set-up reply (plus both frames' time on the line)
  int setup_tries = 5;
  int realtime_priority = 0;        // > 0: the I/O thread asks for SCHED_FIFO at this priority
  std::size_t max_rx_payload = card::kMaxCardPayload;
};

struct SerialLinkCounters {
  unsigned long bytes_in = 0, bytes_out = 0;
  unsigned long frames_in = 0, damaged = 0;  // stream and set-up frames received whole / damaged
  unsigned long overflows = 0;               // received stream frames dropped: the motion thread did not poll
  unsigned long setup_retries = 0;           // set-up requests sent again after a timeout
  unsigned long hangups = 0, reopens = 0;    // the device went away / was opened again
  bool connected = false;
  bool realtime = false;                     // the I/O thread got SCHED_FIFO
};

class SerialCardLink final : public Link, public StreamLink {
 public:
  // Opens and configures the device (open_serial_line: throws SerialLineError) and starts the
  // I/O thread.
  explicit SerialCardLink(SerialLinkSettings settings);
  ~SerialCardLink() override;
  SerialCardLink(const SerialCardLink&) = delete;
  SerialCardLink& operator=(const SerialCardLink&) = delete;

  // Set-up only (blocks up to setup_tries × the timeout): one request, its reply; -1 when no
  // reply came.
  int transact(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept override;
  // Real-time (motion thread): see hal::StreamLink.
  bool send(std::span<const std::uint8_t> frame) noexcept override;
  int poll(std::span<std::uint8_t> frame) noexcept override;
  // Drops every stream frame received so far (set-up, before a stream starts: stale ones).
  void discard_received() noexcept;

  SerialLinkCounters counters() const noexcept;
  const SerialLinkSettings& settings() const noexcept { return settings_; }

 private:
  struct RxFrame {
    std::uint8_t len = 0;  // 0: a damaged frame
    std::array<std::uint8_t, kMaxPayload> bytes{};
  };
  void run() noexcept;
  bool reopen() noexcept;
  void hang_up() noexcept;
  void received(std::uint8_t byte) noexcept;
  void take(FrameDecoder::Result r, const FrameDecoder& d) noexcept;  // a frame, or a damaged one
  bool fill_out() noexcept;  // the next bytes to write: set-up first, then the stream's

  SerialLinkSettings settings_;
  int fd_ = -1;  // the I/O thread's (the constructor's until it starts)
  std::thread thread_;
  std::atomic<bool> stop_{false};

  SpscRing<std::uint8_t, 8192> tx_;  // motion thread → I/O thread: encoded stream frames
  SpscRing<RxFrame, 256> rx_;        // I/O thread → motion thread: stream frames (1.28 s of status frames)
  FrameReceiver receiver_;           // the I/O thread's
  std::array<std::uint8_t, 512> out_{};
  std::size_t out_len_ = 0, out_off_ = 0;

  // Set-up: guarded by mutex_ (never touched by the motion thread).
  std::mutex mutex_;
  std::condition_variable replied_;
  std::vector<std::uint8_t> setup_out_;
  std::uint8_t tag_ = 0, wanted_tag_ = 0;
  bool waiting_ = false;
  int reply_len_ = -1;
  std::array<std::uint8_t, kMaxPayload> reply_{};

  std::atomic<unsigned long> bytes_in_{0}, bytes_out_{0}, frames_in_{0}, damaged_{0}, overflows_{0}, setup_retries_{0},
      hangups_{0}, reopens_{0};
  std::atomic<bool> connected_{false}, realtime_{false};
};

}  // namespace imess::hal
