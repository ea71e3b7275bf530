// The base-period step routine: per axis a small state machine over whole base periods.
#include "imess/hal/step_generator.hpp"

namespace imess::hal {

void StepGenerator::configure(const CompiledPins& pins, const StepTiming& timing) noexcept {
  pins_ = pins;
  timing_ = timing;
  auto at_least_one = [](std::uint32_t& v) { v = v < 1 ? 1 : v; };
  at_least_one(timing_.step_len);
  at_least_one(timing_.step_space);
  at_least_one(timing_.dir_setup);
  at_least_one(timing_.dir_hold);
}

void StepGenerator::command(int axis, std::int64_t target, std::uint64_t rate, bool centred) noexcept {
  Axis& a = axes_[axis];
  std::uint64_t cap = max_rate();
  a.rate.store(rate > cap ? cap : rate, std::memory_order_relaxed);
  a.centred.store(centred, std::memory_order_relaxed);
  a.target.store(target, std::memory_order_release);
}

std::uint8_t StepGenerator::idle_data() const noexcept {
  return static_cast<std::uint8_t>(pins_.enable_data_mask ^ pins_.data_invert);
}

std::uint8_t StepGenerator::tick(bool halted) noexcept {
  std::uint8_t data = halted ? 0 : pins_.enable_data_mask;
  for (int i = 0; i < kParportAxes; ++i) {
    Axis& a = axes_[i];
    // Timers of the pulse in progress.
    if (a.step_high) {
      if (--a.high_left == 0) {
        a.step_high = false;
        a.space_left = timing_.step_space;
        a.hold_left = timing_.dir_hold;
      }
    } else {
      if (a.space_left) --a.space_left;
      if (a.hold_left) --a.hold_left;
    }
    if (a.setup_left) --a.setup_left;

    std::int64_t count = a.count.load(std::memory_order_relaxed);
    std::int64_t target = a.target.load(std::memory_order_acquire);
    if (halted || count == target) {
      a.accum = 0;
      a.resting = true;
    } else {
      if (a.resting && a.centred.load(std::memory_order_relaxed)) a.accum = kOne / 2;  // steps mid-interval
      a.resting = false;
      if (a.accum < kOne) a.accum += a.rate.load(std::memory_order_relaxed);  // a due step waits, never bursts
      int want = target > count ? 1 : -1;
      if (a.accum >= kOne && !a.step_high && a.space_left == 0) {
        if (want != a.dir) {
          if (a.hold_left == 0) {  // change direction now, step after the setup time
            a.dir = want;
            a.setup_left = timing_.dir_setup;
          }
        } else if (a.setup_left == 0) {
          a.step_high = true;
          a.high_left = timing_.step_len;
          a.accum -= kOne;
          a.count.store(count + want, std::memory_order_release);
        }
      }
    }
    if (a.step_high) data |= pins_.step_mask[i];
    if (a.dir > 0) data |= pins_.dir_mask[i];
  }
  return static_cast<std::uint8_t>(data ^ pins_.data_invert);
}

}  // namespace imess::hal
