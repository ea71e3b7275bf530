// Step/dir decoding with timing checks at the sample times, and the switch feedback.
#include "imess/sim/stepper_machine.hpp"

#include <cmath>

namespace imess::sim {

using hal::kParportAxes;

StepperMachine::StepperMachine(StepperMachineConfig config, Mechanics& machine, hal::PortIo& port)
    : config_(std::move(config)), machine_(machine), port_(port), pins_(hal::compile_pins(config_.pins)) {
  for (int a = 0; a < kParportAxes; ++a) {
    axes_[a].origin = machine_.carriage()[a];
    machine_.set_position_driven(a, true);
  }
  last_status_ = status_byte();
  port_.out8(static_cast<std::uint16_t>(config_.base + 1), last_status_);
}

std::uint8_t StepperMachine::status_byte() const noexcept {
  // Logical input states -> register bits: active XOR (per-pin and hardware inversion).
  std::uint8_t active = 0;
  for (int a = 0; a < kParportAxes; ++a) {
    bool home_side_limit = config_.home_direction[a] < 0 ? machine_.limit_neg(a) : machine_.limit_pos(a);
    if (machine_.home_switch(a) || home_side_limit) active |= pins_.endref[a];
    if (machine_.limit_neg(a)) active |= pins_.limit_neg[a];
    if (machine_.limit_pos(a)) active |= pins_.limit_pos[a];
    if (machine_.home_switch(a)) active |= pins_.home[a];
  }
  if (machine_.tip_signal()) active |= pins_.probe;
  if (stop_) active |= pins_.stop;
  return static_cast<std::uint8_t>(active ^ pins_.status_xor);
}

void StepperMachine::sample(std::int64_t t) noexcept {
  const std::uint8_t data = static_cast<std::uint8_t>(port_.in8(config_.base) ^ pins_.data_invert);
  bool moved = false;
  for (int a = 0; a < kParportAxes; ++a) {
    Axis& ax = axes_[a];
    const bool step = (data & pins_.step_mask[a]) != 0, dir = (data & pins_.dir_mask[a]) != 0;
    if (!ax.seen) {  // the first look sets the levels; no edges yet
      ax.seen = true;
      ax.step = step;
      ax.dir = dir;
      continue;
    }
    if (dir != ax.dir) {
      ++edges_;
      if (ax.step || t - ax.fall < config_.min_dir_hold_ns) ++violations_.dir_hold;
      ax.dir = dir;
      ax.dir_change = t;
    }
    if (step && !ax.step) {  // active edge: one step
      ++edges_;
      if (t - ax.fall < config_.min_step_space_ns) ++violations_.step_space;
      if (t - ax.dir_change < config_.min_dir_setup_ns) ++violations_.dir_setup;
      ax.count += dir ? 1 : -1;
      ax.rise = t;
      moved = true;
    } else if (!step && ax.step) {
      ++edges_;
      if (t - ax.rise < config_.min_step_len_ns) ++violations_.pulse_width;
      ax.fall = t;
    }
    ax.step = step;
  }
  if (moved) {
    double dt = started_ ? static_cast<double>(t - last_move_t_) * 1e-9 : 1e-6;
    if (dt <= 0) dt = 1e-9;
    for (int a = 0; a < kParportAxes; ++a)
      machine_.command_position(a, axes_[a].origin + static_cast<double>(axes_[a].count) / config_.steps_per_mm[a]);
    machine_.step(dt);
    for (int a = 0; a < kParportAxes; ++a) {  // a motor pushing into a hard stop stalls: steps are lost
      Axis& ax = axes_[a];
      double want = ax.origin + static_cast<double>(ax.count) / config_.steps_per_mm[a];
      double off = machine_.carriage()[a] - want;
      if (std::abs(off) > 1e-9) {
        ax.lost += static_cast<unsigned long>(std::llround(std::abs(off) * config_.steps_per_mm[a]));
        ax.origin += off;
      }
    }
    last_move_t_ = t;
    started_ = true;
  }
  // The simulator owns the status register: rewritten every sample.
  last_status_ = status_byte();
  port_.out8(static_cast<std::uint16_t>(config_.base + 1), last_status_);
}

}  // namespace imess::sim
