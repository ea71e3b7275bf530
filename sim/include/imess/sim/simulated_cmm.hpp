// SimulatedCmm: the whole simulated measuring machine as the daemon sees it — mechanics and
// workpiece, the emulated servo card, and the link to it. Hand the link to a ServoCardDriver.
#pragma once
#include "imess/sim/emulated_card.hpp"

namespace imess::sim {

struct SimulatedCmmConfig {
  MechanicsConfig mechanics;
  CardConfig card;
  Scene scene = worked_example_scene();
};

class SimulatedCmm {
 public:
  SimulatedCmm(const SimulatedCmmConfig& config, const hal::Clock& clock)
      : mechanics_(config.mechanics, config.scene), card_(config.card, mechanics_), link_(card_, clock) {}
  SimulatedCmm(const SimulatedCmm&) = delete;
  SimulatedCmm& operator=(const SimulatedCmm&) = delete;

  hal::Link& link() noexcept { return link_; }
  Mechanics& mechanics() noexcept { return mechanics_; }
  EmulatedCard& card() noexcept { return card_; }

 private:
  Mechanics mechanics_;
  EmulatedCard card_;
  SimLink link_;
};

}  // namespace imess::sim
