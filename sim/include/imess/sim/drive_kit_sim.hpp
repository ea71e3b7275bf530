// DriveKitSim: the MRM manual's simulated drive kits (DAC + amplifier + DC motor + encoder
// + counter) on the port space, sampled at the kit's own period. Mode 1: the command port
// holds millivolts, the motor runs at mV/1000 × speed-per-volt (with the Mechanics motor
// lag). Mode 2: the command port holds this period's increment in counts; the kit takes it
// and writes 0 back. Position ports: signed 16-bit counts that wrap; the counters latch on
// the probe edge; inputs carry limits, home switches, the probe and the safety chain.
#pragma once
#include <array>
#include <cstdint>

#include "imess/hal/drive_kit_driver.hpp"
#include "imess/hal/port_io.hpp"
#include "imess/sim/mechanics.hpp"
#include "imess/sim/port_device.hpp"

namespace imess::sim {

struct DriveKitSimConfig {
  hal::DriveKitConfig ports;             // the same port map the driver uses
  // Mode 1 speed constant (rpm/V × mm/rev / 60; deg/s per volt for a rotary axis).
  hal::AxisArray<double> mm_s_per_volt = [] {
    hal::AxisArray<double> v;
    v.fill(20);
    return v;
  }();
  double period_ns = 100'000;            // the kit's own integration period
};

class DriveKitSim final : public PortDevice {
 public:
  DriveKitSim(DriveKitSimConfig config, Mechanics& machine, hal::PortIo& port);
  void sample(std::int64_t t_ns) noexcept override;
  // Opens (true) or closes a normally-closed safety input 0..3.
  void set_safety_open(int input, bool open) noexcept { safety_open_[input] = open; }
  Mechanics& machine() noexcept { return machine_; }
  unsigned long increments_taken() const noexcept { return taken_; }

 private:
  std::uint16_t encoder(int a, double mm) const noexcept;
  void write_inputs() noexcept;

  DriveKitSimConfig config_;
  Mechanics& machine_;
  hal::PortIo& port_;
  hal::AxisArray<double> target_{};  // mode 2 commanded position
  std::array<bool, 4> safety_open_{};
  std::int64_t last_t_ = 0;
  bool started_ = false;
  unsigned long taken_ = 0;
};

}  // namespace imess::sim
