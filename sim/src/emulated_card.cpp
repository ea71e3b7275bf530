// The emulated card's firmware (per tick) and its link request handler.
#include "imess/sim/emulated_card.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "imess/hal/axis_status.hpp"

namespace imess::sim {

using hal::card::kAxes;
using hal::LinkReader;
using hal::card::Op;
using hal::card::Status;
namespace st = hal::status;

namespace {
constexpr double kMaxCatchUp = 0.5;  // s; a stalled caller does not make the card spin for ages
// Following: the setpoints stopped coming when none arrived for this many host periods, and
// at least CardConfig::follow_watchdog. A lost frame the driver sees at once (CommLost); this
// watchdog is for a host that stalls. Until it fires, a late frame is bridged by going on at
// the last setpoint's velocity: a host without a real-time kernel wakes up to a millisecond
// late (messd's Stats: LatMax), which must not fault the machine.
constexpr double kFollowWatchdogPeriods = 1.5;
// Follow frames that the firmware refuses as implausible: faster than this many times vmax,
// or farther from the command than that speed covers in two periods.
constexpr double kFollowSpeedMargin = 1.1;
// Weight of one measured frame interval in the averaged host period.
constexpr double kSpanAveraging = 1.0 / 8;
}

EmulatedCard::EmulatedCard(CardConfig config, Mechanics& machine) : config_(std::move(config)), machine_(machine) {
  follow_span_ = config_.follow_period;
  for (int a = 0; a < kAxes; ++a) {
    axes_[a].offset = config_.absolute_scales ? 0.0 : machine_.carriage()[a];
    axes_[a].profile.reset(encoder(a));
    machine_.set_driven(a, false);
  }
}

double EmulatedCard::quantise(double mm) const noexcept {
  return std::round(mm / config_.encoder_resolution) * config_.encoder_resolution;
}

double EmulatedCard::encoder(int a) const noexcept { return quantise(machine_.carriage()[a] - axes_[a].offset); }

void EmulatedCard::open_all() noexcept {
  following_ = false;
  for (int a = 0; a < kAxes; ++a) {
    axes_[a].closed = false;
    axes_[a].following = false;
    machine_.set_driven(a, false);
  }
}

void EmulatedCard::advance_to(double t) noexcept {
  if (!running_) {
    time_ = t;
    running_ = true;
    return;
  }
  if (t - time_ > kMaxCatchUp) time_ = t - kMaxCatchUp;
  while (time_ + config_.tick <= t) step();
}

void EmulatedCard::end_following(bool brake) noexcept {
  following_ = false;
  knot_count_ = 0;
  for (auto& ax : axes_) {
    if (!ax.following) continue;
    ax.following = false;
    if (brake) ax.profile.stop(ax.amax);  // from the tracked command's velocity
  }
}

// Starved: every following axis brakes so that all come to rest together (each at most at its
// acceleration), so the machine stops on the line it was moving along, not off it.
void EmulatedCard::brake_along_path() noexcept {
  double t = 0;  // s: the longest an axis needs to stop at its acceleration
  for (const auto& ax : axes_)
    if (ax.following && ax.amax > 0) t = std::max(t, std::abs(ax.profile.velocity()) / ax.amax);
  following_ = false;
  knot_count_ = 0;
  for (auto& ax : axes_) {
    if (!ax.following) continue;
    ax.following = false;
    const double v = std::abs(ax.profile.velocity());
    ax.profile.stop(t > 0 && v > 0 ? std::min(ax.amax, v / t) : ax.amax);
  }
}

bool EmulatedCard::following_into_limit() const noexcept {
  for (int a = 0; a < kAxes; ++a) {
    const Axis& ax = axes_[a];
    if (!ax.following || !(ax.outputs & hal::card::output::kLimitSwitchesOn)) continue;
    const double v = ax.profile.velocity();
    if ((v < 0 && machine_.limit_neg(a)) || (v > 0 && machine_.limit_pos(a))) return true;
  }
  return false;
}

void EmulatedCard::track_cubic(double s, double span, double late) noexcept {
  const double s2 = s * s, s3 = s2 * s;
  for (auto& ax : axes_) {
    if (!ax.following) continue;
    const double p = (2 * s3 - 3 * s2 + 1) * ax.p0 + (s3 - 2 * s2 + s) * span * ax.v0 + (3 * s2 - 2 * s3) * ax.p1 +
                     (s3 - s2) * span * ax.v1 + late * ax.v1;
    const double v = (6 * s2 - 6 * s) * (ax.p0 - ax.p1) / span + (3 * s2 - 4 * s + 1) * ax.v0 + (3 * s2 - 2 * s) * ax.v1;
    ax.profile.track(p, v);
  }
}

void EmulatedCard::follow_tick() noexcept {
  if (!following_) return;
  follow_age_ += config_.tick;
  const double span = follow_span_;
  bool moving = false;
  for (const auto& ax : axes_) moving = moving || (ax.following && ax.v1 != 0);
  if (following_into_limit()) return end_following(true);  // firmware limit protection, as for profiles
  if (!moving && follow_age_ >= span - 0.5 * config_.tick) {
    // Arrived at a setpoint at rest: the path ended (or pauses); done until the next frame.
    for (auto& ax : axes_)
      if (ax.following) ax.profile.reset(ax.p1);
    following_ = false;
    for (auto& ax : axes_) ax.following = false;
    return;
  }
  if (follow_age_ > std::max(kFollowWatchdogPeriods * span, config_.follow_watchdog)) {
    // The setpoints stopped coming: brake on the card, report a communication timeout.
    for (auto& ax : axes_) ax.faults |= st::kCommTimeout;
    return end_following(true);
  }
  // Cubic Hermite from (p0, v0) to (p1, v1) over the span; a late frame: on at v1.
  track_cubic(std::min(follow_age_ / span, 1.0), span, std::max(0.0, follow_age_ - span));
}

void EmulatedCard::step() noexcept {
  tick();
  time_ += config_.tick;
}

void EmulatedCard::tick() noexcept {
  if (streaming_) knot_tick();
  else follow_tick();
  for (int a = 0; a < kAxes; ++a) {
    Axis& ax = axes_[a];
    if (!ax.closed) {
      ax.profile.reset(encoder(a));
      ax.following = false;
      continue;
    }
    if (!ax.following) {
      // Firmware limit protection: a profile heading into a closed limit switch brakes at amax.
      if (ax.outputs & hal::card::output::kLimitSwitchesOn)
        ax.profile.brake_into_limits(machine_.limit_neg(a), machine_.limit_pos(a), ax.amax);
      ax.profile.step(config_.tick);
    }
    double error = ax.profile.position() - (machine_.carriage()[a] - ax.offset);
    if (std::abs(error) > ax.max_following_error) {
      ax.faults |= st::kFollowingError;
      open_all();
      break;
    }
    machine_.set_motor_velocity(a, config_.velocity_feedforward * ax.profile.velocity() + config_.position_gain * error);
  }
  machine_.step(config_.tick);
  if (machine_.probe_overtravel()) {
    bool any_closed = axes_[0].closed || axes_[1].closed || axes_[2].closed;
    for (auto& ax : axes_) ax.faults |= st::kEmergency;
    if (any_closed) open_all();
  }
  const auto& edge = machine_.probe_edge();
  if (edge.valid && (axes_[0].outputs & hal::card::output::kProbeOn)) {
    bool raw_rising = edge.contact != machine_.config().probe.normally_closed;
    if (raw_rising != latch_on_falling_) {
      for (int a = 0; a < kAxes; ++a) {
        Axis& ax = axes_[a];
        if (ax.latch_valid) continue;  // the first edge is held until read
        ax.latched = quantise(edge.position[a] - ax.offset);
        ax.latch_valid = true;
      }
    }
  }
  ++clock_;
  if (streaming_ && ++since_status_ >= status_ticks_) {
    since_status_ = 0;
    emit_status();
  }
}

std::uint8_t EmulatedCard::inputs(int a) const noexcept {
  return hal::input_bits({.limit_neg = machine_.limit_neg(a),
                          .limit_pos = machine_.limit_pos(a),
                          .tip = machine_.tip_signal(),
                          .home = machine_.home_switch(a),
                          .index = machine_.index_mark(a)});
}

std::uint32_t EmulatedCard::status_word(int a) const noexcept {
  const Axis& ax = axes_[a];
  const bool done = ax.profile.done() && !ax.following;  // following: done only on arrival at rest
  return hal::status_word({machine_.limit_neg(a), machine_.limit_pos(a), done, ax.closed,
                           done && std::abs(ax.profile.position() - encoder(a)) < config_.in_position_window,
                           ax.latch_valid},
                          ax.faults | (starved_ ? st::kHostStarved : 0u));
}

// ------------------------------------------------------------------ link requests

namespace {

bool named(unsigned mask, int a) noexcept { return (mask & (1u << a)) != 0; }

// Axis table {count, axis...}: the mask of the axes named, each at most once.
Status read_axis_table(LinkReader& r, unsigned& mask) noexcept { return hal::card::read_table(r, mask); }

// N f64 values for each axis of the table, in axis order; the frame must end after them.
template <std::size_t N>
Status read_axis_values(LinkReader& r, unsigned mask, hal::AxisArray<std::array<double, N>>& values) noexcept {
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a))
      for (double& v : values[a]) v = r.f64();
  return r.ok() && r.at_end() ? Status::Ok : Status::BadLength;
}

}  // namespace

int EmulatedCard::handle(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept {
  hal::LinkWriter out;
  out.u8(static_cast<std::uint8_t>(Status::Ok));
  LinkReader r(request);
  auto op = static_cast<Op>(r.u8());
  const Status s = r.ok() ? answer(op, r, out) : Status::BadLength;
  // A failure reply is the status byte alone.
  if (s != Status::Ok) {
    out.clear();
    out.u8(static_cast<std::uint8_t>(s));
  }
  auto bytes = out.bytes();
  if (bytes.size() > reply.size()) return -1;
  for (std::size_t i = 0; i < bytes.size(); ++i) reply[i] = bytes[i];
  return static_cast<int>(bytes.size());
}

Status EmulatedCard::answer(Op op, LinkReader& r, hal::LinkWriter& out) noexcept {
  switch (op) {
    case Op::ReadInfo: return read_info(r, out);
    case Op::Boot: return boot(r);
    case Op::LoadParams: return load_params(r);
    case Op::ResetAxes:
    case Op::CloseLoops:
    case Op::OpenLoops: return set_loops(op, r);
    case Op::JogAbsolute: return jog_absolute(r);
    case Op::JogStop: return jog_stop(r);
    case Op::SetPosition: return set_position(r);
    case Op::Follow: return follow(r, out);
    case Op::ReadState: return read_state(r, out);
    case Op::ReadLatch: return read_latch(r, out);
    case Op::WriteOutputs: return write_outputs(r);
    case Op::ShiftPosition: return shift_position(r);
    case Op::ReadProbe: return read_probe(r, out);
    case Op::StartStream: return start_stream(r, out);
    case Op::Segment: return segment(r);
    case Op::Status: return Status::BadOpcode;  // the card's own frame
  }
  return Status::BadOpcode;
}

Status EmulatedCard::ready_axis_table(LinkReader& r, unsigned& mask) const noexcept {
  if (!booted_ || !params_) return Status::NotReady;
  return read_axis_table(r, mask);
}

Status EmulatedCard::read_info(LinkReader& r, hal::LinkWriter& out) const noexcept {
  if (!r.at_end()) return Status::BadLength;
  out.u8(kAxes).u8(booted_ ? 1 : 0).u8(params_ ? 1 : 0);
  std::string_view rev = booted_ ? std::string_view(config_.firmware) : std::string_view("BOOTLOADER");
  out.u8(static_cast<std::uint8_t>(rev.size()));
  for (char c : rev) out.u8(static_cast<std::uint8_t>(c));
  out.u8(analog_probe() ? hal::card::probe::kAnalog : hal::card::probe::kTrigger);
  return Status::Ok;
}

Status EmulatedCard::boot(LinkReader& r) noexcept {
  std::uint8_t len = r.u8();
  char name[255];
  for (int i = 0; i < len; ++i) name[i] = static_cast<char>(r.u8());
  if (!r.ok() || !r.at_end()) return Status::BadLength;
  if (std::string_view(name, len) != config_.firmware) return Status::WrongFirmware;
  booted_ = true;
  params_ = analog_ = false;
  streaming_ = false;  // a new firmware starts quiet, until StartStream
  open_all();
  return Status::Ok;
}

Status EmulatedCard::load_params(LinkReader& r) noexcept {
  if (!booted_) return Status::NotReady;
  std::uint8_t falling = r.u8();
  unsigned mask = 0;
  if (auto s = read_axis_table(r, mask); s != Status::Ok) return s;
  hal::AxisArray<std::array<double, 3>> values{};  // vmax, amax, max following error
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a))
      for (double& v : values[a]) v = r.f64();
  // The trailing u8 analog is optional (a 1996 host sends none).
  const std::uint8_t analog = r.ok() && !r.at_end() ? r.u8() : 0;
  if (!r.ok() || !r.at_end()) return Status::BadLength;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a))
      for (double v : values[a])
        if (!std::isfinite(v) || v <= 0) return Status::BadValue;
  // Only 0 or 1, and 1 only with a measuring probe fitted.
  if (analog > 1 || (analog == 1 && !analog_probe())) return Status::BadValue;
  latch_on_falling_ = falling != 0;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) {
      axes_[a].vmax = values[a][0];
      axes_[a].amax = values[a][1];
      axes_[a].max_following_error = values[a][2];
    }
  analog_ = analog == 1;
  params_ = true;
  return Status::Ok;
}

// ResetAxes (clears the faults, opens), CloseLoops (a faulted axis stays open), OpenLoops.
Status EmulatedCard::set_loops(Op op, LinkReader& r) noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  if (!r.at_end()) return Status::BadLength;
  for (int a = 0; a < kAxes; ++a) {
    if (!named(mask, a)) continue;
    Axis& ax = axes_[a];
    if (op == Op::ResetAxes) {
      ax.faults = 0;
      starved_ = false;
    }
    bool close = op == Op::CloseLoops && !(ax.faults & st::kFaultMask);
    if (!close) ax.following = false;
    if (close && !ax.closed) ax.profile.reset(encoder(a));
    ax.closed = close;
    machine_.set_driven(a, close);
    if (close) machine_.set_motor_velocity(a, 0);
  }
  return Status::Ok;
}

Status EmulatedCard::jog_absolute(LinkReader& r) noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  hal::AxisArray<std::array<double, 3>> v{};  // target, velocity, acceleration
  if (auto s = read_axis_values(r, mask, v); s != Status::Ok) return s;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a) && (!std::isfinite(v[a][0]) || !(v[a][1] > 0) || !(v[a][2] > 0))) return Status::BadValue;
  if (following_) end_following(true);  // a move ends following; axes it does not name brake
  starved_ = false;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a) && axes_[a].closed)
      axes_[a].profile.start(v[a][0], std::min(v[a][1], axes_[a].vmax), std::min(v[a][2], axes_[a].amax));
  return Status::Ok;
}

Status EmulatedCard::jog_stop(LinkReader& r) noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  hal::AxisArray<std::array<double, 1>> decel{};
  if (auto s = read_axis_values(r, mask, decel); s != Status::Ok) return s;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) {
      const double d = decel[a][0];
      if (!(d > 0) || !std::isfinite(d)) return Status::BadValue;
    }
  // Following a streamed path, the axes brake on it together, each within its acceleration,
  // from the card's own velocities: the host's decelerations follow its plan, which runs the
  // lead ahead of the card (on another segment, a component near 0 would brake for ever).
  // (Request/reply: the host's plan is a period ahead at most; its decelerations are kept.)
  unsigned braked = 0;
  if (following_ && streaming_) {
    for (int a = 0; a < kAxes; ++a)
      if (axes_[a].following) braked |= 1u << a;
    brake_along_path();
  }
  if (following_) end_following(true);  // axes the stop does not name brake at amax
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a) && !named(braked, a)) axes_[a].profile.stop(std::min(decel[a][0], axes_[a].amax));
  return Status::Ok;
}

Status EmulatedCard::set_position(LinkReader& r) noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  hal::AxisArray<std::array<double, 1>> value{};
  if (auto s = read_axis_values(r, mask, value); s != Status::Ok) return s;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) {
      if (!std::isfinite(value[a][0])) return Status::BadValue;
      shift_axis(a, machine_.carriage()[a] - value[a][0]);
    }
  return Status::Ok;
}

void EmulatedCard::shift_axis(int a, double new_offset) noexcept {
  Axis& ax = axes_[a];
  const double by = ax.offset - new_offset;
  ax.offset = new_offset;
  ax.profile.shift(by);
  ax.p0 += by;
  ax.p1 += by;
  for (int i = 0; i < knot_count_; ++i) knots_[(knot_head_ + i) % knots_.size()].position[a] += by;
}

// Follow: the setpoint for the end of the next host period; the reply is ReadState's.
Status EmulatedCard::follow(LinkReader& r, hal::LinkWriter& out) noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  hal::AxisArray<std::array<double, 2>> sp{};  // position, velocity
  if (auto s = read_axis_values(r, mask, sp); s != Status::Ok) return s;
  for (int a = 0; a < kAxes; ++a) {
    if (!named(mask, a)) continue;
    const Axis& ax = axes_[a];
    const double vlim = kFollowSpeedMargin * ax.vmax;
    if (!std::isfinite(sp[a][0]) || !std::isfinite(sp[a][1]) || std::abs(sp[a][1]) > vlim) return Status::BadValue;
    if (ax.closed && std::abs(sp[a][0] - ax.profile.position()) > 2 * vlim * follow_span_ + 1e-6) return Status::BadValue;
  }
  // The host period, measured between frames while following (averaged: the card's ticks
  // and the host's clock are not in step).
  if (following_)
    follow_span_ += (std::clamp(follow_age_, config_.tick, kFollowWatchdogPeriods * follow_span_) - follow_span_) *
                    kSpanAveraging;
  bool any = false;
  for (int a = 0; a < kAxes; ++a) {
    Axis& ax = axes_[a];
    if (!named(mask, a) || !ax.closed) {
      if (ax.following) ax.profile.stop(ax.amax);  // no setpoint for it: it brakes
      ax.following = false;
      continue;
    }
    const double p = sp[a][0], v = sp[a][1];
    // An axis at rest that is told to stay there stays done (no flicker of the done bits).
    if (!ax.following && ax.profile.done() && v == 0 && p == ax.profile.position()) continue;
    ax.p0 = ax.profile.position();  // the command now: a running trapezoid is replaced
    ax.v0 = ax.profile.velocity();
    ax.p1 = p;
    ax.v1 = v;
    ax.following = any = true;
  }
  following_ = any;
  follow_age_ = 0;
  write_state(mask, out);
  return Status::Ok;
}

void EmulatedCard::write_state(unsigned mask, hal::LinkWriter& out) const noexcept {
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) out.f64(encoder(a)).u32(status_word(a)).u8(inputs(a));
  if (analog_) write_probe(out);  // the reading of the same tick as the positions
}

bool EmulatedCard::analog_probe() const noexcept { return machine_.config().probe.type == ProbeType::Analog; }

std::uint8_t EmulatedCard::probe_flags() const noexcept {
  namespace pr = hal::card::probe;
  if (!analog_probe()) return 0;
  const AnalogReading& reading = machine_.analog_reading();
  return static_cast<std::uint8_t>(pr::kAnalogPresent | (reading.contact ? pr::kContact : 0) |
                                   (reading.over_range ? pr::kOverRange : 0));
}

void EmulatedCard::write_probe(hal::LinkWriter& out) const noexcept {
  const Vec3& d = machine_.analog_reading().deflection;  // zero with a trigger probe
  out.u8(probe_flags()).f64(d.x()).f64(d.y()).f64(d.z());
}

// ReadProbe: no arguments -> u8 flags, f64 dx, dy, dz.
Status EmulatedCard::read_probe(LinkReader& r, hal::LinkWriter& out) const noexcept {
  if (!booted_ || !params_) return Status::NotReady;
  if (!r.at_end()) return Status::BadLength;
  write_probe(out);
  return Status::Ok;
}

Status EmulatedCard::read_state(LinkReader& r, hal::LinkWriter& out) const noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  if (!r.at_end()) return Status::BadLength;
  write_state(mask, out);
  return Status::Ok;
}

Status EmulatedCard::read_latch(LinkReader& r, hal::LinkWriter& out) noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  if (!r.at_end()) return Status::BadLength;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) {
      out.f64(axes_[a].latched);
      axes_[a].latch_valid = false;
    }
  return Status::Ok;
}

Status EmulatedCard::write_outputs(LinkReader& r) noexcept {
  unsigned mask = 0;
  if (auto s = ready_axis_table(r, mask); s != Status::Ok) return s;
  hal::AxisArray<std::uint8_t> bits{};
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) bits[a] = r.u8();
  if (!r.ok() || !r.at_end()) return Status::BadLength;
  const bool power_edge =
      named(mask, 0) && ((axes_[0].outputs ^ bits[0]) & hal::card::output::kProbeOn) && config_.probe_power_edges;
  for (int a = 0; a < kAxes; ++a)
    if (named(mask, a)) axes_[a].outputs = bits[a];
  if (power_edge) latch_here();  // the probe's power switched: its signal makes an edge
  return Status::Ok;
}

void EmulatedCard::latch_here() noexcept {
  for (int a = 0; a < kAxes; ++a) {
    Axis& ax = axes_[a];
    if (ax.latch_valid) continue;  // the first edge is held until read
    ax.latched = encoder(a);
    ax.latch_valid = true;
  }
}

}  // namespace imess::sim
