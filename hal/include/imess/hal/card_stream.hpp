// The servo card's stream operations (docs/servo-card-link.md, "Streaming"): the frames the
// driver and the card exchange once the stream runs — host frames {seq, op, arguments}, the
// timed setpoint (Op::Segment) among them, and the card's periodic status frame
// (Op::Status). Shared by the driver (hal) and the emulated card (sim). No allocation.
#pragma once
#include <cmath>
#include <cstdint>
#include <span>

#include "imess/hal/link_codec.hpp"
#include "imess/hal/servo_card_protocol.hpp"
#include "imess/hal/types.hpp"

namespace imess::hal::card {

// Positions on the stream are i32 in units of 0.1 µm (±214 m).
inline constexpr double kStreamUnit = 1e-4;  // mm
inline std::int32_t to_units(double mm) noexcept { return static_cast<std::int32_t>(std::lround(mm / kStreamUnit)); }
inline double from_units(std::int32_t u) noexcept { return u * kStreamUnit; }

// Axis table {count, axis...}: write the axes of mask; read back the mask (each axis at most
// once, count 1..kAxes).
void write_table(LinkWriter& w, unsigned mask) noexcept;
Status read_table(LinkReader& r, unsigned& mask) noexcept;

// The longest frame the card sends (a status frame with latch data and the deflection is 68
// bytes, the longest set-up reply ReadInfo's 6 + its revision): a receiver takes a longer length byte as damaged
// at once rather than wait for the bytes of the frames behind it.
inline constexpr std::size_t kMaxCardPayload = 96;

// Status frame flags.
namespace flag {
// A host frame failed its CRC or a sequence number was skipped: the frame after ack is
// wanted again (the card holds the frames that came after it until it comes), and those of
// the next 16 that the held bits do not name.
inline constexpr std::uint8_t kResendWanted = 0x1;
inline constexpr std::uint8_t kLatchData = 0x2;    // latched positions follow the axis data
// The measuring probe's deflection follows (after the latch data): i32 dx, dy, dz (units as the
// positions), u8 probe flags (servo_card_protocol.hpp, card::probe) — sampled at `clock`.
inline constexpr std::uint8_t kDeflection = 0x4;
}

// The card's periodic status frame: Op::Status, u32 clock (card ticks when sampled), u8 ack
// (sequence number of the last host frame handled), u8 ack_status (its Status), u8 flags,
// u8 starvations (saturating count), u8 knots (setpoints buffered), u16 margin (ticks from
// now to the last buffered setpoint), with kResendWanted u16 held (bit i: the card holds
// host frame ack + 2 + i), table, per axis i32 position, u32 status word, u8 inputs; with
// kLatchData per axis i32 latched position; with kDeflection i32 dx, dy, dz, u8 probe flags.
struct StatusFrame {
  std::uint32_t clock = 0;
  std::uint8_t ack = 0, ack_status = 0, flags = 0, starvations = 0, knots = 0;
  std::uint16_t margin = 0;
  std::uint16_t held = 0;  // with kResendWanted
  unsigned mask = 0;
  AxisArray<double> position{}, latched{};
  AxisArray<std::uint32_t> status{};
  AxisArray<std::uint8_t> inputs{};
  Vec3 deflection = Vec3::Zero();  // mm, machine X Y Z, with kDeflection
  std::uint8_t probe = 0;          // card::probe flags, with kDeflection
};
void write_status(LinkWriter& w, const StatusFrame& s) noexcept;
// Parses a whole status frame (opcode included); false when it is not one or is malformed.
bool read_status(std::span<const std::uint8_t> frame, StatusFrame& s) noexcept;

// Op::Segment's arguments: u32 tick (the card clock at which the axes reach the setpoint),
// table, per axis i32 position, f32 velocity (mm/s).
struct Knot {
  std::uint32_t tick = 0;
  unsigned mask = 0;
  AxisArray<double> position{}, velocity{};
};
void write_knot(LinkWriter& w, const Knot& k) noexcept;
// Reads the arguments after the opcode; the frame must end after them.
Status read_knot(LinkReader& r, Knot& k) noexcept;

// Wrap-around order of card ticks and sequence numbers: a is later than b.
inline bool tick_after(std::uint32_t a, std::uint32_t b) noexcept { return static_cast<std::int32_t>(a - b) > 0; }
inline bool seq_after(std::uint8_t a, std::uint8_t b) noexcept { return static_cast<std::int8_t>(a - b) > 0; }

}  // namespace imess::hal::card
