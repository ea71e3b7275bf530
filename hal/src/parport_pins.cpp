// Pin maps of the SHD adapter and the 3D-Step box, parsing and compilation to masks.
#include "imess/hal/parport_pins.hpp"

#include <algorithm>
#include <stdexcept>

namespace imess::hal {

PinLocation pin_location(int pin) noexcept {
  if (pin >= 2 && pin <= 9) return {0, static_cast<std::uint8_t>(1u << (pin - 2)), false, false};
  switch (pin) {
    case 1: return {2, 0x01, true, false};    // STROBE
    case 14: return {2, 0x02, true, false};   // AUTOFEED
    case 16: return {2, 0x04, false, false};  // INIT
    case 17: return {2, 0x08, true, false};   // SELECT IN
    case 15: return {1, 0x08, false, true};   // ERROR
    case 13: return {1, 0x10, false, true};   // SELECT
    case 12: return {1, 0x20, false, true};   // PAPER OUT
    case 10: return {1, 0x40, false, true};   // ACK
    case 11: return {1, 0x80, true, true};    // BUSY, inverted by the port
    default: return {};
  }
}

namespace {
PinAssignment sig(PinSignal s, int axis = -1) { return {s, static_cast<std::int8_t>(axis), false}; }
}  // namespace

std::optional<PinMap> named_pin_map(std::string_view name) {
  PinMap m;
  m.name = std::string(name);
  auto& p = m.pins;
  if (name == "shd-adapter") {
    p[2] = sig(PinSignal::Step, 0);
    p[3] = sig(PinSignal::Step, 1);
    p[4] = sig(PinSignal::Step, 2);
    p[6] = sig(PinSignal::Dir, 0);
    p[7] = sig(PinSignal::Dir, 1);
    p[8] = sig(PinSignal::Dir, 2);
    p[10] = sig(PinSignal::EndRef, 0);
    p[11] = sig(PinSignal::Stop);
    p[12] = sig(PinSignal::EndRef, 1);
    p[13] = sig(PinSignal::EndRef, 2);
    p[15] = sig(PinSignal::Probe);  // end/ref C on the adapter; no C axis on a CMM
    return m;
  }
  if (name == "3d-step") {
    p[2] = sig(PinSignal::Dir, 0);
    p[3] = sig(PinSignal::Step, 0);
    p[4] = sig(PinSignal::Dir, 1);
    p[5] = sig(PinSignal::Step, 1);
    p[6] = sig(PinSignal::Dir, 2);
    p[7] = sig(PinSignal::Step, 2);
    p[10] = sig(PinSignal::EndRef, 0);  // the source prints "end/ref Z (sic)"; X has no other pin
    p[11] = sig(PinSignal::Stop);       // "enable = stop"
    p[12] = sig(PinSignal::EndRef, 1);
    p[13] = sig(PinSignal::EndRef, 2);
    p[15] = sig(PinSignal::Probe);      // (end/ref C)
    return m;
  }
  return std::nullopt;
}

PinAssignment parse_pin_signal(std::string_view text) {
  auto fail = [&] {
    throw std::invalid_argument("'" + std::string(text) +
                                "' is not a pin signal (accepted: \"step X\", \"dir X\", \"endref X\", \"limit- X\", "
                                "\"limit+ X\", \"home X\" for X, Y or Z; \"out 1\" to \"out 4\"; \"probe\", \"stop\", "
                                "\"enable\", \"none\")");
  };
  std::string_view word = text, axis;
  if (auto sp = text.find(' '); sp != std::string_view::npos) {
    word = text.substr(0, sp);
    axis = text.substr(sp + 1);
  }
  PinAssignment a;
  if (word == "out") {
    if (axis.size() != 1 || axis[0] < '1' || axis[0] > '0' + kParportOutputs) fail();
    a.signal = PinSignal::Output;
    a.axis = static_cast<std::int8_t>(axis[0] - '1');
    return a;
  }
  struct Name {
    const char* word;
    PinSignal s;
    bool per_axis;
  };
  static constexpr Name kNames[] = {{"step", PinSignal::Step, true},       {"dir", PinSignal::Dir, true},
                                    {"endref", PinSignal::EndRef, true},   {"limit-", PinSignal::LimitNeg, true},
                                    {"limit+", PinSignal::LimitPos, true}, {"home", PinSignal::Home, true},
                                    {"probe", PinSignal::Probe, false},    {"stop", PinSignal::Stop, false},
                                    {"enable", PinSignal::Enable, false},  {"none", PinSignal::None, false}};
  for (const auto& n : kNames) {
    if (word != n.word) continue;
    a.signal = n.s;
    if (n.per_axis) {
      if (axis.size() != 1) fail();
      for (int i = 0; i < kParportAxes; ++i)
        if (axis[0] == kAxisLetters[i]) a.axis = static_cast<std::int8_t>(i);
      if (a.axis < 0) fail();
    } else if (!axis.empty()) {
      fail();
    }
    return a;
  }
  fail();
  return a;
}

std::string pin_signal_text(const PinAssignment& a) {
  std::string s;
  switch (a.signal) {
    case PinSignal::None: return "none";
    case PinSignal::Step: s = "step"; break;
    case PinSignal::Dir: s = "dir"; break;
    case PinSignal::EndRef: s = "endref"; break;
    case PinSignal::LimitNeg: s = "limit-"; break;
    case PinSignal::LimitPos: s = "limit+"; break;
    case PinSignal::Home: s = "home"; break;
    case PinSignal::Probe: s = "probe"; break;
    case PinSignal::Stop: s = "stop"; break;
    case PinSignal::Enable: s = "enable"; break;
    case PinSignal::Output: s = "out " + std::to_string(a.axis + 1); break;
  }
  if (a.axis >= 0 && a.signal != PinSignal::Output) s += std::string(" ") + kAxisLetters[a.axis];
  if (a.invert) s += " (inverted)";
  return s;
}

void validate_pin_map(const PinMap& map) {
  AxisArray<int> steps{}, dirs{};
  int probes = 0, stops = 0;
  std::array<int, kParportOutputs> output_pin{};  // the pin of out N (0: none yet)
  for (int pin = 1; pin <= kMaxPin; ++pin) {
    const auto& a = map.pins[pin];
    if (a.signal == PinSignal::None) continue;
    auto loc = pin_location(pin);
    auto where = "pin " + std::to_string(pin) + " (" + pin_signal_text(a) + ")";
    if (loc.offset < 0) throw std::invalid_argument(where + ": not a signal pin of the parallel port");
    bool is_input = a.signal == PinSignal::EndRef || a.signal == PinSignal::LimitNeg || a.signal == PinSignal::LimitPos ||
                    a.signal == PinSignal::Home || a.signal == PinSignal::Probe || a.signal == PinSignal::Stop;
    if (is_input != loc.input)
      throw std::invalid_argument(where + (is_input ? ": inputs go on pins 10, 11, 12, 13, 15"
                                                    : ": outputs go on pins 1-9, 14, 16, 17"));
    if ((a.signal == PinSignal::Step || a.signal == PinSignal::Dir) && loc.offset != 0)
      throw std::invalid_argument(where + ": step and dir go on the data pins 2-9");
    if (a.signal == PinSignal::Output) {
      if (a.axis < 0 || a.axis >= kParportOutputs) throw std::invalid_argument(where + ": outputs are out 1 to out 4");
      if (int other = output_pin[a.axis])
        throw std::invalid_argument(where + ": out " + std::to_string(a.axis + 1) + " is on pin " + std::to_string(other) +
                                    " already; one pin per output");
      output_pin[a.axis] = pin;
    }
    if (a.signal == PinSignal::Step) ++steps[a.axis];
    if (a.signal == PinSignal::Dir) ++dirs[a.axis];
    probes += a.signal == PinSignal::Probe;
    stops += a.signal == PinSignal::Stop;
  }
  for (int ax = 0; ax < kParportAxes; ++ax)
    if (steps[ax] != 1 || dirs[ax] != 1)
      throw std::invalid_argument(std::string("axis ") + kAxisLetters[ax] + " needs exactly one step and one dir pin");
  if (probes > 1 || stops > 1) throw std::invalid_argument("at most one probe pin and one stop pin");
  for (int n = kParportOutputs - 1; n > 0; --n)
    for (int m = 0; m < n && output_pin[n]; ++m)
      if (!output_pin[m])
        throw std::invalid_argument("out " + std::to_string(n + 1) + " (pin " + std::to_string(output_pin[n]) + ") without out " +
                                    std::to_string(m + 1) + ": outputs are numbered from 1 without gaps");
}

CompiledPins compile_pins(const PinMap& map) {
  CompiledPins c;
  for (int pin = 1; pin <= kMaxPin; ++pin) {
    const auto& a = map.pins[pin];
    if (a.signal == PinSignal::None) continue;
    auto loc = pin_location(pin);
    if (loc.offset < 0) continue;
    std::uint8_t m = loc.mask;
    bool flip = a.invert != loc.hw_inverted;  // register bit active-low
    switch (a.signal) {
      case PinSignal::Step: c.step_mask[a.axis] |= m; break;
      case PinSignal::Dir: c.dir_mask[a.axis] |= m; break;
      case PinSignal::Enable: (loc.offset == 0 ? c.enable_data_mask : c.enable_control_mask) |= m; break;
      case PinSignal::EndRef: c.endref[a.axis] |= m; break;
      case PinSignal::LimitNeg: c.limit_neg[a.axis] |= m; break;
      case PinSignal::LimitPos: c.limit_pos[a.axis] |= m; break;
      case PinSignal::Home: c.home[a.axis] |= m; break;
      case PinSignal::Probe: c.probe |= m; break;
      case PinSignal::Stop: c.stop |= m; break;
      case PinSignal::Output:
        (loc.offset == 0 ? c.output_data : c.output_control)[a.axis] |= m;
        c.output_count = std::max(c.output_count, a.axis + 1);
        break;
      case PinSignal::None: break;
    }
    if (loc.offset == 0 && flip) c.data_invert |= m;
    if (loc.offset == 2 && flip) c.control_invert |= m;
    if (loc.offset == 1 && flip) c.status_xor |= m;
  }
  // Unused control pins with hardware inversion rest low at the connector.
  for (int pin : {1, 14, 17})
    if (map.pins[pin].signal == PinSignal::None) c.control_invert |= pin_location(pin).mask;
  return c;
}

}  // namespace imess::hal
