// The emulated card over a byte-timed serial line: the card ticks, the bytes flow.
#include "imess/sim/timed_card_link.hpp"

namespace imess::sim {

using hal::FrameDecoder;

TimedCardLink::TimedCardLink(EmulatedCard& card, const hal::Clock& clock, LineConfig config)
    : card_(card),
      clock_(clock),
      to_card_(config.baud, config.bits_per_byte),
      to_host_(config.baud, config.bits_per_byte),
      host_rx_(hal::card::kMaxCardPayload) {}

void TimedCardLink::sync() noexcept {
  const double t = hal::seconds(clock_.now());
  if (!started_) {
    card_.advance_to(t);
    started_ = true;
    t_start_ = t;
  }
  const double tick = card_.tick_period();
  for (double at = t_start_ + static_cast<double>(ticks_ + 1) * tick; at <= t + 1e-12;
       at = t_start_ + static_cast<double>(++ticks_ + 1) * tick) {
    to_card_.deliver(at, [this](std::uint8_t b) {
      card_rx_.feed(b, [this](FrameDecoder::Result r, const FrameDecoder& d) {
        if (r == FrameDecoder::Result::Damaged) {
          ++damaged_at_card_;
          card_.on_damaged_frame();
        } else if (!d.setup()) {
          card_.on_stream_frame(d.payload());  // set-up goes through transact()
        }
      });
    });
    card_.step();
    std::span<const std::uint8_t> out;
    if (card_.take_stream_frame(out)) {
      std::array<std::uint8_t, hal::kMaxWireFrame> wire{};
      const std::size_t n = hal::encode_frame(out, wire);
      to_host_.push(std::span<const std::uint8_t>(wire.data(), n), at);
    }
  }
  to_host_.deliver(t, [this](std::uint8_t b) {
    host_rx_.feed(b, [this](FrameDecoder::Result r, const FrameDecoder& d) {
      if (r == FrameDecoder::Result::Damaged) ++damaged_at_host_;
      if (inbox_count_ == inbox_.size()) return;  // nobody polls: the oldest stay, this one is dropped
      const std::size_t slot = (inbox_head_ + inbox_count_++) % inbox_.size();
      const auto p = d.payload();
      inbox_len_[slot] = r == FrameDecoder::Result::Frame ? p.size() : 0;
      for (std::size_t i = 0; i < inbox_len_[slot]; ++i) inbox_[slot][i] = p[i];
    });
  });
}

int TimedCardLink::transact(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept {
  sync();
  return card_.handle(request, reply);
}

bool TimedCardLink::send(std::span<const std::uint8_t> frame) noexcept {
  sync();
  std::array<std::uint8_t, hal::kMaxWireFrame> wire{};
  const std::size_t n = hal::encode_frame(frame, wire);
  return n > 0 && to_card_.push(std::span<const std::uint8_t>(wire.data(), n), hal::seconds(clock_.now()));
}

int TimedCardLink::poll(std::span<std::uint8_t> frame) noexcept {
  sync();
  if (inbox_count_ == 0) return 0;
  const std::size_t slot = inbox_head_;
  inbox_head_ = (inbox_head_ + 1) % inbox_.size();
  --inbox_count_;
  const std::size_t n = inbox_len_[slot];
  if (n == 0 || n > frame.size()) return -1;
  for (std::size_t i = 0; i < n; ++i) frame[i] = inbox_[slot][i];
  return static_cast<int>(n);
}

}  // namespace imess::sim
