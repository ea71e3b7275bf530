// Outputs: the machine's digital outputs as the loop sees them — their start states (set-up),
// the switches a path's SetOutput segments make as they begin, and the probe's power: after
// its output switches, probe edges are its power edges until the settle time has passed.
#pragma once
#include <cstdint>

#include "imess/core/loop_context.hpp"
#include "imess/planner/sampler.hpp"

namespace imess::core {

class Outputs {
 public:
  explicit Outputs(LoopContext& loop) noexcept : loop_(loop) {}

  // Set-up: every configured output to its start state; throws naming the output when the
  // backend lacks it or refuses the switch.
  void start(Nanos now);
  // The outputs as the backend holds them: a trip (a drive kit's safety input) switches them
  // off behind the core's back, the probe's power with them. The one place on_ is set.
  void refresh() noexcept;
  // The output switches of this sampler tick (SetOutput segments that began, the path at
  // rest), in order. The id of the first the backend did not take (nothing after it is
  // switched), or nullptr.
  const std::uint32_t* switch_for(const planner::Sample& smp, Nanos now) noexcept;

  // Is a probe edge now a hit? The probe powered and past its arming time.
  bool probe_armed(Nanos now) const noexcept { return probe_powered_ && now >= arming_until_; }
  bool probe_powered() const noexcept { return probe_powered_; }
  // The edge of the start-up power-on (part of set-up, not news: no warning).
  bool quiet_edge(Nanos now) const noexcept { return quiet_arming_ && now < arming_until_; }
  std::uint32_t bits() const noexcept { return on_; }  // bit i: config.outputs[i] is on

 private:
  void probe_switched(bool on, Nanos now) noexcept;

  LoopContext& loop_;
  std::uint32_t on_ = 0;          // bit i = config.outputs[i] on
  int probe_output_ = -1;         // the probe's power output (-1: none, always powered)
  bool probe_powered_ = true;
  Nanos arming_until_{0};         // probe edges before this are its power edges
  bool quiet_arming_ = false;     // the arming of start-up: its edges go without a warning
};

}  // namespace imess::core
