// ConfigRig: a shipped configuration file loaded as messd loads it, its machine built and
// driven by the motion core in virtual time — for properties that must hold on every config.
#pragma once
#include <memory>
#include <string>

#include "config.hpp"
#include "core_rig.hpp"
#include "machine.hpp"

namespace imess::test {

class ConfigRig {
 public:
  static constexpr hal::Nanos kPeriod{1'000'000};

  explicit ConfigRig(const std::string& path) {
    app::load_json_config(path, cfg_);
    cfg_.ports.port_io.file = "";  // a private port space: tests never share the shipped /tmp files
    app::finish_config(cfg_);
    machine_ = app::make_machine(cfg_, clock_, false);
    core_ = std::make_unique<core::MotionCore>(machine_->backend(), cfg_.core, machine_->sim_hooks());
    core_->start(clock_.now());
  }

  // One motion cycle; events are popped and handed to on_event.
  template <class OnEvent>
  void step(OnEvent&& on_event) {
    clock_.advance(kPeriod);
    core_->cycle(clock_.now());
    core::Event e;
    while (core_->events().pop(e)) on_event(e);
  }

  // One motion cycle at the configured period, leaving the events in the core's ring for
  // whoever reads them (the golden transcripts' net::Server).
  void cycle() {
    clock_.advance(hal::Nanos(static_cast<long>(cfg_.period_us * 1000)));
    core_->cycle(clock_.now());
  }

  const app::DaemonConfig& config() const { return cfg_; }
  const VirtualClock& clock() const { return clock_; }
  core::MotionCore& core() { return *core_; }
  app::Machine& machine() { return *machine_; }
  bool simulated_hands() const { return machine_->sim_hooks() != nullptr; }

 private:
  app::DaemonConfig cfg_;
  VirtualClock clock_;
  std::unique_ptr<app::Machine> machine_;
  std::unique_ptr<core::MotionCore> core_;
};

}  // namespace imess::test
