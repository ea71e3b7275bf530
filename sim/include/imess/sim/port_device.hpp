// PortDevice: simulated hardware behind the port space, sampled at the base rate;
// BaseTickPump: runs a driver's base routine and the device in lock-step base periods of
// virtual time up to the clock, before each servo-rate call — as SimLink brings the
// emulated card up to time. The driver code runs byte for byte as on real hardware.
#pragma once
#include <cstdint>

#include "imess/hal/base_rate.hpp"
#include "imess/hal/motion_backend.hpp"

namespace imess::sim {

class PortDevice {
 public:
  virtual ~PortDevice() = default;
  // Reads the outputs the driver wrote, advances the machine to t, writes the inputs back.
  virtual void sample(std::int64_t t_ns) noexcept = 0;
};

class BaseTickPump final : public hal::MotionBackend {
 public:
  // base may be nullptr (a driver without a base routine: the device alone is sampled).
  BaseTickPump(hal::MotionBackend& backend, hal::BaseRateDriver* base, PortDevice& device, const hal::Clock& clock,
               hal::Nanos period)
      : backend_(backend), base_(base), device_(device), clock_(clock), period_(period.count()) {}

  // Runs every base period up to t (at most 0.5 s of catch-up after a stall).
  void advance_to(hal::Nanos t) noexcept {
    std::int64_t now = t.count();
    if (!started_) {
      next_ = now;
      started_ = true;
    }
    if (now - next_ > kMaxCatchUp) next_ = now - kMaxCatchUp;
    while (next_ <= now) {
      if (base_) base_->base_tick();
      device_.sample(next_);
      next_ += period_;
      ++ticks_;
    }
  }
  std::uint64_t ticks() const noexcept { return ticks_; }

  void initialise(bool force_reboot) override {
    backend_.initialise(force_reboot);
    advance_to(clock_.now());
  }
  std::string describe() const override { return backend_.describe(); }
  bool read_state(hal::MachineState& out) noexcept override {
    advance_to(clock_.now());
    return backend_.read_state(out);
  }
  bool read_latch(hal::AxisVec& latched) noexcept override { return backend_.read_latch(latched); }
  bool set_loops(bool closed) noexcept override { return backend_.set_loops(closed); }
  bool move(const hal::AxisArray<hal::AxisMove>& moves, unsigned axis_mask) noexcept override {
    return backend_.move(moves, axis_mask);
  }
  bool follow(const hal::Setpoint& sp) noexcept override { return backend_.follow(sp); }
  bool stop(const hal::AxisVec& decel) noexcept override { return backend_.stop(decel); }
  bool set_position(int axis, double value) noexcept override { return backend_.set_position(axis, value); }
  bool reset_faults() noexcept override { return backend_.reset_faults(); }
  int output_count() const noexcept override { return backend_.output_count(); }
  bool set_output(int number, bool on) noexcept override { return backend_.set_output(number, on); }
  bool output_on(int number) const noexcept override { return backend_.output_on(number); }

 private:
  static constexpr std::int64_t kMaxCatchUp = 500'000'000;
  hal::MotionBackend& backend_;
  hal::BaseRateDriver* base_;
  PortDevice& device_;
  const hal::Clock& clock_;
  std::int64_t period_, next_ = 0;
  bool started_ = false;
  std::uint64_t ticks_ = 0;
};

}  // namespace imess::sim
