// The measuring probe's deflection on the servo card's link (docs/servo-card-link.md, "The
// measuring probe"), in virtual time: the real ServoCardDriver on the emulated card of a
// simulated CMM whose probe is analog. The ball is pressed into the cube's top (z 80) and every
// cycle's MachineState must carry the deflection the mechanics read at the tick its positions
// were sampled; with a touch-trigger probe the 1996 frames are unchanged and nothing is valid.
#include <catch2/catch.hpp>

#include <array>

#include "card_stream_rig.hpp"
#include "core_rig.hpp"
#include "port_rigs.hpp"
#include "imess/hal/servo_card_driver.hpp"
#include "imess/sim/analog_probe.hpp"
#include "imess/sim/simulated_cmm.hpp"

using namespace imess;
using namespace imess::test;
namespace pr = hal::card::probe;

namespace {

constexpr hal::Nanos kProbeCycle{1'000'000};
constexpr double kCubeTop = 80.0, kProbeBall = 2.0, kProbeRange = 1.0;

sim::SimulatedCmmConfig probe_cmm(bool streamed = false) {
  sim::SimulatedCmmConfig c;
  c.mechanics.probe.ball_radius = kProbeBall;
  c.mechanics.probe.type = sim::ProbeType::Analog;
  c.mechanics.probe.analog.range = kProbeRange;
  c.mechanics.probe.analog.noise = 0;
  c.mechanics.probe.analog.spring_rate = 0.5;
  c.mechanics.start = axes3(Vec3(430, 330, kCubeTop + kProbeBall + 1.0));  // 1 mm above the cube's top
  c.streamed = streamed;
  return c;
}

// A raw request on the card's link: the reply bytes (status first).
std::vector<std::uint8_t> raw_reply(hal::Link& link, const hal::LinkWriter& w) {
  std::array<std::uint8_t, hal::kMaxFrame> reply{};
  const int n = link.transact(w.bytes(), reply);
  REQUIRE(n > 0);
  return {reply.begin(), reply.begin() + n};
}

hal::LinkWriter probe_op(hal::card::Op o) {
  hal::LinkWriter w;
  w.u8(static_cast<std::uint8_t>(o));
  return w;
}

hal::LinkWriter read_state_all() {
  hal::LinkWriter w = probe_op(hal::card::Op::ReadState);
  hal::card::write_table(w, 7);
  return w;
}

// ReadProbe's reply: flags and the deflection.
struct ProbeReply {
  std::uint8_t flags = 0;
  Vec3 deflection = Vec3::Zero();
};
ProbeReply read_probe(hal::Link& link) {
  const auto bytes = raw_reply(link, probe_op(hal::card::Op::ReadProbe));
  REQUIRE(bytes.size() == 1 + pr::kReadingBytes);
  REQUIRE(bytes[0] == 0);
  hal::LinkReader r(std::span<const std::uint8_t>(bytes.data() + 1, bytes.size() - 1));
  ProbeReply p;
  p.flags = r.u8();
  for (int i = 0; i < 3; ++i) p.deflection[i] = r.f64();
  REQUIRE(r.at_end());
  return p;
}

// The request/reply link: the card and its driver, loops closed.
struct ProbeReplyRig {
  explicit ProbeReplyRig(const sim::SimulatedCmmConfig& c) : cmm(c, clock), driver(cmm.link(), hal::ServoCardConfig{}) {
    driver.initialise(false);
    REQUIRE(driver.set_loops(true));
  }
  // One cycle: the clock a period on, the driver's state; the reading the mechanics made at
  // the tick that state's positions were sampled at (the card answers at once, after it).
  hal::MachineState cycle() {
    clock.advance(kProbeCycle);
    hal::MachineState ms;
    ms.deflection_valid = !expect_valid;  // proves read_state sets it
    REQUIRE(driver.read_state(ms));
    return ms;
  }
  void check_paired(const hal::MachineState& ms) {
    const auto& reading = cmm.mechanics().analog_reading();
    REQUIRE(ms.deflection_valid == expect_valid);
    if (!expect_valid) return;
    CHECK(ms.deflection == reading.deflection);  // f64 on the wire: exact
    CHECK(ms.probe_over_range == reading.over_range);
    CHECK(ms.position[2] == Approx(cmm.mechanics().carriage()[2]).margin(0.51e-4));  // the encoder of the same tick
  }
  // Moves Z to z on the card's own profile (JogAbsolute), checking each cycle's state.
  void press_to(double z) {
    hal::AxisArray<hal::AxisMove> moves{};
    moves[2] = {z, 5.0, 500.0};
    REQUIRE(driver.move(moves, 4u));
    for (int i = 0; i < 2000; ++i) {
      const hal::MachineState ms = cycle();
      check_paired(ms);
      if (ms.all(hal::status::kInPosition) && std::abs(ms.position[2] - z) < 1e-3) return;
    }
    FAIL("the move to z " << z << " did not end");
  }
  VirtualClock clock;
  sim::SimulatedCmm cmm;
  hal::ServoCardDriver driver;
  bool expect_valid = true;
};

}  // namespace

TEST_CASE("card probe, request/reply: Follow's and ReadState's replies carry the deflection of their tick", "[sim][card][analog]") {
  ProbeReplyRig rig(probe_cmm());
  CHECK(rig.driver.analog_probe());
  // Down at 2 mm/s on followed setpoints (Follow's reply is the state) until 0.3 mm into the top.
  const double z0 = kCubeTop + kProbeBall + 1.0, z1 = kCubeTop + kProbeBall - 0.3, v = 2.0;
  const int n = static_cast<int>((z0 - z1) / v * 1000 + 0.5);
  int in_contact = 0;
  for (int i = 1; i <= n + 200; ++i) {
    hal::Setpoint sp;
    sp.position = rig.cmm.mechanics().config().start;
    sp.position[2] = i <= n ? z0 - v * i * 1e-3 : z1;
    sp.velocity[2] = i < n ? -v : 0.0;
    rig.clock.advance(kProbeCycle);
    REQUIRE(rig.driver.follow(sp));
    hal::MachineState ms;
    REQUIRE(rig.driver.read_state(ms));  // the Follow reply: no second round trip
    rig.check_paired(ms);
    if (ms.deflection.norm() > 0) ++in_contact;
  }
  CHECK(in_contact > 100);
  const hal::MachineState at_rest = rig.cycle();  // ReadState
  rig.check_paired(at_rest);
  CHECK(at_rest.deflection.z() == Approx(0.3).margin(0.002));  // the position loop's residual
  CHECK(at_rest.deflection.head<2>().norm() < 1e-6);
  CHECK_FALSE(at_rest.probe_over_range);
  // ReadProbe alone: the same 25 bytes, contact and the analog probe present.
  const ProbeReply p = read_probe(rig.cmm.link());
  CHECK(p.flags == (pr::kContact | pr::kAnalogPresent));
  CHECK(p.deflection == rig.cmm.mechanics().analog_reading().deflection);

  // Beyond the range: clamped, over range on the wire and in the state.
  rig.press_to(kCubeTop + kProbeBall - 1.5);
  const hal::MachineState over = rig.cycle();
  rig.check_paired(over);
  CHECK(over.probe_over_range);
  CHECK(over.deflection.z() == Approx(kProbeRange).margin(1e-9));
  CHECK(read_probe(rig.cmm.link()).flags == (pr::kContact | pr::kOverRange | pr::kAnalogPresent));

  // Off the part again: no contact, zero deflection, still valid.
  rig.press_to(kCubeTop + kProbeBall + 0.5);
  const hal::MachineState off = rig.cycle();
  CHECK(off.deflection_valid);
  CHECK(off.deflection.norm() == 0.0);
  CHECK(read_probe(rig.cmm.link()).flags == pr::kAnalogPresent);
}

TEST_CASE("card probe, request/reply: ReadInfo names the probe, a 1996 host gets the 1996 replies", "[sim][card][analog]") {
  VirtualClock clock;
  sim::SimulatedCmm analog(probe_cmm(), clock);
  sim::SimulatedCmm trigger(sim::SimulatedCmmConfig{}, clock);
  hal::LinkWriter info = probe_op(hal::card::Op::ReadInfo);
  // u8 axes, booted, params, len, the revision ("BOOTLOADER" before a boot), then the probe type.
  CHECK(raw_reply(analog.link(), info).back() == pr::kAnalog);
  CHECK(raw_reply(trigger.link(), info).back() == pr::kTrigger);
  CHECK(raw_reply(trigger.link(), info).size() == 1 + 4 + 10 + 1);

  hal::LinkWriter boot = probe_op(hal::card::Op::Boot);
  const std::string fw = "IMESS-MCU 1.0";
  boot.u8(static_cast<std::uint8_t>(fw.size()));
  for (char c : fw) boot.u8(static_cast<std::uint8_t>(c));
  auto params = [](int analog_byte) {
    hal::LinkWriter w = probe_op(hal::card::Op::LoadParams);
    w.u8(0);
    hal::card::write_table(w, 7);
    for (int a = 0; a < 3; ++a) w.f64(150).f64(1000).f64(5);
    if (analog_byte >= 0) w.u8(static_cast<std::uint8_t>(analog_byte));
    return w;
  };
  for (auto* cmm : {&analog, &trigger}) REQUIRE(raw_reply(cmm->link(), boot) == std::vector<std::uint8_t>{0});
  // A host that sends no analog byte (or 0) gets ReadState's 1996 reply: 1 + 3 × 13 bytes.
  REQUIRE(raw_reply(analog.link(), params(-1)) == std::vector<std::uint8_t>{0});
  CHECK(raw_reply(analog.link(), read_state_all()).size() == 40);
  REQUIRE(raw_reply(analog.link(), params(0)) == std::vector<std::uint8_t>{0});
  CHECK(raw_reply(analog.link(), read_state_all()).size() == 40);
  REQUIRE(raw_reply(analog.link(), params(1)) == std::vector<std::uint8_t>{0});
  CHECK(raw_reply(analog.link(), read_state_all()).size() == 40 + pr::kReadingBytes);
  // Refused: a value other than 0 or 1, and analog on a card with a touch-trigger probe.
  CHECK(raw_reply(analog.link(), params(2)) == std::vector<std::uint8_t>{5});
  CHECK(raw_reply(trigger.link(), params(1)) == std::vector<std::uint8_t>{5});
  REQUIRE(raw_reply(trigger.link(), params(0)) == std::vector<std::uint8_t>{0});
  CHECK(raw_reply(trigger.link(), read_state_all()).size() == 40);
  // ReadProbe on the trigger card: nothing present, nothing deflected.
  const ProbeReply p = read_probe(trigger.link());
  CHECK(p.flags == 0);
  CHECK(p.deflection.norm() == 0.0);
  hal::LinkWriter probe_with_args = probe_op(hal::card::Op::ReadProbe);
  probe_with_args.u8(0);
  CHECK(raw_reply(trigger.link(), probe_with_args) == std::vector<std::uint8_t>{2});
}

TEST_CASE("card probe, request/reply: with a touch-trigger probe pressed in, the deflection is not valid", "[sim][card][analog]") {
  sim::SimulatedCmmConfig c = probe_cmm();
  c.mechanics.probe.type = sim::ProbeType::Trigger;
  ProbeReplyRig rig(c);
  rig.expect_valid = false;
  CHECK_FALSE(rig.driver.analog_probe());
  rig.press_to(kCubeTop + kProbeBall - 0.3);
  const hal::MachineState ms = rig.cycle();
  CHECK_FALSE(ms.deflection_valid);
  CHECK_FALSE(ms.probe_over_range);
  CHECK(ms.deflection.norm() == 0.0);
  CHECK(ms.tip_touched);  // the switch does its work as ever
}

// The streamed link (the default simulated machine's): the driver over the byte-timed 115 200
// baud line; each status frame's deflection must be the reading at that frame's clock tick.
struct ProbeStreamRig {
  explicit ProbeStreamRig(const sim::SimulatedCmmConfig& c)
      : cmm(c, clock), driver(cmm.link(), hal::ServoCardConfig{}, cmm.stream()),
        probe(c.mechanics.probe.analog, c.mechanics.probe.ball_radius) {
    driver.initialise(false);
    REQUIRE(driver.stream() != nullptr);
    REQUIRE(driver.set_loops(true));
  }
  // One motion period; true when a new status frame came (its state in ms).
  bool cycle(hal::MachineState& ms) {
    clock.advance(kProbeCycle);
    const std::uint32_t before = driver.stream()->status_frames();
    ms.deflection_valid = !expect_valid;  // proves read_state sets it
    REQUIRE(driver.read_state(ms));
    return driver.stream()->status_frames() != before;
  }
  // A new status frame's deflection against the probe read afresh where its positions say the
  // carriage was: a frame pairing the deflection with positions of another tick misses by the
  // distance travelled in the ticks between (0.5 µm a tick at 5 mm/s); here it may differ by the
  // stream's 0.1 µm quantisation of both (half a unit each).
  void check_paired(const hal::MachineState& ms) {
    REQUIRE(ms.deflection_valid == expect_valid);
    if (!expect_valid) return;
    const sim::AnalogReading expected = probe.read(cmm.mechanics().scene(), ms.position.head<3>());
    CHECK((ms.deflection - expected.deflection).cwiseAbs().maxCoeff() <= 1.0001e-4);
    CHECK(ms.probe_over_range == expected.over_range);
    const std::uint8_t flags = driver.stream()->newest().probe;
    CHECK(flags == (pr::kAnalogPresent | (expected.contact ? pr::kContact : 0) | (expected.over_range ? pr::kOverRange : 0)));
    ++frames;
    if (expected.contact) ++in_contact;
    if (expected.over_range) ++over_range;
  }
  // Moves Z to z at speed on the card's own profile, checking every status frame on the way.
  void press_to(double z, double speed) {
    hal::AxisArray<hal::AxisMove> moves{};
    moves[2] = {z, speed, 500.0};
    REQUIRE(driver.move(moves, 4u));
    hal::MachineState ms;
    for (int i = 0; i < 3000; ++i) {
      if (cycle(ms)) check_paired(ms);
      if (ms.all(hal::status::kInPosition) && std::abs(ms.position[2] - z) < 1e-3) return;
    }
    FAIL("the move to z " << z << " did not end");
  }
  VirtualClock clock;
  sim::SimulatedCmm cmm;
  hal::ServoCardDriver driver;
  sim::AnalogProbe probe;  // the same probe, noise-free: the reading a position must give
  bool expect_valid = true;
  int frames = 0, in_contact = 0, over_range = 0;
};

TEST_CASE("card probe, stream: every status frame carries the deflection of its clock tick", "[sim][card][analog]") {
  ProbeStreamRig rig(probe_cmm(true));
  REQUIRE(rig.driver.analog_probe());
  // 1 mm down to 0.3 mm into the top at 5 mm/s, then on to 1.5 mm (beyond the range).
  rig.press_to(kCubeTop + kProbeBall - 0.3, 5.0);
  CHECK(rig.in_contact > 10);
  hal::MachineState ms;
  for (int i = 0; i < 200; ++i) rig.cycle(ms);  // settled in the position loop
  while (!rig.cycle(ms)) {
  }
  rig.check_paired(ms);
  // At rest: the mechanics' own reading, within the stream's quantisation.
  CHECK((ms.deflection - rig.cmm.mechanics().analog_reading().deflection).norm() < 0.51e-4);
  CHECK(ms.deflection.z() == Approx(0.3).margin(0.002));
  CHECK_FALSE(ms.probe_over_range);
  CHECK((rig.driver.stream()->newest().flags & hal::card::flag::kDeflection) != 0);
  rig.press_to(kCubeTop + kProbeBall - 1.5, 5.0);
  CHECK(rig.over_range > 10);
  while (!rig.cycle(ms)) {
  }
  CHECK(ms.probe_over_range);
  CHECK(ms.deflection.z() == Approx(kProbeRange).margin(0.51e-4));
  CHECK(rig.driver.stream()->newest().probe == (pr::kAnalogPresent | pr::kContact | pr::kOverRange));
  rig.press_to(kCubeTop + kProbeBall + 0.5, 5.0);
  while (!rig.cycle(ms)) {
  }
  CHECK(ms.deflection_valid);
  CHECK(ms.deflection.norm() == 0.0);
  CHECK(rig.driver.stream()->newest().probe == pr::kAnalogPresent);
  // The frames, 60 bytes on the line with the deflection, came every 6 ms (5 ms would take
  // more than the 115 200 baud line carries), none lost or damaged.
  CHECK(rig.driver.errors() == 0);
  const std::uint32_t clock = rig.driver.stream()->newest().clock;
  while (!rig.cycle(ms)) {
  }
  CHECK(rig.driver.stream()->newest().clock - clock == 60);
}

TEST_CASE("card probe, stream: with a touch-trigger probe the status frames are the 1996 size and carry no deflection", "[sim][card][analog]") {
  sim::SimulatedCmmConfig c = probe_cmm(true);
  c.mechanics.probe.type = sim::ProbeType::Trigger;
  ProbeStreamRig rig(c);
  rig.expect_valid = false;
  rig.press_to(kCubeTop + kProbeBall - 0.3, 5.0);
  hal::MachineState ms;
  while (!rig.cycle(ms)) {
  }
  CHECK_FALSE(ms.deflection_valid);
  CHECK(ms.tip_touched);
  CHECK((rig.driver.stream()->newest().flags & hal::card::flag::kDeflection) == 0);
  // The card's frame: 12 + table (4) + 3 × 9 bytes, and the latch data of the touch.
  std::span<const std::uint8_t> frame;
  while (!rig.cmm.card().take_stream_frame(frame)) rig.cmm.card().step();
  CHECK(frame.size() == 12 + 4 + 27 + ((frame[7] & hal::card::flag::kLatchData) ? 12 : 0));
  const std::uint32_t clock = rig.driver.stream()->newest().clock;  // every 5 ms, as ever
  while (!rig.cycle(ms)) {
  }
  CHECK(rig.driver.stream()->newest().clock - clock == 50);
}

TEST_CASE("card probe: the port backends report no deflection", "[sim][analog]") {
  StepperRig stepper;
  hal::MachineState ms;
  ms.deflection_valid = ms.probe_over_range = true;
  REQUIRE(stepper.backend().read_state(ms));
  CHECK_FALSE(ms.deflection_valid);
  CHECK_FALSE(ms.probe_over_range);
  DriveRig kit;
  ms.deflection_valid = ms.probe_over_range = true;
  REQUIRE(kit.backend().read_state(ms));
  CHECK_FALSE(ms.deflection_valid);
  CHECK_FALSE(ms.probe_over_range);
}
