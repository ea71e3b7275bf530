// StepGenerator: the base-period pulse maker of the step/dir backend (LinuxCNC's stepgen
// split). The servo side hands each axis an integer target step count and a rate; every
// base period tick() advances a 32.32 fixed-point accumulator and emits at most one step
// edge per axis, honouring step length, step space, direction setup and hold in whole base
// periods. Integer only, no allocation, no locks: the servo side and the base side share
// only atomics, so tick() may run in its own faster thread.
#pragma once
#include <atomic>
#include <cstdint>

#include "imess/hal/parport_pins.hpp"
#include "imess/hal/types.hpp"

namespace imess::hal {

// Pulse timing in base periods (each >= 1, so step and dir never change in the same tick).
struct StepTiming {
  std::uint32_t step_len = 1, step_space = 1, dir_setup = 1, dir_hold = 1;
};

class StepGenerator {
 public:
  static constexpr std::uint64_t kOne = 1ull << 32;  // one step in the accumulator

  void configure(const CompiledPins& pins, const StepTiming& timing) noexcept;

  // ---- servo side (any thread but the base one; one writer) ----
  // Drive axis toward target at rate (steps per base period × 2^32, capped at max_rate()).
  // centred: an axis that sets off from its target starts its accumulator at half a step
  // instead of 0, so the steps fall in the middle of their intervals, not at their ends
  // (path following: the count is then the path rounded, not floored).
  void command(int axis, std::int64_t target, std::uint64_t rate, bool centred = false) noexcept;
  std::int64_t count(int axis) const noexcept { return axes_[axis].count.load(std::memory_order_acquire); }
  // The fastest rate the pulse timing allows: one step per (step_len + step_space) periods.
  // Rounded up, so that n ticks at max_rate always make one whole step.
  std::uint64_t max_rate() const noexcept {
    std::uint64_t n = timing_.step_len + timing_.step_space;
    return (kOne + n - 1) / n;
  }
  const StepTiming& timing() const noexcept { return timing_; }

  // ---- base side ----
  // One base period: returns the data register value to write. halted: no new steps (a
  // pulse already high still ends on time). Budget: ~20 ns for three axes (bench/).
  std::uint8_t tick(bool halted) noexcept;
  std::uint8_t idle_data() const noexcept;  // step inactive, dir negative, enable active

 private:
  struct Axis {
    std::atomic<std::int64_t> target{0};
    std::atomic<std::uint64_t> rate{0};
    std::atomic<std::int64_t> count{0};
    std::atomic<bool> centred{false};
    // base-thread state
    std::uint64_t accum = 0;
    std::uint32_t high_left = 0, space_left = 0, setup_left = 0, hold_left = 0;
    bool step_high = false;
    bool resting = true;  // at the target last tick: the next command starts a new phase
    int dir = -1;  // -1 / +1: the level on the dir pin
  };
  CompiledPins pins_{};
  StepTiming timing_{};
  AxisArray<Axis> axes_;
};

}  // namespace imess::hal
