// The servo card's output 1 powers the probe: the real driver over the link to the emulated
// card (request/reply, and streamed over the byte-timed line), without the core, in virtual
// time. Switching the power on or off latches every axis where it stands (the probe's power
// edge); with the power off a real touch latches nothing; set_loops and reset_faults leave
// the power as it was.
#include <catch2/catch.hpp>

#include <optional>

#include "core_rig.hpp"

using namespace imess;
using namespace imess::test;

namespace {
constexpr double kCount = 0.0001;  // mm, one encoder count of the emulated card

// The driver on the simulated CMM, cycled once per motion period by hand.
class CardOutputRig {
 public:
  static constexpr hal::Nanos kPeriod{1'000'000};

  CardOutputRig(bool streamed, bool power_edges)
      : sim_(config(streamed, power_edges)), cmm_(sim_, clock_), driver_(cmm_.link(), hal::ServoCardConfig{}, cmm_.stream()) {
    driver_.initialise(false);
  }

  void cycles(int n) {
    for (int i = 0; i < n; ++i) {
      clock_.advance(kPeriod);
      REQUIRE(driver_.read_state(ms_));
    }
  }
  const hal::MachineState& state() const { return ms_; }
  Vec3 position() const { return xyz(ms_.position); }

  // Moves to target at 20 mm/s and waits until the card reports the profile done.
  void go_to(const Vec3& target) {
    hal::AxisArray<hal::AxisMove> moves{};
    for (int a = 0; a < 3; ++a) moves[a] = {target[a], 20, 500};
    REQUIRE(driver_.move(moves, 7u));
    cycles(10);  // on the stream the move shows once the card has it
    for (int i = 0; i < 5000 && !ms_.motion_done(); ++i) cycles(1);
    cycles(100);  // the loop settles
    REQUIRE(ms_.motion_done());
    REQUIRE(!ms_.faulted());
  }
  // The latch after a few periods (the stream's next status frames), read and cleared;
  // nullopt when none is valid.
  std::optional<Vec3> take_latch() {
    cycles(12);
    if (!ms_.latch_valid()) return std::nullopt;
    hal::AxisVec l = hal::AxisVec::Zero();
    REQUIRE(driver_.read_latch(l));
    cycles(12);
    CHECK(!ms_.latch_valid());
    return xyz(l);
  }

  hal::ServoCardDriver& driver() { return driver_; }
  sim::Mechanics& mechanics() { return cmm_.mechanics(); }

 private:
  static sim::SimulatedCmmConfig config(bool streamed, bool power_edges) {
    sim::SimulatedCmmConfig c;
    c.streamed = streamed;
    c.card.probe_power_edges = power_edges;
    return c;
  }
  VirtualClock clock_;
  sim::SimulatedCmmConfig sim_;
  sim::SimulatedCmm cmm_;
  hal::ServoCardDriver driver_;
  hal::MachineState ms_{};
};

void check_at(const std::optional<Vec3>& latched, const Vec3& where) {
  REQUIRE(latched);
  INFO("latched " << latched->transpose() << ", expected " << where.transpose());
  CHECK((*latched - where).cwiseAbs().maxCoeff() <= kCount + 1e-9);
}

// Above the worked example's cube (top at z = 80): the ball (r 2) touches at z = 82.
const Vec3 kAbove(430, 330, 95), kPressed(430, 330, 81);
}  // namespace

TEST_CASE("card outputs: output 1 is the probe power — each power edge latches where the axes stand") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  CardOutputRig rig(streamed, true);
  CHECK(rig.driver().output_count() == 1);
  CHECK(rig.driver().probe_power());
  CHECK_FALSE(rig.driver().set_output(0, true));
  CHECK_FALSE(rig.driver().set_output(2, false));
  CHECK(rig.driver().probe_power());

  // initialise() powered the probe on and read the latch of that edge: none is left.
  rig.cycles(1);
  CHECK_FALSE(rig.take_latch());

  REQUIRE(rig.driver().set_loops(true));
  rig.go_to(kAbove);
  REQUIRE(rig.driver().set_output(1, false));
  CHECK_FALSE(rig.driver().probe_power());
  check_at(rig.take_latch(), rig.position());
  CHECK(rig.position().z() == Approx(kAbove.z()).margin(0.001));
  CHECK_FALSE(rig.take_latch());

  REQUIRE(rig.driver().set_output(1, true));
  CHECK(rig.driver().probe_power());
  check_at(rig.take_latch(), rig.position());
  CHECK_FALSE(rig.take_latch());

  // Powered: a touch latches where the ball met the cube, as always.
  rig.go_to(kPressed);
  REQUIRE(rig.mechanics().tip_contact());
  const auto touch = rig.take_latch();
  REQUIRE(touch);
  CHECK(touch->z() == Approx(82).margin(0.001));
  rig.go_to(kAbove);
  CHECK_FALSE(rig.mechanics().tip_contact());
}

TEST_CASE("card outputs: with the probe off a touch latches nothing, and set_loops / reset_faults keep it off") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  CardOutputRig rig(streamed, true);
  rig.cycles(1);
  REQUIRE_FALSE(rig.take_latch());  // initialise() dropped its power-on edge
  REQUIRE(rig.driver().set_loops(true));
  rig.go_to(kAbove);
  REQUIRE(rig.driver().set_output(1, false));
  REQUIRE(rig.take_latch());  // the power-off edge

  // The loops opened and closed, the faults reset: the card's outputs are not written.
  REQUIRE(rig.driver().set_loops(false));
  REQUIRE(rig.driver().reset_faults());
  rig.cycles(20);
  REQUIRE(rig.driver().set_loops(true));
  rig.cycles(20);
  CHECK_FALSE(rig.driver().probe_power());
  CHECK_FALSE(rig.take_latch());

  rig.go_to(kPressed);  // through the touch edge and 1 mm on
  CHECK(rig.mechanics().tip_contact());
  CHECK_FALSE(rig.state().latch_valid());
  CHECK_FALSE(rig.take_latch());
  rig.go_to(kAbove);  // and the re-seat edge
  CHECK_FALSE(rig.mechanics().tip_contact());
  CHECK_FALSE(rig.take_latch());

  // Powered again: the touch latches.
  REQUIRE(rig.driver().set_output(1, true));
  check_at(rig.take_latch(), rig.position());
  rig.go_to(kPressed);
  const auto touch = rig.take_latch();
  REQUIRE(touch);
  CHECK(touch->z() == Approx(82).margin(0.001));
}

TEST_CASE("card outputs: CardConfig::probe_power_edges false switches the power without an edge") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  CardOutputRig rig(streamed, false);
  rig.cycles(1);
  CHECK_FALSE(rig.take_latch());  // no power-on edge at initialise()
  REQUIRE(rig.driver().set_loops(true));
  rig.go_to(kAbove);
  REQUIRE(rig.driver().set_output(1, false));
  CHECK_FALSE(rig.take_latch());
  rig.go_to(kPressed);
  CHECK(rig.mechanics().tip_contact());
  CHECK_FALSE(rig.take_latch());  // off: no touch either
  rig.go_to(kAbove);
  REQUIRE(rig.driver().set_output(1, true));
  CHECK_FALSE(rig.take_latch());
  rig.go_to(kPressed);
  const auto touch = rig.take_latch();
  REQUIRE(touch);
  CHECK(touch->z() == Approx(82).margin(0.001));
}
