// SimulatedCmm: the whole simulated measuring machine as the daemon sees it — mechanics and
// workpiece, the emulated servo card, and the link to it. Hand link() (and stream(), when the
// card is streamed over a byte-timed serial line) to a ServoCardDriver.
#pragma once
#include "imess/sim/emulated_card.hpp"
#include "imess/sim/timed_card_link.hpp"

namespace imess::sim {

struct SimulatedCmmConfig {
  MechanicsConfig mechanics;
  CardConfig card;
  Scene scene = default_scene();
  bool streamed = false;  // the card on a serial line (TimedCardLink), not the instant request/reply link
  LineConfig line;
};

class SimulatedCmm {
 public:
  SimulatedCmm(const SimulatedCmmConfig& config, const hal::Clock& clock)
      : mechanics_(config.mechanics, config.scene),
        card_(config.card, mechanics_),
        link_(card_, clock),
        line_(card_, clock, config.line),
        streamed_(config.streamed) {}
  SimulatedCmm(const SimulatedCmm&) = delete;
  SimulatedCmm& operator=(const SimulatedCmm&) = delete;

  hal::Link& link() noexcept { return streamed_ ? static_cast<hal::Link&>(line_) : link_; }
  hal::StreamLink* stream() noexcept { return streamed_ ? &line_ : nullptr; }
  bool streamed() const noexcept { return streamed_; }
  TimedCardLink& line() noexcept { return line_; }
  Mechanics& mechanics() noexcept { return mechanics_; }
  EmulatedCard& card() noexcept { return card_; }

 private:
  Mechanics mechanics_;
  EmulatedCard card_;
  SimLink link_;
  TimedCardLink line_;
  bool streamed_;
};

}  // namespace imess::sim
