// ServoCardDriver: frames every operation of the card link protocol. Real-time calls use
// only the fixed writer_/reply_ buffers.
#include "imess/hal/servo_card_driver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "imess/hal/servo_card_protocol.hpp"
#include "imess/hal/stream_frame.hpp"

namespace imess::hal {

using card::kAxes;
using card::Op;
using card::Status;

namespace {
constexpr unsigned kAllAxes = (1u << kAxes) - 1;
// Every module's outputs: limit and reference switches on, the probe powered or not.
constexpr std::uint8_t output_bits(bool probe_on) {
  return static_cast<std::uint8_t>(card::output::kLimitSwitchesOn | card::output::kReferenceSwitchOn |
                                   (probe_on ? card::output::kProbeOn : 0));
}

const char* status_text(std::uint8_t s) {
  switch (static_cast<Status>(s)) {
    case Status::Ok: return "ok";
    case Status::BadOpcode: return "unknown opcode";
    case Status::BadLength: return "bad frame length";
    case Status::BadAxis: return "bad axis table";
    case Status::NotReady: return "no firmware or parameters loaded";
    case Status::BadValue: return "bad value";
    case Status::WrongFirmware: return "wrong firmware";
  }
  return "unknown status";
}
}  // namespace

ServoCardDriver::ServoCardDriver(Link& link, ServoCardConfig config, StreamLink* stream)
    : link_(link), config_(std::move(config)), stream_link_(stream) {}

LinkWriter& ServoCardDriver::begin(Op op) noexcept {
  writer_.clear();
  return writer_.u8(static_cast<std::uint8_t>(op));
}

void ServoCardDriver::table(unsigned axis_mask) noexcept {
  std::uint8_t count = 0;
  for (int a = 0; a < kAxes; ++a) count += (axis_mask >> a) & 1u;
  writer_.u8(count);
  for (int a = 0; a < kAxes; ++a)
    if (axis_mask & (1u << a)) writer_.u8(static_cast<std::uint8_t>(a));
}

bool ServoCardDriver::exchange(std::span<const std::uint8_t>& payload) noexcept {
  if (!writer_.ok()) {
    ++errors_;
    return false;
  }
  int n = link_.transact(writer_.bytes(), reply_);
  if (n < 1 || reply_[0] != static_cast<std::uint8_t>(Status::Ok)) {
    ++errors_;
    return false;
  }
  payload = std::span<const std::uint8_t>(reply_.data() + 1, static_cast<std::size_t>(n - 1));
  return true;
}

bool ServoCardDriver::simple() noexcept {
  std::span<const std::uint8_t> payload;
  return exchange(payload);
}

bool ServoCardDriver::command(CardStreamSession::Effect effect) noexcept {
  if (!session_) return simple();
  if (!writer_.ok()) {
    ++errors_;
    return false;
  }
  return session_->command(writer_.bytes(), effect);
}

void ServoCardDriver::fail(const std::string& what) const {
  throw std::runtime_error("servo card: " + what);
}

void ServoCardDriver::set_up_call(const char* what) {
  int n = link_.transact(writer_.bytes(), reply_);
  if (n < 1) fail(std::string(what) + ": no answer on the link");
  if (reply_[0] != 0) fail(std::string(what) + ": card answered '" + status_text(reply_[0]) + "'");
}

void ServoCardDriver::initialise(bool force_reboot) {
  comm_lost_ = have_followed_ = false;
  session_.reset();  // set-up speaks request/reply only
  // 1. Firmware: boot when missing, wrong, or forced (-r); retry a wrong revision.
  for (int attempt = 0;; ++attempt) {
    begin(Op::ReadInfo);
    int n = link_.transact(writer_.bytes(), reply_);
    if (n < 1) fail("no answer to ReadInfo — is the card present and the link configured?");
    LinkReader r(std::span<const std::uint8_t>(reply_.data(), static_cast<std::size_t>(n)));
    auto st = r.u8();
    auto axes = r.u8();
    bool booted = r.u8() != 0;
    r.u8();  // params loaded: reloaded below in every case
    auto len = r.u8();
    std::string rev;
    for (int i = 0; i < len; ++i) rev.push_back(static_cast<char>(r.u8()));
    // The probe type ends the reply of a card that has one to tell (a 1996 card: a trigger probe).
    const std::uint8_t probe = r.ok() && !r.at_end() ? r.u8() : card::probe::kTrigger;
    if (!r.ok() || st != 0) fail("malformed ReadInfo reply");
    if (probe > card::probe::kAnalog)
      fail("ReadInfo names probe type " + std::to_string(probe) + " (0 touch-trigger and 1 analog are known)");
    analog_ = probe == card::probe::kAnalog;
    if (axes < kAxes) fail("card reports " + std::to_string(axes) + " axes, messd needs " + std::to_string(kAxes));
    if (booted && rev == config_.firmware && !force_reboot) {
      revision_ = rev;
      break;
    }
    if (attempt >= config_.boot_retries)
      fail("firmware revision '" + rev + "' after " + std::to_string(attempt) + " boots, need '" + config_.firmware + "'");
    begin(Op::Boot).u8(static_cast<std::uint8_t>(config_.firmware.size()));
    for (char c : config_.firmware) writer_.u8(static_cast<std::uint8_t>(c));
    set_up_call("booting firmware");
    force_reboot = false;
  }
  // 2. Control parameters.
  begin(Op::LoadParams).u8(config_.tip_reversed ? 1 : 0);
  table(kAllAxes);
  for (int a = 0; a < kAxes; ++a)
    writer_.f64(config_.max_velocity[a]).f64(config_.max_accel[a]).f64(config_.max_following_error[a]);
  if (analog_) writer_.u8(1);  // the probe reading with every state (a trigger probe: the 1996 frame)
  set_up_call("loading control parameters");
  // 3. Reset axes (loops open, faults cleared), switch limit/reference/probe inputs on.
  begin(Op::ResetAxes);
  table(kAllAxes);
  set_up_call("resetting axes");
  begin(Op::WriteOutputs);
  table(kAllAxes);
  for (int a = 0; a < kAxes; ++a) writer_.u8(output_bits(true));
  set_up_call("switching limit, reference and probe inputs on");
  probe_on_ = true;
  // The probe's power-on edge latched the axes: part of set-up, read and dropped here.
  begin(Op::ReadLatch);
  table(kAllAxes);
  set_up_call("clearing the latch of the probe's power-on");
  if (stream_link_) start_stream();
}

// 4. With a stream: status frames every status period, real-time calls on the stream from now.
void ServoCardDriver::start_stream() {
  StreamSettings s = config_.stream;
  if (analog_ && s.baud > 0) {
    // The deflection makes a status frame 13 bytes longer (60 on the line with three axes:
    // 5.2 ms at 115 200 baud, more than the 5 ms period): the period grows to the whole
    // milliseconds in which the frames take at most 90 % of the line.
    const double bytes = kFrameOverhead + 13 + kAxes + 9.0 * kAxes + 13;
    const double needed = bytes * 10 / s.baud / 0.9;
    s.status_period = std::max(s.status_period, std::ceil(needed * 1000 - 1e-9) / 1000);
  }
  if (!(s.status_period > 0 && s.status_period * 1e6 < 65536 && s.period > 0 && s.segment_cycles >= 1 && s.lead > 0))
    fail("stream settings out of range (status period 0-65 ms, period and lead > 0, segment cycles >= 1)");
  session_.reset();
  begin(Op::StartStream).u16(static_cast<std::uint16_t>(std::lround(s.status_period * 1e6)));
  table(kAllAxes);
  set_up_call("starting the stream");
  LinkReader r(std::span<const std::uint8_t>(reply_.data() + 1, reply_.size() - 1));
  const std::uint32_t ticks_per_second = r.u32(), clock = r.u32();
  if (!r.ok() || ticks_per_second == 0) fail("malformed StartStream reply");
  MachineState now;
  begin(Op::ReadState);
  table(kAllAxes);
  std::span<const std::uint8_t> payload;
  if (!exchange(payload) || !parse_state(payload, now)) fail("no state after starting the stream");
  // Status frames of an earlier stream (before a restart of messd or a re-boot) are stale.
  std::array<std::uint8_t, kMaxFrame> stale{};
  while (stream_link_->poll(stale) != 0) {}
  session_.emplace(*stream_link_, s);
  session_->start(ticks_per_second, clock, now, config_.tip_reversed);
}

unsigned long ServoCardDriver::link_errors() const noexcept {
  if (!rebooting()) last_errors_ = errors();
  return last_errors_;
}

std::string ServoCardDriver::reboot() {
  int expected = kRebootWanted;
  if (!phase_.compare_exchange_strong(expected, kRebooting, std::memory_order_acq_rel)) return "no re-boot was asked for";
  std::string failure;
  try {
    initialise(false);
  } catch (const std::exception& e) {
    failure = e.what();
    session_.reset();
    reboot_failed_ = true;
  }
  phase_.store(kRunning, std::memory_order_release);
  return failure;
}

std::string ServoCardDriver::describe() const {
  return "servo card, firmware '" + revision_ + "'" + (analog_ ? ", measuring probe" : "");
}

bool ServoCardDriver::read_state(MachineState& out) noexcept {
  if (rebooting() || reboot_failed_) {  // the card is being re-booted, or could not be
    out = last_;
    out.deflection_valid = out.probe_over_range = false;
    for (int a = 0; a < kAxes; ++a) {
      out.status[a] &= ~(status::kFaultMask | status::kClosedLoop | status::kLatchValid);
      if (reboot_failed_) out.status[a] |= status::kCommTimeout;
    }
    return true;
  }
  if (session_) {
    const bool ok = session_->read_state(out);
    last_ = out;
    return ok;
  }
  if (have_followed_) {  // the Follow reply of this cycle: no second round trip
    have_followed_ = false;
    out = followed_;
  } else {
    begin(Op::ReadState);
    table(kAllAxes);
    std::span<const std::uint8_t> payload;
    if (!exchange(payload) || !parse_state(payload, out)) return false;
  }
  if (comm_lost_)
    for (auto& s : out.status) s |= status::kCommTimeout;
  return true;
}

double ServoCardDriver::path_lead_s() const noexcept { return session_ ? session_->lead() : 0.0; }

bool ServoCardDriver::follow(const Setpoint& sp) noexcept {
  if (rebooting() || reboot_failed_) return false;
  if (session_) return session_->follow(sp);
  // Measured on the link (tests/sim/test_card_follow.cpp): 53 bytes out, 40 back.
  begin(Op::Follow);
  table(kAllAxes);
  for (int a = 0; a < kAxes; ++a) writer_.f64(sp.position[a]).f64(sp.velocity[a]);
  std::span<const std::uint8_t> payload;
  have_followed_ = exchange(payload) && parse_state(payload, followed_);
  if (!have_followed_) comm_lost_ = true;
  return have_followed_;
}

bool ServoCardDriver::parse_state(std::span<const std::uint8_t> payload, MachineState& out) noexcept {
  LinkReader r(payload);
  out.count = kAxes;
  for (int a = 0; a < kAxes; ++a) {
    out.position[a] = r.f64();
    out.status[a] = r.u32();
    out.inputs[a] = r.u8();
  }
  out.deflection_valid = out.probe_over_range = false;
  out.deflection = Vec3::Zero();
  if (analog_) {  // the probe reading of the tick the positions were sampled at
    const std::uint8_t flags = r.u8();
    for (int i = 0; i < 3; ++i) out.deflection[i] = r.f64();
    out.deflection_valid = (flags & card::probe::kAnalogPresent) != 0;
    out.probe_over_range = (flags & card::probe::kOverRange) != 0;
  }
  if (!r.ok() || !r.at_end()) {
    ++errors_;
    return false;
  }
  // The tip is wired to every axis module; axis 0 carries it.
  bool contact = (out.inputs[0] & input::kTip) != 0;
  out.tip_touched = config_.tip_reversed ? !contact : contact;
  return true;
}

bool ServoCardDriver::read_latch(AxisVec& latched) noexcept {
  if (rebooting() || reboot_failed_) return false;
  begin(Op::ReadLatch);
  table(kAllAxes);
  if (session_)  // the status frame carries the latch; the command clears it on the card
    return session_->latched(latched) && command(CardStreamSession::Effect::ClearLatch);
  std::span<const std::uint8_t> payload;
  if (!exchange(payload)) return false;
  LinkReader r(payload);
  for (int a = 0; a < kAxes; ++a) latched[a] = r.f64();
  return r.ok() && r.at_end();
}

bool ServoCardDriver::set_loops(bool closed) noexcept {
  if (rebooting() || reboot_failed_) return !closed;  // open they are
  begin(closed ? Op::CloseLoops : Op::OpenLoops);
  table(kAllAxes);
  return command(closed ? CardStreamSession::Effect::CloseLoops : CardStreamSession::Effect::OpenLoops);
}

bool ServoCardDriver::move(const AxisArray<AxisMove>& moves, unsigned axis_mask) noexcept {
  if (rebooting() || reboot_failed_) return false;
  if ((axis_mask & kAllAxes) == 0) return true;
  begin(Op::JogAbsolute);
  table(axis_mask);
  for (int a = 0; a < kAxes; ++a)
    if (axis_mask & (1u << a)) writer_.f64(moves[a].target).f64(moves[a].velocity).f64(moves[a].accel);
  return command(CardStreamSession::Effect::Motion);
}

bool ServoCardDriver::stop(const AxisVec& decel) noexcept {
  if (rebooting() || reboot_failed_) return true;  // nothing moves
  begin(Op::JogStop);
  table(kAllAxes);
  for (int a = 0; a < kAxes; ++a) writer_.f64(decel[a]);
  return command(CardStreamSession::Effect::Motion);
}

bool ServoCardDriver::set_position(int axis, double value) noexcept {
  if (rebooting() || reboot_failed_) return false;
  if (axis < 0 || axis >= kAxes) return false;
  if (session_) {  // relative on the stream: exact however old the newest status frame is
    const double delta = session_->shift_for(axis, value);
    begin(Op::ShiftPosition);
    table(1u << axis);
    writer_.f64(delta);
    if (!command(CardStreamSession::Effect::None)) return false;
    session_->note_shift(axis, delta);
    return true;
  }
  begin(Op::SetPosition);
  table(1u << axis);
  writer_.f64(value);
  return simple();
}

bool ServoCardDriver::set_output(int number, bool on) noexcept {
  if (rebooting() || reboot_failed_) return false;
  if (number != 1) return false;
  begin(Op::WriteOutputs);
  table(kAllAxes);
  for (int a = 0; a < kAxes; ++a) writer_.u8(output_bits(on));
  if (!command(CardStreamSession::Effect::None)) return false;
  probe_on_ = on;
  return true;
}

bool ServoCardDriver::reset_faults() noexcept {
  if (rebooting()) return false;
  if (config_.reboot_on_reset && (reboot_failed_ || (session_ && session_->silent()))) {
    reboot_failed_ = false;
    phase_.store(kRebootWanted, std::memory_order_release);
    return true;
  }
  begin(Op::ResetAxes);
  table(kAllAxes);
  if (!command(CardStreamSession::Effect::Reset)) return false;
  comm_lost_ = have_followed_ = false;
  return true;
}

}  // namespace imess::hal
