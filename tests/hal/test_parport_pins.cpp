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

TEST_CASE("user outputs: \"out 1\" to \"out 4\" parse, print, and compile to their register bits with the inversions") {
  auto a = parse_pin_signal("out 3");
  CHECK(a.signal == PinSignal::Output);
  CHECK(a.axis == 2);
  CHECK(pin_signal_text(a) == "out 3");
  CHECK(pin_signal_text(parse_pin_signal("out 1")) == "out 1");
  for (const char* bad : {"out 0", "out 5", "out", "out X", "out 12", "output 1"})
    CHECK_THROWS_WITH(parse_pin_signal(bad), Catch::Contains("\"out 1\" to \"out 4\""));

  auto m = *named_pin_map("shd-adapter");
  m.pins[5] = parse_pin_signal("out 1");   // data bit 3, the adapter's unused step C
  m.pins[9] = parse_pin_signal("out 2");   // data bit 7, active low
  m.pins[9].invert = true;
  m.pins[1] = parse_pin_signal("out 3");   // control bit 0, STROBE: inverted by the port
  m.pins[16] = parse_pin_signal("out 4");  // control bit 2, INIT: not inverted by the port; active low
  m.pins[16].invert = true;
  REQUIRE_NOTHROW(validate_pin_map(m));
  auto c = compile_pins(m);
  CHECK(c.output_count == 4);
  CHECK(c.output_data == std::array<std::uint8_t, 4>{0x08, 0x80, 0, 0});
  CHECK(c.output_control == std::array<std::uint8_t, 4>{0, 0, 0x01, 0x04});
  CHECK(c.data_invert == 0x80);
  CHECK(c.control_invert == 0x0F);  // STROBE, AUTOFEED, SELECT IN by the port; INIT per pin
  CHECK(c.step_mask == AxisArray<std::uint8_t>{0x01, 0x02, 0x04});  // the rest as before
  CHECK(c.dir_mask == AxisArray<std::uint8_t>{0x10, 0x20, 0x40});
  CHECK(compile_pins(*named_pin_map("shd-adapter")).output_count == 0);
  CHECK(compile_pins(*named_pin_map("3d-step")).output_count == 0);
}

TEST_CASE("user outputs: on an input pin, twice, with a gap, or in place of a step pin are refused naming the pin") {
  auto m = *named_pin_map("shd-adapter");
  m.pins[15] = parse_pin_signal("out 1");  // the probe's status pin
  CHECK_THROWS_WITH(validate_pin_map(m), Catch::Contains("pin 15 (out 1)") && Catch::Contains("outputs go on pins 1-9, 14, 16, 17"));
  m = *named_pin_map("shd-adapter");
  m.pins[5] = parse_pin_signal("out 1");
  m.pins[14] = parse_pin_signal("out 1");
  CHECK_THROWS_WITH(validate_pin_map(m), Catch::Contains("pin 14 (out 1)") && Catch::Contains("is on pin 5 already"));
  m = *named_pin_map("shd-adapter");
  m.pins[5] = parse_pin_signal("out 1");
  m.pins[17] = parse_pin_signal("out 3");
  CHECK_THROWS_WITH(validate_pin_map(m), Catch::Contains("out 3 (pin 17) without out 2") && Catch::Contains("from 1 without gaps"));
  m = *named_pin_map("shd-adapter");
  m.pins[2] = parse_pin_signal("out 1");  // step X's pin
  CHECK_THROWS_WITH(validate_pin_map(m), Catch::Contains("axis X needs exactly one step"));
  m = *named_pin_map("3d-step");
  m.pins[8] = parse_pin_signal("out 1");
  m.pins[9] = parse_pin_signal("out 2");
  m.pins[14] = parse_pin_signal("out 3");
  m.pins[16] = parse_pin_signal("out 4");
  CHECK_NOTHROW(validate_pin_map(m));
}
