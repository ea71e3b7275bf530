// The base-period step routine: golden port bytes for a short fixed move on both pin maps
// (hand-derived from the timing rules), the pulse timing at the maximum rate, and where a
// centred (path-following) command puts its steps.
#include <catch2/catch.hpp>

#include <vector>

#include "imess/hal/step_generator.hpp"

using namespace imess::hal;

namespace {
std::vector<int> run(StepGenerator& g, int ticks) {
  std::vector<int> bytes;
  for (int i = 0; i < ticks; ++i) bytes.push_back(g.tick(false));
  return bytes;
}
}  // namespace

TEST_CASE("golden port bytes: X +2 and Y -1 steps then X back, 3D-Step pins") {
  StepGenerator g;
  g.configure(compile_pins(*named_pin_map("3d-step")), StepTiming{1, 1, 1, 1});
  g.command(0, 2, g.max_rate());
  g.command(1, -1, g.max_rate());
  // dir X = bit 0, step X = bit 1, dir Y = bit 2, step Y = bit 3. Half a step per tick:
  // tick 2 sets dir X (setup 1 tick) while Y, already pointing negative, steps at once.
  CHECK(run(g, 7) == std::vector<int>{0x00, 0x09, 0x03, 0x01, 0x03, 0x01, 0x01});
  CHECK(g.count(0) == 2);
  CHECK(g.count(1) == -1);
  g.command(0, 0, g.max_rate());
  CHECK(run(g, 6) == std::vector<int>{0x01, 0x00, 0x02, 0x00, 0x02, 0x00});
  CHECK(g.count(0) == 0);
}

TEST_CASE("golden port bytes: the same move on the SHD adapter pins") {
  StepGenerator g;
  g.configure(compile_pins(*named_pin_map("shd-adapter")), StepTiming{1, 1, 1, 1});
  g.command(0, 2, g.max_rate());
  g.command(1, -1, g.max_rate());
  // step X = bit 0, step Y = bit 1, dir X = bit 4.
  CHECK(run(g, 7) == std::vector<int>{0x00, 0x12, 0x11, 0x10, 0x11, 0x10, 0x10});
}

TEST_CASE("longer pulse timing in base periods, and halting stops new steps at once") {
  StepGenerator g;
  g.configure(compile_pins(*named_pin_map("shd-adapter")), StepTiming{3, 2, 2, 4});
  CHECK(g.max_rate() == StepGenerator::kOne / 5 + 1);  // rounded up: 5 ticks make a whole step
  g.command(0, 100, StepGenerator::kOne);  // capped at one step per 5 ticks
  auto b = run(g, 20);
  // The first step is due at tick 5 (0.2 steps per tick); X points negative, so dir X
  // (bit 4) turns first and the step follows after the 2-tick setup. Then step X (bit 0)
  // is high for exactly 3 ticks and low for 2: the maximum rate.
  std::vector<int> step;
  for (int v : b) step.push_back(v & 1);
  CHECK(step == std::vector<int>{0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1, 0});
  CHECK((b[3] & 0x10) == 0);
  CHECK((b[4] & 0x10) == 0x10);
  auto before = g.count(0);
  for (int i = 0; i < 10; ++i) g.tick(true);
  CHECK(g.count(0) == before);
}

TEST_CASE("a centred command puts its steps mid-interval, a plain one at the interval's end") {
  for (bool centred : {false, true}) {
    StepGenerator g;
    g.configure(compile_pins(*named_pin_map("shd-adapter")), StepTiming{1, 1, 1, 1});
    g.tick(false);                                           // at rest
    g.command(0, -2, StepGenerator::kOne / 8, centred);      // dir already negative: no setup wait
    std::vector<int> at;
    for (int i = 1; i <= 20; ++i) {
      auto before = g.count(0);
      g.tick(false);
      if (g.count(0) != before) at.push_back(i);
    }
    CHECK(at == (centred ? std::vector<int>{4, 12} : std::vector<int>{8, 16}));
    CHECK(g.count(0) == -2);
  }
}
