// The drive kits per kit period: amplifier enable, command port, motor, counters, latch, inputs.
#include "imess/sim/drive_kit_sim.hpp"

#include <cmath>

namespace imess::sim {


DriveKitSim::DriveKitSim(DriveKitSimConfig config, Mechanics& machine, hal::PortIo& port)
    : config_(std::move(config)), machine_(machine), port_(port) {
  for (int a = 0; a < config_.ports.layout.count; ++a) {
    target_[a] = machine_.carriage()[a];
    port_.out16(config_.ports.axes[a].position_port, encoder(a, machine_.carriage()[a]));
  }
  write_inputs();
}

std::uint16_t DriveKitSim::encoder(int a, double mm) const noexcept {
  // The counter's low 16 bits (two's complement wrap).
  auto counts = static_cast<std::int64_t>(std::llround(mm / config_.ports.axes[a].position_unit_mm));
  return static_cast<std::uint16_t>(static_cast<std::uint64_t>(counts) & 0xFFFFu);
}

void DriveKitSim::write_inputs() noexcept {
  const auto& p = config_.ports;
  std::array<std::uint16_t, 2> bank{};  // inputs, inputs 2
  for (int a = 0; a < p.layout.count; ++a) {
    const auto& ax = p.axes[a];
    std::uint16_t& in = bank[ax.inputs_bank & 1u];
    if (machine_.limit_neg(a)) in |= ax.limit_neg_bit;
    if (machine_.limit_pos(a)) in |= ax.limit_pos_bit;
    if (machine_.home_switch(a)) in |= ax.home_bit;
  }
  if (p.inputs2_port) port_.out16(p.inputs2_port, bank[1]);
  std::uint16_t in = bank[0];
  if (machine_.tip_signal()) in |= p.probe_bit;
  for (int i = 0; i < 4; ++i)
    if (!safety_open_[i]) in |= p.safety_bits[i];  // normally closed: 1 while closed
  port_.out16(p.inputs_port, in);
}

void DriveKitSim::sample(std::int64_t t) noexcept {
  const auto& p = config_.ports;
  double dt = started_ ? static_cast<double>(t - last_t_) * 1e-9 : 0.0;
  last_t_ = t;
  started_ = true;
  const std::uint16_t outputs = port_.in16(p.outputs_port);
  for (int a = 0; a < config_.ports.layout.count; ++a) {
    const auto& ax = p.axes[a];
    const bool enabled = ax.enable_bit == 0 || (outputs & ax.enable_bit);
    auto cmd = static_cast<std::int16_t>(port_.in16(ax.command_port));
    if (p.mode == 1) {
      machine_.set_driven(a, enabled);
      machine_.set_motor_velocity(a, enabled ? cmd / 1000.0 * config_.mm_s_per_volt[a] : 0.0);
    } else {
      if (enabled != machine_.position_driven(a)) {
        machine_.set_position_driven(a, enabled);
        target_[a] = machine_.carriage()[a];
      }
      if (cmd != 0) {  // take the increment, write 0 back: the handshake
        if (enabled) target_[a] += cmd * ax.position_unit_mm;
        port_.out16(ax.command_port, 0);
        ++taken_;
      }
      machine_.command_position(a, target_[a]);
    }
  }
  if (dt > 0) machine_.step(dt);
  const auto& edge = machine_.probe_edge();
  if (dt > 0 && edge.valid && edge.contact && p.latch_status_port && !(port_.in16(p.latch_status_port) & 1)) {
    for (int a = 0; a < config_.ports.layout.count; ++a)
      if (p.axes[a].latch_port) port_.out16(p.axes[a].latch_port, encoder(a, edge.position[a]));
    port_.out16(p.latch_status_port, 1);
  }
  for (int a = 0; a < config_.ports.layout.count; ++a) port_.out16(p.axes[a].position_port, encoder(a, machine_.carriage()[a]));
  write_inputs();
}

}  // namespace imess::sim
