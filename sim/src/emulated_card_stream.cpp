// The emulated card's stream: host frames in (sequence-checked), timed setpoints executed on
// the card's own clock, a status frame out every status period.
#include <algorithm>
#include <cmath>

#include "imess/hal/axis_status.hpp"
#include "imess/sim/emulated_card.hpp"

namespace imess::sim {

using hal::card::kAxes;
using hal::LinkReader;
using hal::card::Op;
using hal::card::Status;
namespace st = hal::status;
namespace card = hal::card;

namespace {
// Setpoints the firmware refuses as implausible: faster than this many times vmax.
constexpr double kSpeedMargin = 1.1;
bool named(unsigned mask, int a) noexcept { return (mask & (1u << a)) != 0; }
}  // namespace

// StartStream: u16 status period (µs), table -> u32 ticks per second, u32 clock.
Status EmulatedCard::start_stream(LinkReader& r, hal::LinkWriter& out) noexcept {
  const std::uint16_t period_us = r.u16();
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  if (!r.at_end()) return Status::BadLength;
  if (period_us == 0) return Status::BadValue;
  status_ticks_ = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(period_us * 1e-6 / config_.tick)));
  stream_mask_ = mask;
  streaming_ = true;
  have_seq_ = resend_wanted_ = false;
  held_len_.fill(0);
  ack_ = 0;
  frame_status_ = Status::Ok;
  since_status_ = 0;
  if (following_) end_following(true);
  out.u32(static_cast<std::uint32_t>(std::lround(1 / config_.tick))).u32(clock_);
  return Status::Ok;
}

// Frames are handled in sequence. One that comes after a missing one is held (up to kHeld
// ahead) and the missing one asked for (kResendWanted with ack: the host sends the frame
// after ack again); when it comes, the held ones behind it are handled too. A frame handled
// already (sent again) is dropped. ResetAxes is taken whatever its seq: the host sends it
// when it gave up on a broken stream, and the count starts anew from it.
void EmulatedCard::on_stream_frame(std::span<const std::uint8_t> frame) noexcept {
  LinkReader r(frame);
  const std::uint8_t seq = r.u8();
  const auto op = static_cast<Op>(r.u8());
  if (!r.ok()) return on_damaged_frame();
  if (have_seq_ && seq != static_cast<std::uint8_t>(ack_ + 1) && op != Op::ResetAxes) {
    if (!card::seq_after(seq, ack_)) return;
    resend_wanted_ = true;
    if (static_cast<std::uint8_t>(seq - ack_) <= kHeld) {
      auto& slot = held_[seq % kHeld];
      std::copy(frame.begin(), frame.end(), slot.begin());
      held_len_[seq % kHeld] = static_cast<std::uint16_t>(frame.size());
    }
    return;
  }
  if (op == Op::ResetAxes) held_len_.fill(0);
  handle_in_sequence(frame);
  for (;;) {  // the held frames that follow it
    const auto next = static_cast<std::uint8_t>(ack_ + 1);
    auto& len = held_len_[next % kHeld];
    if (len == 0 || held_[next % kHeld][0] != next) break;
    const std::size_t n = len;
    len = 0;
    handle_in_sequence(std::span<const std::uint8_t>(held_[next % kHeld].data(), n));
  }
  resend_wanted_ = false;
  for (auto len : held_len_) resend_wanted_ = resend_wanted_ || len != 0;  // another is missing
}

void EmulatedCard::handle_in_sequence(std::span<const std::uint8_t> frame) noexcept {
  LinkReader r(frame);
  const std::uint8_t seq = r.u8();
  const auto op = static_cast<Op>(r.u8());
  have_seq_ = true;
  ack_ = seq;
  hal::LinkWriter reply;  // a stream command's reply data is not sent: status frames say it all
  const Status s = streaming_ ? answer(op, r, reply) : Status::NotReady;
  if (op == Op::ResetAxes && s == Status::Ok) frame_status_ = Status::Ok;  // refusals before it are done with
  else if (s != Status::Ok && frame_status_ == Status::Ok) frame_status_ = s;
}

// A host frame damaged: the frame after ack is asked for again; the buffered path runs on
// meanwhile (and brakes on itself, starved, when it does not come in time).
void EmulatedCard::on_damaged_frame() noexcept { resend_wanted_ = true; }

bool EmulatedCard::take_stream_frame(std::span<const std::uint8_t>& frame) noexcept {
  if (!outbox_ready_) return false;
  outbox_ready_ = false;
  frame = outbox_.bytes();
  return true;
}

void EmulatedCard::emit_status() noexcept {
  card::StatusFrame s;
  s.clock = clock_;
  s.ack = ack_;
  s.ack_status = static_cast<std::uint8_t>(frame_status_);
  frame_status_ = Status::Ok;
  s.flags = resend_wanted_ ? card::flag::kResendWanted : 0;
  for (int i = 0; i < 16; ++i) {  // the frames held after the missing one
    const auto seq = static_cast<std::uint8_t>(ack_ + 2 + i);
    if (held_len_[seq % kHeld] != 0 && held_[seq % kHeld][0] == seq) s.held |= static_cast<std::uint16_t>(1u << i);
  }
  s.starvations = static_cast<std::uint8_t>(std::min<unsigned long>(starvations_, 255));
  s.knots = static_cast<std::uint8_t>(knot_count_);
  if (following_) {
    const std::uint32_t last = knot_count_ > 0 ? knots_[(knot_head_ + knot_count_ - 1) % knots_.size()].tick : t1_;
    s.margin = card::tick_after(last, clock_) ? static_cast<std::uint16_t>(std::min<std::uint32_t>(last - clock_, 65535)) : 0;
  }
  s.mask = stream_mask_;
  for (int a = 0; a < kAxes; ++a) {
    if (!named(stream_mask_, a)) continue;
    s.position[a] = encoder(a);
    s.status[a] = status_word(a);
    s.inputs[a] = inputs(a);
    s.latched[a] = axes_[a].latched;
    if (axes_[a].latch_valid) s.flags |= card::flag::kLatchData;
  }
  if (analog_) {  // the probe reading of this tick: it pairs with the positions above
    s.flags |= card::flag::kDeflection;
    s.deflection = machine_.analog_reading().deflection;
    s.probe = probe_flags();
  }
  outbox_.clear();
  card::write_status(outbox_, s);
  outbox_ready_ = true;
}

// Segment: a setpoint the axes reach at card tick k.tick. The first one after rest starts
// from the command now; later ones queue behind the span being run.
Status EmulatedCard::segment(LinkReader& r) noexcept {
  if (!booted_ || !params_) return Status::NotReady;
  card::Knot k;
  if (auto s = card::read_knot(r, k); s != Status::Ok) return s;
  for (int a = 0; a < kAxes; ++a)
    if (named(k.mask, a) && std::abs(k.velocity[a]) > kSpeedMargin * axes_[a].vmax) return Status::BadValue;
  // A broken stream resumes only after ResetAxes. The card's axes only: a fault raised on
  // "every axis" also marks the unused entries, which ResetAxes's table never names.
  for (int a = 0; a < kAxes; ++a)
    if (axes_[a].faults & st::kFaultMask) return Status::NotReady;
  if (following_) {
    const std::uint32_t last = knot_count_ > 0 ? knots_[(knot_head_ + knot_count_ - 1) % knots_.size()].tick : t1_;
    if (!card::tick_after(k.tick, last)) return Status::BadValue;
    if (knot_count_ == static_cast<int>(knots_.size())) return Status::BadLength;
    knots_[(knot_head_ + knot_count_++) % knots_.size()] = k;
    return Status::Ok;
  }
  if (!card::tick_after(k.tick, clock_)) {  // due already: the host sent it too late
    ++starvations_;
    starved_ = true;
    return Status::Ok;
  }
  starved_ = false;
  bool any = false;
  for (int a = 0; a < kAxes; ++a) {
    Axis& ax = axes_[a];
    if (!named(k.mask, a) || !ax.closed) continue;
    ax.p0 = ax.profile.position();  // the command now: a running trapezoid is replaced
    ax.v0 = ax.profile.velocity();
    ax.p1 = k.position[a];
    ax.v1 = k.velocity[a];
    ax.following = any = true;
  }
  following_ = any;
  t0_ = clock_;
  t1_ = k.tick;
  return Status::Ok;
}

void EmulatedCard::knot_tick() noexcept {
  if (!following_) return;
  while (!card::tick_after(t1_, clock_)) {  // reached the setpoint at t1_
    if (knot_count_ == 0) {
      bool rest = true;
      for (const auto& ax : axes_) rest = rest && (!ax.following || ax.v1 == 0);
      if (!rest) {  // starved: the next setpoint did not come in time
        ++starvations_;
        starved_ = true;
        return brake_along_path();
      }
      for (auto& ax : axes_)
        if (ax.following) ax.profile.reset(ax.p1);
      following_ = false;
      for (auto& ax : axes_) ax.following = false;
      return;
    }
    const card::Knot& k = knots_[knot_head_];
    knot_head_ = (knot_head_ + 1) % static_cast<int>(knots_.size());
    --knot_count_;
    t0_ = t1_;
    t1_ = k.tick;
    for (int a = 0; a < kAxes; ++a) {
      Axis& ax = axes_[a];
      if (!ax.following) continue;
      ax.p0 = ax.p1;
      ax.v0 = ax.v1;
      ax.p1 = named(k.mask, a) ? k.position[a] : ax.p1;
      ax.v1 = named(k.mask, a) ? k.velocity[a] : 0.0;
    }
  }
  if (following_into_limit()) return end_following(true);
  const double span = static_cast<double>(t1_ - t0_) * config_.tick;
  track_cubic(static_cast<double>(clock_ - t0_) * config_.tick / span, span, 0);
}

// ShiftPosition: table, per axis f64 delta; the current position becomes position + delta.
Status EmulatedCard::shift_position(LinkReader& r) noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  hal::AxisArray<double> delta{};
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) delta[a] = r.f64();
  if (!r.ok() || !r.at_end()) return Status::BadLength;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a) && !std::isfinite(delta[a])) return Status::BadValue;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) shift_axis(a, axes_[a].offset - delta[a]);
  return Status::Ok;
}

}  // namespace imess::sim
