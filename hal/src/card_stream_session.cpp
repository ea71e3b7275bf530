// The driver's side of the card stream: status frames in, commands and timed setpoints out,
// the state laid over with what is still on its way, and the link watched for gaps.
#include "imess/hal/card_stream_session.hpp"

#include <algorithm>
#include <cmath>

#include "imess/hal/stream_frame.hpp"

namespace imess::hal {

using card::kAxes;

namespace {
constexpr unsigned kAllAxes = (1u << kAxes) - 1;
constexpr double kBitsPerByte = 10;  // start, 8 data, stop

std::uint32_t ticks(double seconds, std::uint32_t per_second) {
  return static_cast<std::uint32_t>(std::lround(seconds * per_second));
}
}  // namespace

void CardStreamSession::start(std::uint32_t ticks_per_second, std::uint32_t clock, const MachineState& state,
                              bool tip_reversed) noexcept {
  tip_reversed_ = tip_reversed;
  ticks_per_cycle_ = std::max<std::uint32_t>(1, ticks(settings_.period, ticks_per_second));
  status_ticks_ = std::max<std::uint32_t>(1, ticks(settings_.status_period, ticks_per_second));
  lead_ticks_ = ticks(settings_.lead, ticks_per_second);
  // A status frame is read up to a period after its last byte arrived, which took its length
  // on the line after it was sampled: half a period plus that, on average.
  const double bytes = kFrameOverhead + 13 + kAxes + 9.0 * kAxes + (state.deflection_valid ? 13 : 0);
  const double line = settings_.baud > 0 ? bytes * kBitsPerByte / settings_.baud : 0;
  delay_ticks_ = ticks(line + 0.5 * settings_.period, ticks_per_second);
  // A frame's ack comes with the next status frame after it arrives, which is on the line a
  // while and read in the next period: a status period, that, and two periods to spare.
  answer_cycles_ = static_cast<std::uint32_t>(std::ceil((settings_.status_period + line) / settings_.period)) + 2;
  status_line_cycles_ = static_cast<std::uint32_t>(std::ceil(line / settings_.period)) + 1;
  newest_ = card::StatusFrame{};
  newest_.clock = clock;
  newest_.mask = kAllAxes;
  for (int a = 0; a < kAxes; ++a) {
    newest_.position[a] = state.position[a];
    // A latch the card holds shows with the first status frame, which brings its positions.
    newest_.status[a] = state.status[a] & ~status::kLatchValid;
    newest_.inputs[a] = state.inputs[a];
  }
  if (state.deflection_valid) {  // a measuring probe: its reading comes with every status frame
    newest_.flags |= card::flag::kDeflection;
    newest_.deflection = state.deflection;
    newest_.probe = static_cast<std::uint8_t>(card::probe::kAnalogPresent |
                                              (state.probe_over_range ? card::probe::kOverRange : 0));
  }
  stream_status_ = comm_lost_ = link_broken_ = refused_ = following_ = false;
  seq_ = 0;
  cycle_ = status_cycle_ = 0;
  damaged_seen_ = false;
  line_free_ = 0;
  resend_tries_ = 0;
  resend_hold_ = 0;
  motion_ = loops_ = reset_ = latch_ = Pending{};
  shift_pending_ = {};
  shift_ = {};
}

bool CardStreamSession::pending(Pending& p) const noexcept {
  if (p.on && !card::seq_after(p.seq, newest_.ack)) p.on = false;
  return p.on;
}

void CardStreamSession::lost() noexcept {
  comm_lost_ = true;
  ++errors_;
}

void CardStreamSession::broken() noexcept {
  link_broken_ = true;
  ++errors_;
}

void CardStreamSession::take(std::span<const std::uint8_t> frame) noexcept {
  card::StatusFrame s;
  if (!card::read_status(frame, s)) return broken();
  // One went missing (lost, or damaged and counted already): counted, and this one is taken.
  if (stream_status_ && s.clock - newest_.clock != status_ticks_ && !damaged_since_) ++errors_;
  damaged_since_ = false;
  if (stream_status_ && s.starvations != newest_.starvations) {
    // Frames the card asked for again did not reach it within the lead: the line, not the host
    // (a frame only overdue may be the host's own stall, late status frames: HostStall).
    if (resend_tries_ > 0 && resend_asked_ && card::seq_after(resend_first_, s.ack)) {
      newest_ = s;
      return broken();
    }
    // A stall outlasted the lead: twice the lead from now.
    longest_gap_ = std::max(longest_gap_, (2 * lead() - settings_.status_period) / 1.5);
  }
  newest_ = s;
  stream_status_ = true;
  status_cycle_ = cycle_;
  ++status_frames_;
  // Until the card has a reset sent, what it reports is of the frames before it.
  if (pending(reset_)) return;
  if (s.ack_status != static_cast<std::uint8_t>(card::Status::Ok)) {  // the card refused a command
    refused_ = true;
    ++errors_;
  }
}

std::uint8_t CardStreamSession::first_unacked() const noexcept {
  // A reset on its way is sent again from itself: the card takes ResetAxes whatever its seq.
  return reset_.on ? reset_.seq : static_cast<std::uint8_t>(newest_.ack + 1);
}

bool CardStreamSession::resend_due() const noexcept {
  if (link_broken_ || comm_lost_ || !card::seq_after(seq_, newest_.ack)) return false;
  if (static_cast<std::int32_t>(cycle_ - resend_hold_) < 0) return false;  // the last resend is on its way
  // Overdue: the card talked on for three answers' time after the frame crossed the line (a
  // frame lost without a trace; the card asks at once for one it saw damaged or skipped). Three:
  // on a loaded host status frames come in late bursts, each read long after it was sampled.
  const bool overdue = static_cast<std::int32_t>(status_cycle_ - sent_at_[first_unacked()]) >
                       static_cast<std::int32_t>(3 * answer_cycles_);
  return card_asks() || overdue;
}

// Selective: the first frame the card has not acknowledged again, and those after it that the
// card does not hold.
bool CardStreamSession::card_asks() const noexcept {
  return !reset_.on && (newest_.flags & card::flag::kResendWanted) != 0;
}

void CardStreamSession::resend() noexcept {
  const std::uint8_t first = first_unacked();
  resend_asked_ = card_asks();
  resend_tries_ = first == resend_first_ && resend_tries_ > 0 ? resend_tries_ + 1 : 1;
  resend_first_ = first;
  ++errors_;  // the card saw a host frame damaged or missing (or its ack was)
  if (resend_tries_ > settings_.resend_tries || static_cast<std::uint8_t>(seq_ - first) >= kResendWindow) return broken();
  // It, and of the 16 after it those the card does not hold though they had crossed the line
  // when it sent its status frame.
  const std::uint8_t last = card::seq_after(seq_, static_cast<std::uint8_t>(first + 16)) ? static_cast<std::uint8_t>(first + 16) : seq_;
  for (std::uint8_t q = first;; ++q) {
    const int bit = static_cast<std::uint8_t>(q - first) - 1;  // -1: first itself
    const bool held = bit >= 0 && !reset_.on && (newest_.held >> bit & 1u);
    const bool crossed = static_cast<std::int32_t>(status_cycle_ - sent_at_[q]) > static_cast<std::int32_t>(status_line_cycles_);
    if (q == first || (!held && crossed)) {
      const auto slot = static_cast<std::size_t>(q % kResendWindow);
      if (!link_.send(std::span<const std::uint8_t>(kept_[slot].data(), kept_len_[slot]))) break;  // full: again later
      queue_on_line(kept_len_[slot]);
      sent_at_[q] = static_cast<std::uint32_t>(std::ceil(line_free_));
      ++frames_resent_;
    }
    if (q == last) break;
  }
  resend_hold_ = static_cast<std::uint32_t>(std::ceil(line_free_)) + answer_cycles_;
}

bool CardStreamSession::read_state(MachineState& out) noexcept {
  ++cycle_;
  for (;;) {
    const int n = link_.poll(rx_);
    if (n == 0) break;
    if (n < 0) {  // damaged: counted; the stream goes on with the next status frame
      ++errors_;
      damaged_since_ = true;
      damaged_cycle_ = cycle_;
      damaged_seen_ = true;
    } else
      take(std::span<const std::uint8_t>(rx_.data(), static_cast<std::size_t>(n)));
  }
  // The status frames stopped coming: the card is gone (CommLost) — or, while damaged frames
  // still arrive, the line damages them all (LinkErrors).
  if (!comm_lost_ && !link_broken_ && silent()) {
    if (damaged_seen_ && cycle_ - damaged_cycle_ <= 2 * answer_cycles_) broken();
    else lost();
  }
  if (resend_tries_ > 0 && !card::seq_after(resend_first_, newest_.ack)) resend_tries_ = 0;  // through
  if (resend_due()) resend();

  const bool reset = pending(reset_), loops = pending(loops_), motion = pending(motion_), latch = pending(latch_);
  out.count = kAxes;
  for (int a = 0; a < kAxes; ++a) {
    if (!pending(shift_pending_[a])) shift_[a] = 0;
    out.position[a] = newest_.position[a] + shift_[a];
    out.inputs[a] = newest_.inputs[a];
    std::uint32_t s = newest_.status[a];
    if (reset) s &= ~(status::kFaultMask | status::kClosedLoop);
    if (loops) s = loops_closed_ ? s | status::kClosedLoop : s & ~status::kClosedLoop;
    if (motion) s &= ~(status::kProfileEnd | status::kInPosition | status::kHostStarved);
    if (latch) s &= ~status::kLatchValid;
    if (comm_lost_) s |= status::kCommTimeout;
    if (link_broken_) s |= status::kLinkErrors;
    if (refused_) s |= status::kDataError;
    out.status[a] = s;
  }
  // The deflection sampled with the positions of the same status frame.
  out.deflection_valid = (newest_.flags & card::flag::kDeflection) && (newest_.probe & card::probe::kAnalogPresent);
  out.deflection = out.deflection_valid ? newest_.deflection : Vec3::Zero();
  out.probe_over_range = out.deflection_valid && (newest_.probe & card::probe::kOverRange);
  const bool contact = (out.inputs[0] & input::kTip) != 0;  // wired to every module; axis 0 carries it
  out.tip_touched = tip_reversed_ ? !contact : contact;
  return true;
}

bool CardStreamSession::send(std::span<const std::uint8_t> op_frame) noexcept {
  frame_.clear();
  frame_.u8(static_cast<std::uint8_t>(seq_ + 1));
  for (std::uint8_t b : op_frame) frame_.u8(b);
  if (!frame_.ok() || !link_.send(frame_.bytes())) {
    ++errors_;
    return false;
  }
  ++seq_;
  const auto slot = static_cast<std::size_t>(seq_ % kResendWindow);  // kept for a resend
  std::copy(frame_.bytes().begin(), frame_.bytes().end(), kept_[slot].begin());
  kept_len_[slot] = static_cast<std::uint16_t>(frame_.bytes().size());
  queue_on_line(frame_.bytes().size());
  sent_at_[seq_] = static_cast<std::uint32_t>(std::ceil(line_free_));
  ++frames_sent_;
  return true;
}

// A frame's acknowledgement is awaited from when its last byte crosses the line: behind the
// frames still queued before it, at the baud rate.
void CardStreamSession::queue_on_line(std::size_t payload_bytes) noexcept {
  const double on_line = settings_.baud > 0 ? static_cast<double>(payload_bytes + kFrameOverhead) * kBitsPerByte /
                                                  settings_.baud / settings_.period
                                            : 0.0;
  line_free_ = std::max(line_free_, static_cast<double>(cycle_)) + on_line;
}

bool CardStreamSession::command(std::span<const std::uint8_t> op_frame, Effect effect) noexcept {
  if (!send(op_frame)) return false;
  const Pending now{true, seq_};
  switch (effect) {
    case Effect::None: break;
    case Effect::Motion:
      motion_ = now;
      following_ = false;
      break;
    case Effect::CloseLoops:
    case Effect::OpenLoops:
      loops_ = now;
      loops_closed_ = effect == Effect::CloseLoops;
      following_ = following_ && loops_closed_;
      break;
    case Effect::Reset:
      reset_ = now;
      loops_ = Pending{};
      following_ = comm_lost_ = link_broken_ = refused_ = false;
      resend_tries_ = 0;
      stream_status_ = false;  // a gap before the reset is not held against the frames after it
      status_cycle_ = cycle_;
      break;
    case Effect::ClearLatch: latch_ = now; break;
  }
  return true;
}

double CardStreamSession::lead() const noexcept {
  return std::clamp(1.5 * longest_gap_ + settings_.status_period, settings_.lead, std::max(settings_.lead, settings_.max_lead));
}

std::uint32_t CardStreamSession::card_now() const noexcept {
  return newest_.clock + delay_ticks_ + (cycle_ - status_cycle_) * ticks_per_cycle_;
}

bool CardStreamSession::follow(const Setpoint& sp) noexcept {
  const bool fresh = !following_ || cycle_ != follow_cycle_ + 1;  // a new path (or a gap in one)
  follow_cycle_ = cycle_;
  if (sp.time >= 0) {  // the host's stalls, seen as the path time's steps (halved over ~70 s of following)
    if (!fresh && last_time_ >= 0) longest_gap_ = std::max(longest_gap_ * 0.99999, sp.time - last_time_);
    last_time_ = sp.time;
  }
  if (fresh) {
    lead_ticks_ = static_cast<std::uint32_t>(std::lround(lead() * ticks_per_cycle_ / settings_.period));
    std::uint32_t start = card_now() + lead_ticks_;
    if (knots_sent_ > 0 && !card::tick_after(start, last_knot_tick_)) start = last_knot_tick_ + ticks_per_cycle_;
    base_tick_ = start;
    base_cycle_ = cycle_;
    base_time_ = sp.time;
    last_knot_n_ = 0;
    following_ = true;
  }
  // The periods since the path began: by the setpoint's path time when it has one (a stalled
  // host's next setpoint counts every period it missed, while the card ran the path on its
  // own clock), else one a cycle.
  const std::uint32_t n = sp.time >= 0 ? static_cast<std::uint32_t>(std::max(0L, std::lround((sp.time - base_time_) / settings_.period)))
                                       : cycle_ - base_cycle_;
  const bool rest = sp.velocity.isZero(0);
  const bool due = fresh || n - last_knot_n_ >= static_cast<std::uint32_t>(settings_.segment_cycles) || (rest && !last_knot_rest_);
  if (!due) return !comm_lost_;
  card::Knot k;
  k.tick = base_tick_ + n * ticks_per_cycle_;
  k.mask = kAllAxes;
  for (int a = 0; a < kAxes; ++a) {
    k.position[a] = sp.position[a];
    k.velocity[a] = sp.velocity[a];
  }
  LinkWriter w;
  w.u8(static_cast<std::uint8_t>(card::Op::Segment));
  card::write_knot(w, k);
  if (!send(w.bytes())) {
    lost();
    return false;
  }
  if (fresh) motion_ = Pending{true, seq_};
  last_knot_n_ = n;
  last_knot_tick_ = k.tick;
  last_knot_rest_ = rest;
  ++knots_sent_;
  return !comm_lost_;
}

bool CardStreamSession::latched(AxisVec& out) noexcept {
  if (!(newest_.flags & card::flag::kLatchData)) return false;
  for (int a = 0; a < kAxes; ++a) out[a] = newest_.latched[a] + (pending(shift_pending_[a]) ? shift_[a] : 0.0);
  return true;
}

double CardStreamSession::shift_for(int axis, double value) noexcept {
  const double shown = newest_.position[axis] + (pending(shift_pending_[axis]) ? shift_[axis] : 0.0);
  return value - shown;
}

void CardStreamSession::note_shift(int axis, double delta) noexcept {
  shift_[axis] = (pending(shift_pending_[axis]) ? shift_[axis] : 0.0) + delta;
  shift_pending_[axis] = Pending{true, seq_};
}

}  // namespace imess::hal
