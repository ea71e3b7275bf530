// CardStreamSession: the driver's side of the servo card's stream (docs/servo-card-link.md,
// "Streaming"). Nothing here waits for the card: commands and timed setpoints are queued on
// the StreamLink, the card's periodic status frames are taken as they arrive, and the state
// handed to the motion core is the newest status frame with what the frames still on their
// way will change laid over it (a move sent clears "profile end" until the card has it). A
// lost or damaged status frame is counted (errors()) and the stream goes on with the next
// one; status frames that stop coming latch a communication timeout
// (status bit 0 on every axis, the core's CommLost). A host frame the card saw damaged or
// missing (it asks for the frame after its ack again, holding those that came after it), or
// did not acknowledge in time, is sent again (from the last kResendWindow frames kept);
// the same frame still not through after resend_tries, a frame no longer kept, a card that
// starved while a resend was under way or a malformed status frame latch status::kLinkErrors
// (the core's LinkErrors) — each until reset(). A starved card (the host stalled longer than
// the lead) is no fault: it reports kHostStarved. Real-time calls are noexcept and allocate
// nothing.
#pragma once
#include <array>
#include <cstdint>

#include "imess/hal/card_stream.hpp"
#include "imess/hal/motion_backend.hpp"
#include "imess/hal/stream_link.hpp"

namespace imess::hal {

struct StreamSettings {
  double period = 0.001;          // s, the motion period: one read_state() per period
  double status_period = 0.005;   // s, the card's status frames
  int segment_cycles = 4;         // a timed setpoint every this many periods (and when the path comes to rest)
  // s, setpoints are stamped at least this far ahead of the card's clock: the longest stall of
  // the host it rides out (docs/servo-card-link.md, "Host stalls": measured, then chosen).
  double lead = 0.060;
  double max_lead = 0.200;        // s, the most the lead grows to after longer stalls (the card buffers 64 knots)
  double baud = 115200;           // the line, for the age of a status frame when it is read (0: no delay)
  int timeout_cycles = 20;        // periods without a status frame: CommLost
  int resend_tries = 8;           // a frame sent again this often and still not acknowledged: LinkErrors
};

// Host frames kept for sending again: 64 frames, 256 ms of setpoints (more than the longest lead).
inline constexpr int kResendWindow = 64;

class CardStreamSession {
 public:
  CardStreamSession(StreamLink& link, StreamSettings settings) : link_(link), settings_(settings) {}

  // Set-up (after StartStream): the card's ticks per second, its clock and state right now.
  void start(std::uint32_t ticks_per_second, std::uint32_t clock, const MachineState& state, bool tip_reversed) noexcept;

  // The newest state (see above). False never: a dead link shows as CommLost.
  bool read_state(MachineState& out) noexcept;
  // Queues one command (op and arguments, built by the driver); what it will change is laid
  // over the state until the card acknowledges it. False: the transmit queue is full.
  enum class Effect { None, Motion, CloseLoops, OpenLoops, Reset, ClearLatch };
  bool command(std::span<const std::uint8_t> op_frame, Effect effect) noexcept;
  // The setpoint of this period, stamped with the card tick it is due at; sent every
  // segment_cycles periods and when the path comes to rest.
  bool follow(const Setpoint& sp) noexcept;
  // The latched positions of the newest status frame; false when it carries none.
  bool latched(AxisVec& out) noexcept;
  // Positions are redefined relatively on the stream (Op::ShiftPosition, exact however old
  // the newest status frame is): the delta that makes axis read value now, and, once its
  // command is queued, the note that lays it over the positions until the card has it.
  double shift_for(int axis, double value) noexcept;
  void note_shift(int axis, double delta) noexcept;

  // For tests, Stats and the bench.
  const card::StatusFrame& newest() const noexcept { return newest_; }
  unsigned long frames_sent() const noexcept { return frames_sent_; }
  unsigned long status_frames() const noexcept { return status_frames_; }
  unsigned long knots_sent() const noexcept { return knots_sent_; }
  unsigned long errors() const noexcept { return errors_; }
  unsigned long frames_resent() const noexcept { return frames_resent_; }
  bool comm_lost() const noexcept { return comm_lost_; }
  bool link_broken() const noexcept { return link_broken_; }
  // No status frame for more than timeout_cycles periods: the card is gone (or stalled), or the
  // line damages every frame.
  bool silent() const noexcept { return cycle_ - status_cycle_ > static_cast<std::uint32_t>(settings_.timeout_cycles); }
  unsigned starvations() const noexcept { return newest_.starvations; }
  // The lead the next path gets: the configured one, or 1.5 × the longest stall seen while
  // following lately plus a status period, when that is more (at most max_lead); a card that
  // starved doubles it.
  double lead() const noexcept;
  // The line carries at most a motion period of frames not yet sent (by the baud rate).
  bool line_ready() const noexcept { return line_free_ <= static_cast<double>(cycle_) + 1.0; }
  double longest_stall() const noexcept { return longest_gap_; }

 private:
  struct Pending {
    bool on = false;
    std::uint8_t seq = 0;
  };
  bool send(std::span<const std::uint8_t> op_frame) noexcept;
  void queue_on_line(std::size_t payload_bytes) noexcept;  // sent_at_[seq_] and line_free_ for a frame queued now
  bool resend_due() const noexcept;  // the card asked for frames again, or one is overdue
  bool card_asks() const noexcept;   // the newest status frame wants a frame again
  void resend() noexcept;            // the frames from the first not acknowledged on, again
  std::uint8_t first_unacked() const noexcept;
  void take(std::span<const std::uint8_t> frame) noexcept;
  void lost() noexcept;    // the card went quiet or starved: CommLost
  void broken() noexcept;  // the link lost a frame the stream cannot do without: LinkErrors
  bool pending(Pending& p) const noexcept;  // clears p once the card has acknowledged it
  std::uint32_t card_now() const noexcept;  // the card clock, estimated

  StreamLink& link_;
  StreamSettings settings_;
  bool tip_reversed_ = false;
  std::uint32_t ticks_per_cycle_ = 10, status_ticks_ = 50, lead_ticks_ = 120, delay_ticks_ = 0;
  LinkWriter frame_;
  std::array<std::uint8_t, kMaxFrame> rx_{};
  std::uint8_t seq_ = 0;                     // of the last frame sent
  std::array<std::uint32_t, 256> sent_at_{};  // the cycle each sequence number crossed the line
  // The frames kept for a resend (payload with its seq), by seq modulo the window.
  std::array<std::array<std::uint8_t, kMaxFrame>, kResendWindow> kept_{};
  std::array<std::uint16_t, kResendWindow> kept_len_{};
  std::uint8_t resend_first_ = 0;   // the first frame of the last resend
  int resend_tries_ = 0;            // resends from resend_first_ so far (0: none under way)
  bool resend_asked_ = false;       // the card asked for them (else they were only overdue)
  std::uint32_t resend_hold_ = 0;   // no resend before this cycle: the last one's frames are on their way
  std::uint32_t answer_cycles_ = 0; // periods from a frame crossing the line to its ack at the host
  std::uint32_t status_line_cycles_ = 0;  // periods from a status frame's sample to its reading here
  card::StatusFrame newest_{};
  bool stream_status_ = false;  // newest_ came on the stream (not from set-up)
  bool damaged_since_ = false;  // a damaged frame came since the last status frame (already counted)
  std::uint32_t cycle_ = 0, status_cycle_ = 0, damaged_cycle_ = 0;
  bool damaged_seen_ = false;  // a damaged frame came (at damaged_cycle_)
  bool comm_lost_ = false, link_broken_ = false, refused_ = false;
  Pending motion_, loops_, reset_, latch_;
  bool loops_closed_ = false;
  AxisArray<Pending> shift_pending_{};
  AxisArray<double> shift_{};
  // Following: the path's tick for cycle base_cycle_, the last follow() cycle, the last knot.
  bool following_ = false;
  std::uint32_t base_tick_ = 0, base_cycle_ = 0, follow_cycle_ = 0, last_knot_tick_ = 0, last_knot_n_ = 0;
  double base_time_ = 0;  // s: the path time (Setpoint::time) of the path's first knot
  double last_time_ = -1;  // s: the path time of the last follow(); -1 none
  double line_free_ = 0;   // the cycle (fractional) by which every frame sent has crossed the line
  double longest_gap_ = 0;  // s: the longest path step between two follow() calls lately (decays)
  bool last_knot_rest_ = false;
  unsigned long frames_sent_ = 0, status_frames_ = 0, knots_sent_ = 0, errors_ = 0, frames_resent_ = 0;
};

}  // namespace imess::hal
