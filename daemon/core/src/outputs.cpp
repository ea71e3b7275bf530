// Outputs: start states, the path's output switches, the probe's power and arming time.
#include "imess/core/outputs.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

namespace imess::core {

void Outputs::start(Nanos now) {
  const CoreConfig& config = loop_.config;
  hal::MotionBackend& hw = loop_.hw;
  for (int i = 0; i < config.output_count; ++i) {
    const OutputSettings& o = config.outputs[i];
    const std::string name(o.name_view());
    if (o.number < 1 || o.number > hw.output_count())
      throw std::runtime_error("output '" + name + "' is number " + std::to_string(o.number) + "; the backend has " +
                               (hw.output_count() ? "outputs 1 to " + std::to_string(hw.output_count())
                                                  : std::string("no outputs")));
    if (!hw.set_output(o.number, o.at_start))
      throw std::runtime_error("output '" + name + "' (number " + std::to_string(o.number) + ") could not be switched " +
                               (o.at_start ? "on" : "off") + " at start");
    if (o.probe_power) {
      probe_output_ = i;
      probe_switched(o.at_start, now);
      quiet_arming_ = true;
    }
  }
  refresh();
}

// The probe's power output switched: edges until its settle time has passed are power edges.
void Outputs::probe_switched(bool on, Nanos now) noexcept {
  probe_powered_ = on;
  arming_until_ =
      now + std::chrono::nanoseconds(static_cast<std::int64_t>(loop_.config.outputs[probe_output_].settle_s * 1e9));
}

const std::uint32_t* Outputs::switch_for(const planner::Sample& smp, Nanos now) noexcept {
  for (int k = 0; k < smp.switch_count; ++k) {
    const auto& sw = smp.switches[k];
    const bool on = sw.value != 0;
    if (!loop_.hw.set_output(sw.output, on)) {
      ++loop_.hardware_errors;
      refresh();
      return &sw.id;
    }
    if (probe_output_ >= 0 && loop_.config.outputs[probe_output_].number == sw.output) {
      quiet_arming_ = false;
      probe_switched(on, now);
    }
  }
  if (smp.switch_count > 0) refresh();  // Outputs shows the switch in this cycle's snapshot
  return nullptr;
}

void Outputs::refresh() noexcept {
  for (int i = 0; i < loop_.config.output_count; ++i) {
    const bool on = loop_.hw.output_on(loop_.config.outputs[i].number);
    on_ = on ? (on_ | (1u << i)) : (on_ & ~(1u << i));
    if (i == probe_output_ && !on) probe_powered_ = false;
  }
}

}  // namespace imess::core
