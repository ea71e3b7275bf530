// Pin maps: the two SHD-family maps land on the right register bits, BUSY's hardware
// inversion and per-pin inversion are applied, bad maps are refused naming the pin.
#include <catch2/catch.hpp>

#include "imess/hal/parport_pins.hpp"

using namespace imess::hal;

TEST_CASE("the SHD adapter map: steps on data 0-2, dirs on 4-6, switches on the status register") {
  auto m = named_pin_map("shd-adapter");
  REQUIRE(m);
  REQUIRE_NOTHROW(validate_pin_map(*m));
  auto c = compile_pins(*m);
  CHECK(c.step_mask == AxisArray<std::uint8_t>{0x01, 0x02, 0x04});
  CHECK(c.dir_mask == AxisArray<std::uint8_t>{0x10, 0x20, 0x40});
  CHECK(c.endref == AxisArray<std::uint8_t>{0x40, 0x20, 0x10});  // ACK, PAPER OUT, SELECT
  CHECK(c.stop == 0x80);
  CHECK(c.probe == 0x08);  // pin 15, ERROR
  // BUSY is inverted by the port: STOP (pin 11 high) reads as bit 7 clear.
  CHECK(c.status_xor == 0x80);
  CHECK(c.data_invert == 0);
}

TEST_CASE("the 3D-Step map: dir/step pairs") {
  auto c = compile_pins(*named_pin_map("3d-step"));
  CHECK(c.dir_mask == AxisArray<std::uint8_t>{0x01, 0x04, 0x10});
  CHECK(c.step_mask == AxisArray<std::uint8_t>{0x02, 0x08, 0x20});
  CHECK(c.endref == AxisArray<std::uint8_t>{0x40, 0x20, 0x10});
  CHECK(c.stop == 0x80);
  CHECK(!named_pin_map("isel"));
}

TEST_CASE("per-pin inversion flips the register sense and on BUSY cancels the hardware inversion") {
  auto m = *named_pin_map("shd-adapter");
  m.pins[2].invert = true;   // step X active low
  m.pins[11].invert = true;  // STOP active low at the pin: reads as bit 7 set
  m.pins[15].invert = true;
  auto c = compile_pins(m);
  CHECK(c.data_invert == 0x01);
  CHECK(c.status_xor == 0x08);
}

TEST_CASE("pin signals parse and print and wrong ones are refused with the accepted forms") {
  auto a = parse_pin_signal("limit+ Y");
  CHECK(a.signal == PinSignal::LimitPos);
  CHECK(a.axis == 1);
  CHECK(pin_signal_text(a) == "limit+ Y");
  CHECK(parse_pin_signal("probe").signal == PinSignal::Probe);
  CHECK_THROWS_WITH(parse_pin_signal("step W"), Catch::Contains("accepted"));
  CHECK_THROWS_WITH(parse_pin_signal("probe X"), Catch::Contains("accepted"));
}

TEST_CASE("unworkable pin maps name the pin") {
  auto m = *named_pin_map("shd-adapter");
  m.pins[10] = {PinSignal::Step, 0, false};
  m.pins[2] = {};
  CHECK_THROWS_WITH(validate_pin_map(m), Catch::Contains("pin 10") && Catch::Contains("outputs go on"));
  m = *named_pin_map("shd-adapter");
  m.pins[3] = {};
  CHECK_THROWS_WITH(validate_pin_map(m), Catch::Contains("axis Y needs exactly one step"));
  m = *named_pin_map("shd-adapter");
  m.pins[9] = {PinSignal::Probe, -1, false};
  CHECK_THROWS_WITH(validate_pin_map(m), Catch::Contains("inputs go on pins"));
}
