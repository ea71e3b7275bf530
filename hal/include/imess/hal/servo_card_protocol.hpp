// The servo card's link protocol (see docs/servo-card-link.md): one opcode byte, an axis
// table {count, axis...} for multi-axis operations, then little-endian u32 / f64 values.
// Replies start with a status byte. Once streaming, frames on the stream link carry
// {seq, op, arguments} host to card and Status frames card to host (hal/card_stream.hpp). Shared by the driver (hal) and the emulated card (sim).
#pragma once
#include <cstdint>

namespace imess::hal::card {

// The card drives three axes, X Y Z (the link's axis tables name axes 0..2).
inline constexpr int kAxes = 3;

enum class Op : std::uint8_t {
  ReadInfo = 0x01,      // -> status, u8 axes, u8 booted, u8 params_loaded, u8 len, revision bytes,
                        // u8 probe_type (probe::kTrigger, probe::kAnalog; absent on a 1996 card: trigger)
  Boot = 0x02,          // u8 len, firmware revision bytes -> status
  LoadParams = 0x03,    // u8 latch_on_falling, table, per axis f64 vmax, f64 amax, f64 max_following_error,
                        // [u8 analog] -> status (analog 1: Follow's and ReadState's replies end in the
                        // probe reading; absent or 0: the 1996 replies)
  ResetAxes = 0x04,     // table -> status (clears fault bits, stops profiles, opens loops)
  CloseLoops = 0x10,    // table -> status
  OpenLoops = 0x11,     // table -> status
  JogAbsolute = 0x21,   // table, per axis f64 target, f64 velocity, f64 accel -> status
  JogStop = 0x22,       // table, per axis f64 decel -> status
  SetPosition = 0x23,   // table, per axis f64 value -> status
  Segment = 0x25,       // stream only: u32 tick, table, per axis i32 position (0.1 µm), f32 velocity
                        // (a setpoint stamped with the card clock, sent ahead; hal/card_stream.hpp)
  ShiftPosition = 0x26, // table, per axis f64 delta -> status (the current position becomes position + delta)
  Follow = 0x24,        // table, per axis f64 position, f64 velocity (the setpoint one motion period
                        // ahead) -> status, then the ReadState reply: one round trip per cycle
  ReadState = 0x30,     // table -> status, per axis f64 position, u32 status word, u8 inputs
                        // (+ the probe reading when LoadParams enabled it)
  ReadProbe = 0x33,     // -> status, u8 probe flags, f64 dx, dy, dz (mm, machine X Y Z): the probe reading
  ReadLatch = 0x31,     // table -> status, per axis f64 latched position (clears latch-valid)
  WriteOutputs = 0x40,  // table, per axis u8 output bits -> status
  StartStream = 0x50,   // u16 status period (card ticks), table -> status, u32 card ticks per second;
                        // from then on the card sends Status frames and takes host frames on the stream
  Status = 0x32,        // card -> host on the stream, unasked, every status period (hal/card_stream.hpp)
};

enum class Status : std::uint8_t {
  Ok = 0,
  BadOpcode = 1,
  BadLength = 2,   // frame shorter or longer than the operation needs
  BadAxis = 3,     // axis number not on the card, or a count of 0
  NotReady = 4,    // no firmware booted or no parameters loaded yet
  BadValue = 5,    // non-finite number, non-positive speed
  WrongFirmware = 6,
};

// The measuring probe (docs/servo-card-link.md, "The measuring probe"): ReadInfo's probe type,
// and the flags of a probe reading (u8 flags, f64 dx, dy, dz: probe::kReadingBytes), sampled at the
// card tick of the positions it comes with.
namespace probe {
inline constexpr std::uint8_t kTrigger = 0, kAnalog = 1;
inline constexpr std::uint8_t kContact = 0x1, kOverRange = 0x2, kAnalogPresent = 0x4;
inline constexpr int kReadingBytes = 1 + 3 * 8;
}

// Output bits per axis module (WriteOutputs).
namespace output {
inline constexpr std::uint8_t kLimitSwitchesOn = 0x1, kReferenceSwitchOn = 0x2, kProbeOn = 0x4;
}

}  // namespace imess::hal::card
