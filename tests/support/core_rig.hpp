// MotionRig: the motion core in virtual time — step the loop, send commands, collect events.
// No threads, no sleeping: deterministic and fast. CoreRig: on the simulated servo-card CMM
// (RigOptions::sim.streamed: the card streamed over a byte-timed serial line).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "imess/core/motion_core.hpp"
#include "imess/hal/servo_card_driver.hpp"
#include "imess/sim/simulated_cmm.hpp"

namespace imess::test {

using core::Command;
using core::CommandKind;
using core::Event;
using core::EventKind;
using core::Mode;
using hal::Vec3;

// The X Y Z machine's axes as a Vec3 and back (the other axes 0).
inline Vec3 xyz(const hal::AxisVec& p) { return p.head<3>(); }
inline hal::AxisVec axes3(const Vec3& v) {
  hal::AxisVec a = hal::AxisVec::Zero();
  a.head<3>() = v;
  return a;
}

class VirtualClock final : public hal::Clock {
 public:
  hal::Nanos now() const noexcept override { return t_; }
  void advance(hal::Nanos d) { t_ += d; }

 private:
  hal::Nanos t_{1'000'000'000};
};

struct RigOptions {
  sim::SimulatedCmmConfig sim;
  core::CoreConfig core;
  bool tip_reversed = false;
};

inline RigOptions default_options() {
  RigOptions o;
  o.core.referenced_at_start = o.sim.card.absolute_scales;
  o.core.outputs[0] = core::default_probe_output();  // as messd configures the card's probe
  o.core.output_count = 1;
  return o;
}

// The motion core driving any MotionBackend in virtual time: step the loop, send commands,
// collect events. The rigs below (and the port backends' rigs in port_rigs.hpp) build a
// machine and its backend, then the core on it.
class MotionRig {
 public:
  static constexpr hal::Nanos kPeriod{1'000'000};
  virtual ~MotionRig() = default;

  void start_core(core::CoreConfig config, hal::SimHooks* hooks = nullptr) {
    core_ = std::make_unique<core::MotionCore>(backend(), config, hooks);
    core_->start(clock_.now());
  }
  void step() {
    clock_.advance(kPeriod);
    core_->cycle(clock_.now());
    core::Event e;
    while (core_->events().pop(e)) events_.push_back(e);
  }
  void run(double seconds) {
    for (long i = 0, n = static_cast<long>(seconds * 1000 + 0.5); i < n; ++i) step();
  }
  // Steps until pred() holds or the time runs out; returns whether it held.
  bool run_until(const std::function<bool()>& pred, double max_seconds) {
    for (long i = 0, n = static_cast<long>(max_seconds * 1000); i < n; ++i) {
      if (pred()) return true;
      step();
    }
    return pred();
  }

  // Sends a command; returns the reply (None = Ok) after the next cycle.
  core::Refusal send(Command c) {
    c.client = 1;
    c.seq = ++seq_;
    core_->submit(c);
    step();
    for (auto& e : events_)
      if (e.kind == EventKind::Reply && e.seq == c.seq) return e.refusal;
    return core::Refusal::Hardware;  // no reply: a test failure shows it
  }
  core::Refusal start_mv(Vec3 percent) { return send({CommandKind::StartMv, 0, 0, axes3(percent)}); }
  core::Refusal go_to(Vec3 target, double speed = 0) { return send({CommandKind::GoTo, 0, 0, axes3(target), speed}); }
  core::Refusal hand(Vec3 delta, double speed = 10) { return send({CommandKind::HandMv, 0, 0, axes3(delta), speed}); }
  core::Refusal simple(CommandKind k) { return send({k}); }
  // The stop lane (StopMv) and the parameter lane (Set), as the io thread uses them.
  void stop() {
    core_->request_stop();
    step();
  }
  void set(core::ParamId id, double value) {
    core_->set_param(id, value);
    step();
  }

  std::vector<Event> take(EventKind kind) {
    std::vector<Event> out, keep;
    for (auto& e : events_) (e.kind == kind ? out : keep).push_back(e);
    events_.swap(keep);
    return out;
  }
  const std::vector<Event>& events() const { return events_; }
  void clear_events() { events_.clear(); }

  Mode mode() const { return core_->mode(); }
  Vec3 position() const { return core_->machine().position.head<3>(); }
  core::MotionCore& core() { return *core_; }
  VirtualClock& clock() { return clock_; }
  virtual hal::MotionBackend& backend() = 0;

 protected:
  VirtualClock clock_;
  std::unique_ptr<core::MotionCore> core_;
  std::vector<Event> events_;
  std::uint32_t seq_ = 0;
};

// The motion core on the simulated servo-card CMM.
class CoreRig final : public MotionRig {
 public:
  explicit CoreRig(RigOptions options = default_options())
      : options_(options), cmm_(options.sim, clock_), driver_(cmm_.link(), card_config(options), cmm_.stream()) {
    core_ = std::make_unique<core::MotionCore>(driver_, options.core, &cmm_.mechanics());
    driver_.initialise(false);
    core_->start(clock_.now());
  }

  static hal::ServoCardConfig card_config(const RigOptions& o) {
    hal::ServoCardConfig c;
    c.firmware = o.sim.card.firmware;
    c.tip_reversed = o.tip_reversed;
    return c;
  }

  hal::MotionBackend& backend() override { return driver_; }
  sim::Mechanics& mechanics() { return cmm_.mechanics(); }
  sim::SimulatedCmm& cmm() { return cmm_; }
  hal::ServoCardDriver& driver() { return driver_; }
  const RigOptions& options() const { return options_; }

 private:
  RigOptions options_;
  sim::SimulatedCmm cmm_;
  hal::ServoCardDriver driver_;
};

}  // namespace imess::test
