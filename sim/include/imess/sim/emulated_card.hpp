// EmulatedCard: an MCU-style servo card answering the link protocol of
// hal/servo_card_protocol.hpp. Its firmware closes the position loops, runs trapezoid
// profiles or follows the host's per-period setpoints, stops axes at limit switches,
// watches the following error and latches all axes on the probe edge; the Mechanics
// behind it is the machine. Probe edges latch only while axis 0's kProbeOn output bit is
// set (the probe powered). Switching the probe's power on or off makes an edge of its own,
// as a real touch probe's does (DirectCMM's STARTUP/SHUTDOWN modes exist for it): whenever
// Op::WriteOutputs changes axis 0's kProbeOn bit — the first power-on at initialisation
// included — every axis latches where it stands, unless a latch is already held
// (CardConfig::probe_power_edges: false leaves power changes without an edge). Once
// streaming (Op::StartStream) it also takes host frames on a stream — timed setpoints
// (Op::Segment) executed on its own clock — and sends a status frame every status period
// (emulated_card_stream.cpp).
#pragma once
#include <array>
#include <span>
#include <string>

#include "imess/hal/card_stream.hpp"
#include "imess/hal/link.hpp"
#include "imess/hal/link_codec.hpp"
#include "imess/hal/servo_card_protocol.hpp"
#include "imess/sim/mechanics.hpp"
#include "imess/hal/trapezoid_planner.hpp"

namespace imess::sim {

struct CardConfig {
  std::string firmware = "IMESS-MCU 1.0";  // the revision this card boots into
  double tick = 0.0001;                    // s, firmware servo period (10 kHz)
  double position_gain = 60;               // 1/s, velocity demand per mm of following error
  double velocity_feedforward = 0.9;       // fraction of the profile velocity fed forward
  double encoder_resolution = 0.0001;      // mm per count
  double in_position_window = 0.005;       // mm
  bool absolute_scales = true;             // false: counters read 0 where the machine stands at power-on
  double follow_period = 0.001;            // s, the host period assumed until Follow frames measured it
  double follow_watchdog = 0.005;          // s, no Follow frame for this long (and 1.5 host periods): CommLost
  bool probe_power_edges = true;           // switching the probe's power (kProbeOn) latches, as a real probe's edge
};

class EmulatedCard {
 public:
  EmulatedCard(CardConfig config, Mechanics& machine);

  // Runs the firmware and the machine up to time t (seconds since power-on).
  void advance_to(double t) noexcept;
  // Handles one link request; returns the reply length (-1: the reply does not fit).
  int handle(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept;

  // The stream (a transport such as sim::TimedCardLink calls these between ticks).
  // One firmware tick (after advance_to has set the card's time once).
  void step() noexcept;
  double tick_period() const noexcept { return config_.tick; }
  // A host frame {seq, op, arguments} that arrived intact / a frame that failed its CRC.
  void on_stream_frame(std::span<const std::uint8_t> frame) noexcept;
  void on_damaged_frame() noexcept;
  // Frames held after a missing one, until it comes again.
  static constexpr int kHeld = 16;
  // The status frame the last tick produced, if it produced one (valid until the next tick).
  bool take_stream_frame(std::span<const std::uint8_t>& frame) noexcept;
  // Counters for tests: setpoint buffer underruns, setpoints buffered, the card clock.
  unsigned long starvations() const noexcept { return starvations_; }
  int knots_buffered() const noexcept { return knot_count_; }
  std::uint32_t clock() const noexcept { return clock_; }

 private:
  struct Axis {
    hal::TrapezoidPlanner profile;  // the firmware runs the same profile law as the host planners
    bool closed = false;
    double vmax = 100, amax = 1000, max_following_error = 5;
    double offset = 0;     // world - machine coordinate
    std::uint32_t faults = 0;
    bool latch_valid = false;
    double latched = 0;
    std::uint8_t outputs = 0;
    // Following (Op::Follow): a cubic from the command when the last setpoint arrived
    // (p0, v0) to that setpoint (p1, v1) over follow_span_; profile tracks the command.
    bool following = false;
    double p0 = 0, v0 = 0, p1 = 0, v1 = 0;
  };

  void tick() noexcept;
  double encoder(int a) const noexcept;
  double quantise(double mm) const noexcept;
  std::uint32_t status_word(int a) const noexcept;
  std::uint8_t inputs(int a) const noexcept;
  void open_all() noexcept;
  // Following: per tick the interpolated command of every following axis; ends on arrival
  // at rest, brakes at amax when the setpoints stop coming (kCommTimeout) or a limit closes.
  void follow_tick() noexcept;
  void end_following(bool brake) noexcept;
  void brake_along_path() noexcept;  // starved: all following axes to rest together
  // The cubic Hermite from (p0, v0) to (p1, v1) of every following axis at s of span
  // seconds (s = 1 at the end), going on at v1 for late seconds past it.
  void track_cubic(double s, double span, double late) noexcept;
  bool following_into_limit() const noexcept;
  // Streaming: per tick the interpolated command between timed setpoints; on arrival at the
  // last one at rest following ends, without one (starved) the axes brake along the path
  // and report kHostStarved until the next motion command.
  void knot_tick() noexcept;
  void handle_in_sequence(std::span<const std::uint8_t> frame) noexcept;
  void emit_status() noexcept;
  void shift_axis(int a, double new_offset) noexcept;
  // Every axis latched where it stands now (unless a latch is held): a probe power edge.
  void latch_here() noexcept;
  void write_state(unsigned mask, hal::LinkWriter& out) const noexcept;
  // The measuring probe: fitted (sim.probe.type analog), its reading's flags
  // (hal::card::probe) and the reading as the link carries it (u8 flags, f64 dx, dy, dz).
  bool analog_probe() const noexcept;
  std::uint8_t probe_flags() const noexcept;
  void write_probe(hal::LinkWriter& out) const noexcept;

  // The link operations (hal/servo_card_protocol.hpp), one each: read the request's
  // arguments from r, act, append the reply's data to out; Status::Ok or the refusal.
  using Op = hal::card::Op;
  using Status = hal::card::Status;
  Status answer(Op op, hal::LinkReader& r, hal::LinkWriter& out) noexcept;
  Status ready_axis_table(hal::LinkReader& r, unsigned& mask) const noexcept;
  Status read_info(hal::LinkReader& r, hal::LinkWriter& out) const noexcept;
  Status boot(hal::LinkReader& r) noexcept;
  Status load_params(hal::LinkReader& r) noexcept;
  Status set_loops(Op op, hal::LinkReader& r) noexcept;
  Status jog_absolute(hal::LinkReader& r) noexcept;
  Status jog_stop(hal::LinkReader& r) noexcept;
  Status set_position(hal::LinkReader& r) noexcept;
  Status follow(hal::LinkReader& r, hal::LinkWriter& out) noexcept;
  Status read_state(hal::LinkReader& r, hal::LinkWriter& out) const noexcept;
  Status read_latch(hal::LinkReader& r, hal::LinkWriter& out) noexcept;
  Status read_probe(hal::LinkReader& r, hal::LinkWriter& out) const noexcept;
  Status write_outputs(hal::LinkReader& r) noexcept;
  Status shift_position(hal::LinkReader& r) noexcept;
  Status start_stream(hal::LinkReader& r, hal::LinkWriter& out) noexcept;
  Status segment(hal::LinkReader& r) noexcept;

  CardConfig config_;
  Mechanics& machine_;
  hal::AxisArray<Axis> axes_{};
  double time_ = 0;
  bool running_ = false;  // time_ set by the first advance_to
  bool booted_ = false, params_ = false, latch_on_falling_ = false;
  bool analog_ = false;  // LoadParams' analog: the probe reading ends ReadState/Follow replies and status frames
  bool following_ = false;   // some axis follows setpoints
  double follow_age_ = 0;    // s since the last setpoint arrived
  double follow_span_ = 0;   // s, the host period: measured between Follow frames (averaged)

  // Streaming.
  std::uint32_t clock_ = 0;  // ticks since power-on
  bool streaming_ = false;
  unsigned stream_mask_ = 0;
  std::uint32_t status_ticks_ = 50, since_status_ = 0;
  bool have_seq_ = false, resend_wanted_ = false;
  std::array<std::array<std::uint8_t, hal::kMaxFrame>, kHeld> held_{};  // by seq modulo kHeld
  std::array<std::uint16_t, kHeld> held_len_{};                         // 0: none held there
  std::uint8_t ack_ = 0;
  Status frame_status_ = Status::Ok;  // the first refusal since the last status frame
  unsigned long starvations_ = 0;
  bool starved_ = false;  // kHostStarved: set by a starvation, cleared by the next motion command or ResetAxes
  // Timed setpoints: the span being interpolated (ticks t0_ to t1_, the axes' p0/v0 to
  // p1/v1) and those buffered behind it.
  std::uint32_t t0_ = 0, t1_ = 0;
  std::array<hal::card::Knot, 64> knots_{};
  int knot_head_ = 0, knot_count_ = 0;
  hal::LinkWriter outbox_;
  bool outbox_ready_ = false;
};

// The transport to the emulated card: brings the card up to the clock's time, then lets
// it answer. This is the seam where a serial line to a real card would sit.
class SimLink final : public hal::Link {
 public:
  SimLink(EmulatedCard& card, const hal::Clock& clock) : card_(card), clock_(clock) {}
  int transact(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept override {
    card_.advance_to(hal::seconds(clock_.now()));
    return card_.handle(request, reply);
  }

 private:
  EmulatedCard& card_;
  const hal::Clock& clock_;
};

}  // namespace imess::sim
