// The stream operations' encoders and parsers (hal/card_stream.hpp).
#include "imess/hal/card_stream.hpp"

namespace imess::hal::card {

namespace {
bool named(unsigned mask, int a) noexcept { return (mask & (1u << a)) != 0; }
}

void write_table(LinkWriter& w, unsigned mask) noexcept {
  std::uint8_t count = 0;
  for (int a = 0; a < kAxes; ++a) count += named(mask, a) ? 1 : 0;
  w.u8(count);
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) w.u8(static_cast<std::uint8_t>(a));
}

Status read_table(LinkReader& r, unsigned& mask) noexcept {
  const std::uint8_t count = r.u8();
  if (!r.ok()) return Status::BadLength;
  if (count == 0 || count > kAxes) return Status::BadAxis;
  mask = 0;
  for (int i = 0; i < count; ++i) {
    const std::uint8_t a = r.u8();
    if (!r.ok()) return Status::BadLength;
    if (a >= kAxes || named(mask, a)) return Status::BadAxis;
    mask |= 1u << a;
  }
  return Status::Ok;
}

void write_status(LinkWriter& w, const StatusFrame& s) noexcept {
  w.u8(static_cast<std::uint8_t>(Op::Status)).u32(s.clock).u8(s.ack).u8(s.ack_status).u8(s.flags);
  w.u8(s.starvations).u8(s.knots).u16(s.margin);
  if (s.flags & flag::kResendWanted) w.u16(s.held);
  write_table(w, s.mask);
  for (int a = 0; a < kAxes; ++a)
    if (named(s.mask, a)) w.i32(to_units(s.position[a])).u32(s.status[a]).u8(s.inputs[a]);
  if (s.flags & flag::kLatchData)
    for (int a = 0; a < kAxes; ++a)
      if (named(s.mask, a)) w.i32(to_units(s.latched[a]));
  if (s.flags & flag::kDeflection) w.i32(to_units(s.deflection.x())).i32(to_units(s.deflection.y())).i32(to_units(s.deflection.z())).u8(s.probe);
}

bool read_status(std::span<const std::uint8_t> frame, StatusFrame& s) noexcept {
  LinkReader r(frame);
  if (r.u8() != static_cast<std::uint8_t>(Op::Status)) return false;
  s.clock = r.u32();
  s.ack = r.u8();
  s.ack_status = r.u8();
  s.flags = r.u8();
  s.starvations = r.u8();
  s.knots = r.u8();
  s.margin = r.u16();
  s.held = (s.flags & flag::kResendWanted) ? r.u16() : 0;
  if (read_table(r, s.mask) != Status::Ok) return false;
  for (int a = 0; a < kAxes; ++a)
    if (named(s.mask, a)) {
      s.position[a] = from_units(r.i32());
      s.status[a] = r.u32();
      s.inputs[a] = r.u8();
    }
  if (s.flags & flag::kLatchData)
    for (int a = 0; a < kAxes; ++a)
      if (named(s.mask, a)) s.latched[a] = from_units(r.i32());
  if (s.flags & flag::kDeflection) {
    for (int i = 0; i < 3; ++i) s.deflection[i] = from_units(r.i32());
    s.probe = r.u8();
  }
  return r.ok() && r.at_end();
}

void write_knot(LinkWriter& w, const Knot& k) noexcept {
  w.u32(k.tick);
  write_table(w, k.mask);
  for (int a = 0; a < kAxes; ++a)
    if (named(k.mask, a)) w.i32(to_units(k.position[a])).f32(static_cast<float>(k.velocity[a]));
}

Status read_knot(LinkReader& r, Knot& k) noexcept {
  k.tick = r.u32();
  if (auto s = read_table(r, k.mask); s != Status::Ok) return s;
  for (int a = 0; a < kAxes; ++a)
    if (named(k.mask, a)) {
      k.position[a] = from_units(r.i32());
      k.velocity[a] = r.f32();
    }
  if (!r.ok() || !r.at_end()) return Status::BadLength;
  for (int a = 0; a < kAxes; ++a)
    if (named(k.mask, a) && !std::isfinite(k.velocity[a])) return Status::BadValue;
  return Status::Ok;
}

}  // namespace imess::hal::card
