// EmulatedCard: an MCU-style servo card answering the link protocol of
// hal/servo_card_protocol.hpp. Its firmware closes the position loops, runs trapezoid
// profiles, stops axes at limit switches, watches the following error and latches all
// axes on the probe edge; the Mechanics behind it is the machine.
#pragma once
#include <span>
#include <string>

#include "imess/hal/link.hpp"
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
};

class EmulatedCard {
 public:
  EmulatedCard(CardConfig config, Mechanics& machine);

  // Runs the firmware and the machine up to time t (seconds since power-on).
  void advance_to(double t) noexcept;
  // Handles one link request; returns the reply length.
  int handle(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept;

  double time() const noexcept { return time_; }
  Mechanics& machine() noexcept { return machine_; }
  unsigned long requests() const noexcept { return requests_; }

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
  };

  void tick() noexcept;
  double encoder(int a) const noexcept;
  double quantise(double mm) const noexcept;
  std::uint32_t status_word(int a) const noexcept;
  std::uint8_t inputs(int a) const noexcept;
  void open_all() noexcept;

  CardConfig config_;
  Mechanics& machine_;
  hal::AxisArray<Axis> axes_{};
  double time_ = 0;
  bool running_ = false;  // time_ set by the first advance_to
  bool booted_ = false, params_ = false, latch_on_falling_ = false;
  unsigned long requests_ = 0;
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
