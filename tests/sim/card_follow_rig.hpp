// CardFollowRig: the real ServoCardDriver over a byte-counting, fault-injecting link to the
// EmulatedCard of a SimulatedCmm, in virtual time, and a planned path (planner::Planner,
// sampled by planner::Sampler at the motion period) turned into follow() setpoints.
#pragma once
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <vector>

#include "core_rig.hpp"
#include "poses.hpp"
#include "imess/planner/planner.hpp"
#include "imess/planner/sampler.hpp"

namespace imess::test {

// Between driver and card: counts the bytes each way and injects one fault into the
// transaction `after` transactions from arming.
class FaultyLink final : public hal::Link {
 public:
  enum class Fault {
    None,
    LoseRequest,  // never reaches the card (what a serial link makes of a frame failing its CRC)
    LoseReply,    // the card acts on it, the reply is lost
    Truncate,     // reaches the card one byte short
    Corrupt,      // reaches the card with a bit flipped in the exponent of the last axis' position
  };
  explicit FaultyLink(hal::Link& inner) : inner_(inner) {}
  void inject(Fault f, long after = 0) {
    fault_ = f;
    countdown_ = after;
  }

  int transact(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept override {
    ++transactions;
    bytes_out += static_cast<long>(request.size());
    Fault f = Fault::None;
    if (fault_ != Fault::None && countdown_-- == 0) std::swap(f, fault_);
    if (f == Fault::LoseRequest) return -1;
    std::array<std::uint8_t, hal::kMaxFrame> buf{};
    std::copy(request.begin(), request.end(), buf.begin());
    std::size_t size = request.size();
    if (f == Fault::Truncate) --size;
    if (f == Fault::Corrupt) buf[size - 9] ^= 0x10;  // Z position, top byte: 100 mm → 100·2^256 mm
    const int n = inner_.transact(std::span<const std::uint8_t>(buf.data(), size), reply);
    if (n > 0) bytes_in += n;
    return f == Fault::LoseReply ? -1 : n;
  }

  long transactions = 0, bytes_out = 0, bytes_in = 0;

 private:
  hal::Link& inner_;
  Fault fault_ = Fault::None;
  long countdown_ = 0;
};


// The card and its driver, loops closed at the simulated machine's start position.
class CardFollowRig {
 public:
  static constexpr double kT = 0.001;  // s, the motion period
  static constexpr hal::Nanos kPeriod{1'000'000};

  CardFollowRig() : cmm_(sim_, clock_), link_(cmm_.link()), driver_(link_, hal::ServoCardConfig{}) {
    driver_.initialise(false);
    REQUIRE(driver_.set_loops(true));
  }

  // The planner's machine: travel from the simulated mechanics, speed and acceleration
  // limits from the card configuration (the sim config's 150 mm/s, 1000 mm/s²).
  planner::Machine machine() const {
    const hal::ServoCardConfig card;
    planner::Machine m = planner::make_machine("XYZ", 0, 1000, card.max_velocity[0], card.max_accel[0]);
    for (int a = 0; a < 3; ++a) {
      m.axes[a].travel_min = sim_.mechanics.axes[a].travel_min;
      m.axes[a].travel_max = sim_.mechanics.axes[a].travel_max;
      m.axes[a].max_velocity = card.max_velocity[a];
      m.axes[a].max_accel = card.max_accel[a];
    }
    return m;
  }
  Vec3 start() const { return xyz(sim_.mechanics.start); }

  // Plans the requests from the start position and samples them at the motion period: the
  // setpoints for the ends of the periods 1, 2, … until the path rests at its end.
  std::vector<hal::Setpoint> sampled_path(const std::vector<planner::Request>& requests) const {
    planner::Planner planner(machine());
    planner.set_position(pose3(start()));
    for (const auto& r : requests) {
      const auto res = planner.append(r);
      INFO(planner::describe(res, planner.machine()));
      REQUIRE(res.ok());
    }
    planner.flush();
    std::vector<planner::PlannedSegment> segments;
    planner::PlannedSegment s;
    while (planner.take(s)) segments.push_back(s);
    std::size_t next = 0;
    auto pop = [&](planner::PlannedSegment& out) {
      if (next == segments.size()) return false;
      out = segments[next++];
      return true;
    };
    planner::Sampler sampler(pose3(start()));
    std::vector<hal::Setpoint> out;
    for (int i = 0; i < 200000; ++i) {
      const planner::Sample& smp = sampler.advance(kT, pop);
      hal::Setpoint sp;
      for (int a = 0; a < 3; ++a) {
        sp.position[a] = smp.pose[a];
        sp.velocity[a] = smp.velocity[a];
      }
      out.push_back(sp);
      if (!smp.busy && sampler.idle()) break;
    }
    return out;
  }

  // One motion period on.
  void tick() { clock_.advance(kPeriod); }
  // The card's own status words (a raw ReadState, past the driver's latches).
  hal::AxisArray<std::uint32_t> card_status() {
    hal::LinkWriter w;
    w.u8(static_cast<std::uint8_t>(hal::card::Op::ReadState)).u8(3).u8(0).u8(1).u8(2);
    std::array<std::uint8_t, hal::kMaxFrame> reply{};
    const int n = cmm_.link().transact(w.bytes(), reply);
    REQUIRE(n == 40);
    hal::LinkReader r(std::span<const std::uint8_t>(reply.data() + 1, 39));
    hal::AxisArray<std::uint32_t> out{};
    for (int a = 0; a < 3; ++a) {
      r.f64();
      out[a] = r.u32();
      r.u8();
    }
    return out;
  }

  hal::ServoCardDriver& driver() { return driver_; }
  FaultyLink& link() { return link_; }
  sim::Mechanics& mechanics() { return cmm_.mechanics(); }
  VirtualClock& clock() { return clock_; }

 private:
  VirtualClock clock_;
  sim::SimulatedCmmConfig sim_;
  sim::SimulatedCmm cmm_;
  FaultyLink link_;
  hal::ServoCardDriver driver_;
};

// Lines with a corner and an arc, in the free space above the worked example's box,
// starting where the simulated machine stands (430, 330, 100).
inline std::vector<planner::Request> corner_and_arc_path() {
  using planner::Arc;
  using planner::Line;
  Arc arc;
  arc.id = 3;
  arc.target = pose3(Vec3(440, 380, 110));
  arc.centre = {460, 380, 110};
  arc.ccw = true;  // through (460, 400)
  arc.feed = 80;
  return {Line{1, pose3(Vec3(480, 330, 100)), 100}, Line{2, pose3(Vec3(480, 380, 110)), 100}, arc,
          Line{4, pose3(Vec3(430, 330, 100)), 120}};
}

}  // namespace imess::test
