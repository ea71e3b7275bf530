// ServoCardDriver: the MotionBackend for an MCU-style servo card that closes the position
// loops and runs trapezoid profiles or follows per-period setpoints itself; spoken to only
// through a Link (request/reply) and, when it has one, a StreamLink: then set-up still uses
// the Link, and every real-time call goes through the stream without waiting for the card
// (CardStreamSession: timed setpoints ahead, periodic status frames).
#pragma once
#include <atomic>
#include <optional>
#include <string>

#include "imess/hal/card_stream_session.hpp"

#include "imess/hal/link.hpp"
#include "imess/hal/link_codec.hpp"
#include "imess/hal/motion_backend.hpp"
#include "imess/hal/servo_card_protocol.hpp"

namespace imess::hal {

struct ServoCardConfig {
  std::string firmware = "IMESS-MCU 1.0";   // revision the daemon requires
  AxisArray<double> max_velocity{150, 150, 150};       // mm/s, card-side limit
  AxisArray<double> max_accel{1000, 1000, 1000};       // mm/s²
  AxisArray<double> max_following_error{5, 5, 5};     // mm
  bool tip_reversed = false;                          // probe switch opens on contact
  int boot_retries = 3;
  StreamSettings stream;                              // used when the driver has a StreamLink
  // A card on a line that can come back (a serial device): reset_faults() while the card is
  // silent asks for a re-boot (reboot_wanted()), which a set-up thread runs (reboot()).
  bool reboot_on_reset = false;
};

class ServoCardDriver final : public MotionBackend {
 public:
  ServoCardDriver(Link& link, ServoCardConfig config, StreamLink* stream = nullptr);

  void initialise(bool force_reboot) override;
  std::string describe() const override;

  bool read_state(MachineState& out) noexcept override;
  bool read_latch(AxisVec& latched) noexcept override;
  bool set_loops(bool closed) noexcept override;
  bool move(const AxisArray<AxisMove>& moves, unsigned axis_mask) noexcept override;
  // One Follow frame: the setpoint out, the card's state back in the same round trip; the
  // next read_state() returns that state (as of this call) without touching the link. A
  // failed exchange latches a communication timeout (status bit 0 on every axis: the core's
  // CommLost) until reset_faults(): a setpoint stream with a gap cannot be resumed.
  bool follow(const Setpoint& sp) noexcept override;
  // Request/reply: the firmware goes on at the last Follow's velocity until its watchdog.
  // Streamed: the card runs the buffered path on its own clock through a host stall; the
  // knots are stamped by the setpoints' path time.
  PathTime path_time() const noexcept override { return session_ ? PathTime::OwnClock : PathTime::Bridged; }
  double path_lead_s() const noexcept override;
  bool ready_for_command() const noexcept override { return !session_ || session_->line_ready(); }
  bool stop(const AxisVec& decel) noexcept override;
  bool set_position(int axis, double value) noexcept override;
  // On the stream, with reboot_on_reset, while no status frame comes (the card was gone): asks
  // for reboot() and reports a quiet machine (loops open, last positions) until it is done.
  bool reset_faults() noexcept override;
  unsigned long link_errors() const noexcept override;

  // The re-boot of a card that came back (set-up: call from a thread of its own, never the
  // motion thread; it blocks for the set-up exchanges). Runs initialise(false) while every
  // real-time call answers from the last state; on failure the machine shows CommLost again
  // and the message is returned. "" on success.
  bool reboot_wanted() const noexcept { return phase_.load(std::memory_order_acquire) == kRebootWanted; }
  std::string reboot();
  // Output 1 powers the probe (card::output::kProbeOn on every axis module; initialise()
  // switches it on). Op::WriteOutputs with the limit and reference switches on, request/reply
  // or on the stream; nothing else (set_loops, reset_faults) writes the outputs.
  int output_count() const noexcept override { return 1; }
  bool set_output(int number, bool on) noexcept override;
  bool output_on(int number) const noexcept override { return number == 1 && probe_on_.load(std::memory_order_relaxed); }
  bool probe_power() const noexcept { return probe_on_.load(std::memory_order_relaxed); }

  // Link transactions that failed or were refused since start (for Stats and -dt).
  unsigned long errors() const noexcept { return errors_ + (session_ ? session_->errors() : 0); }
  // The card's probe is a measuring one (ReadInfo's probe type): every state carries its
  // deflection (MachineState::deflection_valid).
  bool analog_probe() const noexcept { return analog_; }
  // The stream's side, when the driver has one (counters for tests and Stats).
  const CardStreamSession* stream() const noexcept { return session_ ? &*session_ : nullptr; }

 private:
  LinkWriter& begin(card::Op op) noexcept;
  void table(unsigned axis_mask) noexcept;
  // Sends writer_, checks the status byte; on success reply_ holds the payload after it.
  bool exchange(std::span<const std::uint8_t>& payload) noexcept;
  bool simple() noexcept;
  // A real-time command: on the stream when there is one, else a request/reply exchange.
  bool command(CardStreamSession::Effect effect) noexcept;
  void start_stream();
  bool parse_state(std::span<const std::uint8_t> payload, MachineState& out) noexcept;
  [[noreturn]] void fail(const std::string& what) const;
  void set_up_call(const char* what);

  Link& link_;
  ServoCardConfig config_;
  StreamLink* stream_link_;
  std::optional<CardStreamSession> session_;
  LinkWriter writer_;
  std::array<std::uint8_t, kMaxFrame> reply_{};
  std::string revision_;
  unsigned long errors_ = 0;
  MachineState followed_{};     // the state that came back with the last Follow frame
  bool have_followed_ = false;  // not yet returned by read_state()
  bool comm_lost_ = false;      // a Follow frame failed: report kCommTimeout until reset
  bool analog_ = false;         // ReadInfo: a measuring probe; LoadParams enabled its reading
  // Output 1 as last written (initialise(): on); atomic: a re-boot writes it while the motion
  // thread may read it.
  std::atomic<bool> probe_on_{false};
  // Re-boot hand-over between the motion thread (Running) and the set-up thread.
  static constexpr int kRunning = 0, kRebootWanted = 1, kRebooting = 2;
  std::atomic<int> phase_{kRunning};
  bool reboot_failed_ = false;  // the last reboot() failed: CommLost until the next
  MachineState last_{};         // the last state handed to the core (answered while re-booting)
  mutable unsigned long last_errors_ = 0;  // link_errors() as last read outside a re-boot
  bool rebooting() const noexcept { return phase_.load(std::memory_order_acquire) != kRunning; }
};

}  // namespace imess::hal
