// The emulated card's firmware (per tick) and its link request handler.
#include "imess/sim/emulated_card.hpp"

#include "imess/hal/axis_status.hpp"

#include <cmath>

#include "imess/hal/link_codec.hpp"
#include "imess/hal/servo_card_protocol.hpp"

namespace imess::sim {

using hal::kAxes;
using hal::LinkReader;
using hal::card::Op;
using hal::card::Status;
namespace st = hal::status;
namespace in = hal::input;

namespace {
constexpr double kMaxCatchUp = 0.5;  // s; a stalled caller does not make the card spin for ages
}

EmulatedCard::EmulatedCard(CardConfig config, Mechanics& machine) : config_(std::move(config)), machine_(machine) {
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
  for (int a = 0; a < kAxes; ++a) {
    axes_[a].closed = false;
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
  while (time_ + config_.tick <= t) {
    tick();
    time_ += config_.tick;
  }
}

void EmulatedCard::tick() noexcept {
  for (int a = 0; a < kAxes; ++a) {
    Axis& ax = axes_[a];
    if (!ax.closed) {
      ax.profile.reset(encoder(a));
      continue;
    }
    // Firmware limit protection: a profile heading into a closed limit switch brakes at amax.
    if (ax.outputs & hal::card::output::kLimitSwitchesOn)
      ax.profile.brake_into_limits(machine_.limit_neg(a), machine_.limit_pos(a), ax.amax);
    ax.profile.step(config_.tick);
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
}

std::uint8_t EmulatedCard::inputs(int a) const noexcept {
  std::uint8_t bits = 0;
  if (machine_.limit_pos(a)) bits |= in::kLimitPos;
  if (machine_.limit_neg(a)) bits |= in::kLimitNeg;
  if (machine_.tip_signal()) bits |= in::kTip;
  if (machine_.home_switch(a)) bits |= in::kHome;
  if (machine_.index_mark(a)) bits |= in::kIndex;
  return bits;
}

std::uint32_t EmulatedCard::status_word(int a) const noexcept {
  const Axis& ax = axes_[a];
  const bool done = ax.profile.done();
  return hal::status_word({machine_.limit_neg(a), machine_.limit_pos(a), done, ax.closed,
                           done && std::abs(ax.profile.position() - encoder(a)) < config_.in_position_window,
                           ax.latch_valid},
                          ax.faults);
}

int EmulatedCard::handle(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept {
  ++requests_;
  hal::LinkWriter out;
  auto finish = [&](Status s) -> int {
    // A failure reply is the status byte alone.
    if (s != Status::Ok) {
      out.clear();
      out.u8(static_cast<std::uint8_t>(s));
    }
    auto bytes = out.bytes();
    if (bytes.size() > reply.size()) return -1;
    for (std::size_t i = 0; i < bytes.size(); ++i) reply[i] = bytes[i];
    return static_cast<int>(bytes.size());
  };
  out.u8(static_cast<std::uint8_t>(Status::Ok));
  LinkReader r(request);
  auto op = static_cast<Op>(r.u8());
  if (!r.ok()) return finish(Status::BadLength);

  // Axis table {count, axis...}; mask of the axes named.
  auto read_table = [&](unsigned& mask) -> Status {
    std::uint8_t count = r.u8();
    if (!r.ok()) return Status::BadLength;
    if (count == 0 || count > kAxes) return Status::BadAxis;
    mask = 0;
    for (int i = 0; i < count; ++i) {
      std::uint8_t a = r.u8();
      if (!r.ok()) return Status::BadLength;
      if (a >= kAxes || (mask & (1u << a))) return Status::BadAxis;
      mask |= 1u << a;
    }
    return Status::Ok;
  };
  auto ready = [&] { return booted_ && params_; };
  unsigned mask = 0;

  switch (op) {
    case Op::ReadInfo: {
      if (!r.at_end()) return finish(Status::BadLength);
      out.u8(kAxes).u8(booted_ ? 1 : 0).u8(params_ ? 1 : 0);
      std::string_view rev = booted_ ? std::string_view(config_.firmware) : std::string_view("BOOTLOADER");
      out.u8(static_cast<std::uint8_t>(rev.size()));
      for (char c : rev) out.u8(static_cast<std::uint8_t>(c));
      return finish(Status::Ok);
    }
    case Op::Boot: {
      std::uint8_t len = r.u8();
      char name[255];
      for (int i = 0; i < len; ++i) name[i] = static_cast<char>(r.u8());
      if (!r.ok() || !r.at_end()) return finish(Status::BadLength);
      if (std::string_view(name, len) != config_.firmware) return finish(Status::WrongFirmware);
      booted_ = true;
      params_ = false;
      open_all();
      return finish(Status::Ok);
    }
    case Op::LoadParams: {
      if (!booted_) return finish(Status::NotReady);
      std::uint8_t falling = r.u8();
      if (auto s = read_table(mask); s != Status::Ok) return finish(s);
      double values[kAxes][3];
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a))
          for (double& v : values[a]) v = r.f64();
      if (!r.ok() || !r.at_end()) return finish(Status::BadLength);
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a))
          for (double v : values[a])
            if (!std::isfinite(v) || v <= 0) return finish(Status::BadValue);
      latch_on_falling_ = falling != 0;
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) {
          axes_[a].vmax = values[a][0];
          axes_[a].amax = values[a][1];
          axes_[a].max_following_error = values[a][2];
        }
      params_ = true;
      return finish(Status::Ok);
    }
    case Op::ResetAxes:
    case Op::CloseLoops:
    case Op::OpenLoops: {
      if (!ready()) return finish(Status::NotReady);
      if (auto s = read_table(mask); s != Status::Ok) return finish(s);
      if (!r.at_end()) return finish(Status::BadLength);
      for (int a = 0; a < kAxes; ++a) {
        if (!(mask & (1u << a))) continue;
        Axis& ax = axes_[a];
        if (op == Op::ResetAxes) ax.faults = 0;
        bool close = op == Op::CloseLoops && !(ax.faults & st::kFaultMask);
        if (close && !ax.closed) ax.profile.reset(encoder(a));
        ax.closed = close;
        machine_.set_driven(a, close);
        if (close) machine_.set_motor_velocity(a, 0);
      }
      return finish(Status::Ok);
    }
    case Op::JogAbsolute: {
      if (!ready()) return finish(Status::NotReady);
      if (auto s = read_table(mask); s != Status::Ok) return finish(s);
      double v[kAxes][3];
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a))
          for (double& x : v[a]) x = r.f64();
      if (!r.ok() || !r.at_end()) return finish(Status::BadLength);
      for (int a = 0; a < kAxes; ++a)
        if ((mask & (1u << a)) && (!std::isfinite(v[a][0]) || !(v[a][1] > 0) || !(v[a][2] > 0)))
          return finish(Status::BadValue);
      for (int a = 0; a < kAxes; ++a)
        if ((mask & (1u << a)) && axes_[a].closed)
          axes_[a].profile.start(v[a][0], std::min(v[a][1], axes_[a].vmax), std::min(v[a][2], axes_[a].amax));
      return finish(Status::Ok);
    }
    case Op::JogStop: {
      if (!ready()) return finish(Status::NotReady);
      if (auto s = read_table(mask); s != Status::Ok) return finish(s);
      double d[kAxes] = {0, 0, 0};
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) d[a] = r.f64();
      if (!r.ok() || !r.at_end()) return finish(Status::BadLength);
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) {
          if (!(d[a] > 0) || !std::isfinite(d[a])) return finish(Status::BadValue);
          axes_[a].profile.stop(std::min(d[a], axes_[a].amax));
        }
      return finish(Status::Ok);
    }
    case Op::SetPosition: {
      if (!ready()) return finish(Status::NotReady);
      if (auto s = read_table(mask); s != Status::Ok) return finish(s);
      double val[kAxes] = {0, 0, 0};
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) val[a] = r.f64();
      if (!r.ok() || !r.at_end()) return finish(Status::BadLength);
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) {
          if (!std::isfinite(val[a])) return finish(Status::BadValue);
          double old_offset = axes_[a].offset;
          axes_[a].offset = machine_.carriage()[a] - val[a];
          axes_[a].profile.shift(old_offset - axes_[a].offset);
        }
      return finish(Status::Ok);
    }
    case Op::ReadState: {
      if (!ready()) return finish(Status::NotReady);
      if (auto s = read_table(mask); s != Status::Ok) return finish(s);
      if (!r.at_end()) return finish(Status::BadLength);
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) out.f64(encoder(a)).u32(status_word(a)).u8(inputs(a));
      return finish(Status::Ok);
    }
    case Op::ReadLatch: {
      if (!ready()) return finish(Status::NotReady);
      if (auto s = read_table(mask); s != Status::Ok) return finish(s);
      if (!r.at_end()) return finish(Status::BadLength);
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) {
          out.f64(axes_[a].latched);
          axes_[a].latch_valid = false;
        }
      return finish(Status::Ok);
    }
    case Op::WriteOutputs: {
      if (!ready()) return finish(Status::NotReady);
      if (auto s = read_table(mask); s != Status::Ok) return finish(s);
      std::uint8_t bits[kAxes] = {0, 0, 0};
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) bits[a] = r.u8();
      if (!r.ok() || !r.at_end()) return finish(Status::BadLength);
      for (int a = 0; a < kAxes; ++a)
        if (mask & (1u << a)) axes_[a].outputs = bits[a];
      return finish(Status::Ok);
    }
  }
  return finish(Status::BadOpcode);
}

}  // namespace imess::sim
