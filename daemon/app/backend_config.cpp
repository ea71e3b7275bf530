// Reading the parport and drive-kit sections of "backend" (strict, like the rest of the
// configuration: unknown keys and wrong forms stop start-up naming file and key).
#include "backend_config.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "config.hpp"
#include "json_object.hpp"

namespace imess::app {

namespace {

// A port address as a number (888) or a hex string ("0x378").
std::uint16_t port_address(JsonObject& o, const std::string& key, std::uint16_t def) {
  o.accept(key);
  if (!o.has(key)) return def;
  const char* expected = "a port address from 0 to 0xFFFF, e.g. 888 or \"0x378\"";
  if (!o.is_string(key)) {
    if (!o.is_number(key)) o.fail(key, expected);
    return static_cast<std::uint16_t>(o.whole(key, def, 0, 0xFFFF));
  }
  std::string s = o.text(key, "");
  std::size_t used = 0;
  unsigned long v = 0;
  try {
    v = std::stoul(s, &used, 0);
  } catch (const std::logic_error&) {
    o.fail(key, expected);
  }
  if (used != s.size() || s.find('-') != std::string::npos || v > 0xFFFF) o.fail(key, expected);
  return static_cast<std::uint16_t>(v);
}

void read_port_io(JsonObject& b, PortBackendConfig& p, bool simulated) {
  auto& io = p.port_io;
  io.type = simulated ? "sim" : "x86";
  auto o = b.object("port_io");
  if (!o) return;
  if (simulated) {
    o->text("type", "sim", {"sim"});
  } else {
    io.type = o->text("type", io.type, {"x86", "ppdev", "sim"});
  }
  io.file = o->text("file", io.file);
  io.base = port_address(*o, "base", io.base);
  io.count = static_cast<int>(o->whole("count", io.count, 1, 4096));
  io.device = o->text("device", io.device);
  o->finish();
}

hal::PinMap read_pins(JsonObject& b) {
  hal::PinMap map = *hal::named_pin_map("shd-adapter");
  b.accept("pins");
  if (!b.has("pins")) return map;
  const char* forms = "\"shd-adapter\", \"3d-step\" or an object {\"map\": ..., \"<pin>\": \"<signal>\"}";
  auto named = [&](const std::string& name) {
    auto m = hal::named_pin_map(name);
    if (!m) b.fail("pins", forms);
    return *m;
  };
  if (b.is_string("pins")) return named(b.text("pins", "shd-adapter"));
  if (!b.is_object("pins")) b.fail("pins", forms);
  auto o = b.object("pins");
  std::string base = o->text("map", "none", {"none", "shd-adapter", "3d-step"});
  if (base == "none") {
    map = hal::PinMap{};
    map.name = "custom";
  } else {
    map = named(base);
    map.name = base + " (modified)";
  }
  for (int pin = 1; pin <= hal::kMaxPin; ++pin) {
    auto key = std::to_string(pin);
    if (!o->has(key)) continue;
    std::string text = o->text(key, "");
    bool invert = false;
    for (const char* suffix : {" inverted", " invert"}) {
      std::string sfx(suffix);
      if (text.size() > sfx.size() && text.compare(text.size() - sfx.size(), sfx.size(), sfx) == 0) {
        invert = true;
        text.erase(text.size() - sfx.size());
      }
    }
    try {
      auto a = hal::parse_pin_signal(text);
      a.invert = invert;
      map.pins[pin] = a;
    } catch (const std::invalid_argument& e) {
      o->fail(key, std::string("a pin signal: ") + e.what() + "; append \" inverted\" for an active-low pin");
    }
  }
  o->finish("\"map\" and the pin numbers \"1\" to \"" + std::to_string(hal::kMaxPin) + "\"");
  try {
    hal::validate_pin_map(map);
  } catch (const std::invalid_argument& e) {
    b.fail("pins", std::string("a workable pin map (") + e.what() + ")");
  }
  return map;
}

}  // namespace

void read_stepper_section(JsonObject& b, DaemonConfig& cfg, bool simulated) {
  auto& s = cfg.ports.stepper;
  cfg.ports.port_io.base = 0x378;  // LPT1
  read_port_io(b, cfg.ports, simulated);
  s.pins = read_pins(b);
  s.base = port_address(b, "parport_base", simulated ? cfg.ports.port_io.base : 0x378);
  s.base_period_ns = b.number("base_period_us", s.base_period_ns / 1000, 1, 1000) * 1000;
  s.step_len_ns = b.number("step_len_us", s.step_len_ns / 1000, 0, 1000) * 1000;
  s.step_space_ns = b.number("step_space_us", s.step_space_ns / 1000, 0, 1000) * 1000;
  s.dir_setup_ns = b.number("dir_setup_us", s.dir_setup_ns / 1000, 0, 1000) * 1000;
  s.dir_hold_ns = b.number("dir_hold_us", s.dir_hold_ns / 1000, 0, 1000) * 1000;
  if (b.has("initial_position")) cfg.ports.initial_position_set = true;
  s.initial_position = b.vec3("initial_position", s.initial_position, 1e5);
  if (auto axes = b.object("axes")) {
    for (int a = 0; a < hal::kParportAxes; ++a) {
      auto ax = axes->object(std::string(1, hal::kAxisLetters[a]));
      if (!ax) continue;
      auto& x = s.axes[a];
      x.steps_per_mm = ax->number("steps_per_mm", x.steps_per_mm, 0.01, 1e6);
      x.max_speed = ax->number("max_speed", x.max_speed, 0.01, 5000);
      x.max_accel = ax->number("max_accel", x.max_accel, 0.1, 1e6);
      x.index_pitch_mm = ax->number("index_pitch_mm", x.index_pitch_mm, 0, 1000);
      x.index_width_mm = ax->number("index_width_mm", x.index_width_mm, 0, 100);
      ax->finish();
    }
    axes->finish();
  }
  if (simulated) {
    if (auto p = b.object("sim_power_stage")) {
      auto& ps = cfg.ports.stepper_sim;
      ps.min_step_len_ns = p->number("min_step_len_us", ps.min_step_len_ns / 1000, 0, 1000) * 1000;
      ps.min_step_space_ns = p->number("min_step_space_us", ps.min_step_space_ns / 1000, 0, 1000) * 1000;
      ps.min_dir_setup_ns = p->number("min_dir_setup_us", ps.min_dir_setup_ns / 1000, 0, 1000) * 1000;
      ps.min_dir_hold_ns = p->number("min_dir_hold_us", ps.min_dir_hold_ns / 1000, 0, 1000) * 1000;
      p->finish();
    }
  }
}

namespace {

// Input/output bit masks as numbers or "0x..." strings.
std::uint16_t bits(JsonObject& o, const std::string& key, std::uint16_t def) { return port_address(o, key, def); }

std::string hex(unsigned v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%X", v);
  return buf;
}

// "outputs": [{"port": "0x302", "bit": 0}, ...]: user outputs 1.. replacing the map's; each
// a bit 0-15 of a port in the port_io range, checked against the kit's own ports and bits.
void read_drive_outputs(JsonObject& b, PortBackendConfig& p) {
  auto& d = p.drive;
  const unsigned first = p.port_io.base, last = first + static_cast<unsigned>(p.port_io.count) - 1;
  if (auto outs = b.objects("outputs")) {
    if (outs->size() > hal::kMaxDriveKitOutputs)
      b.fail("outputs", "at most " + std::to_string(hal::kMaxDriveKitOutputs) + " outputs [{\"port\": \"0x302\", \"bit\": 0}, ...]");
    d.outputs = {};
    d.output_count = static_cast<int>(outs->size());
    for (std::size_t i = 0; i < outs->size(); ++i) {
      auto& o = (*outs)[i];
      const std::string range = "a port address from " + hex(first) + " to " + hex(last) + " (backend.port_io's base and count)";
      if (!o.has("port")) o.fail("port", range);
      const std::uint16_t port = port_address(o, "port", 0);
      if (port < first || port > last) o.fail("port", range);
      if (!o.has("bit")) o.fail("bit", "a bit number from 0 to 15");
      const auto bit = o.whole("bit", 0, 0, 15);
      o.finish();
      d.outputs[i] = {port, static_cast<std::uint16_t>(1u << bit)};
    }
  } else {
    for (int i = 0; i < d.output_count; ++i)
      if (d.outputs[i].port < first || d.outputs[i].port > last)
        b.fail("outputs", "given when the port map's outputs lie outside backend.port_io (output " + std::to_string(i + 1) +
                              " on port " + hex(d.outputs[i].port) + ", the ports are " + hex(first) + " to " + hex(last) +
                              "): [{\"port\": ..., \"bit\": ...}, ...], [] for none");
  }
  try {
    hal::validate_drive_kit_outputs(d);
  } catch (const std::invalid_argument& e) {
    b.fail("outputs", std::string("user outputs on free port bits (") + e.what() +
                          "; \"outputs\": [] for none)");
  }
}

}  // namespace

void read_drive_section(JsonObject& b, DaemonConfig& cfg, bool simulated) {
  auto& d = cfg.ports.drive;
  cfg.ports.port_io.base = 0x300;  // BRIEF §5
  read_port_io(b, cfg.ports, simulated);
  const auto& layout = cfg.core.layout;
  auto map = b.text("port_map", "mrm-b", {"mrm-a", "mrm-b"});
  d = *hal::named_drive_kit_map(map, layout.count);
  d.layout = layout;
  d.mode = static_cast<int>(b.whole("mode", d.mode, 1, 2));
  d.sync_port = port_address(b, "sync_port", d.sync_port);
  d.inputs_port = port_address(b, "inputs_port", d.inputs_port);
  d.outputs_port = port_address(b, "outputs_port", d.outputs_port);
  d.latch_status_port = port_address(b, "latch_status_port", d.latch_status_port);
  d.probe_bit = bits(b, "probe_bit", d.probe_bit);
  d.safe_outputs = bits(b, "safe_outputs", d.safe_outputs);
  d.dac_limit_mv = b.number("dac_limit_mv", d.dac_limit_mv, 1, 32767);
  if (auto sb = b.objects("safety_inputs")) {
    if (sb->size() > 4) b.fail("safety_inputs", "at most 4 inputs");
    d.safety_bits = {0, 0, 0, 0};
    for (std::size_t i = 0; i < sb->size(); ++i) {
      (*sb)[i].text("name", "");  // for people: which switch it is
      d.safety_bits[i] = bits((*sb)[i], "bit", 0);
      (*sb)[i].finish();
    }
  }
  if (b.has("initial_position")) cfg.ports.initial_position_set = true;
  d.initial_position = b.axis_values("initial_position", d.initial_position, layout, 1e5);
  if (b.has("inputs2_port") || layout.count > 3) d.inputs2_port = port_address(b, "inputs2_port", d.inputs2_port);
  if (auto axes = b.object("axes")) {
    for (int a = 0; a < layout.count; ++a) {
      auto ax = axes->object(std::string(1, layout.letters[a]));
      if (!ax) continue;
      auto& x = d.axes[a];
      x.command_port = port_address(*ax, "command_port", x.command_port);
      x.position_port = port_address(*ax, "position_port", x.position_port);
      x.latch_port = port_address(*ax, "latch_port", x.latch_port);
      x.position_unit_mm = ax->number("position_unit_mm", x.position_unit_mm, 1e-6, 10);
      x.mv_per_mm_s = ax->number("mv_per_mm_s", x.mv_per_mm_s, 1e-3, 1e5);
      x.kp = ax->number("kp", x.kp, 0, 1e4);
      x.ki = ax->number("ki", x.ki, 0, 1e6);
      x.kd = ax->number("kd", x.kd, 0, 1e3);
      x.feed_forward = ax->number("feed_forward", x.feed_forward, 0, 2);
      x.max_following_error = ax->number("max_following_error", x.max_following_error, 1e-3, 100);
      x.in_position_mm = ax->number("in_position_mm", x.in_position_mm, 1e-5, 10);
      x.max_speed = ax->number("max_speed", x.max_speed, 0.01, 5000);
      x.max_accel = ax->number("max_accel", x.max_accel, 0.1, 1e6);
      x.index_pitch_mm = ax->number("index_pitch_mm", x.index_pitch_mm, 0, 1000);
      x.index_width_mm = ax->number("index_width_mm", x.index_width_mm, 0, 100);
      x.limit_neg_bit = bits(*ax, "limit_neg_bit", x.limit_neg_bit);
      x.limit_pos_bit = bits(*ax, "limit_pos_bit", x.limit_pos_bit);
      x.home_bit = bits(*ax, "home_bit", x.home_bit);
      x.enable_bit = bits(*ax, "enable_bit", x.enable_bit);
      x.inputs_bank = static_cast<std::uint8_t>(ax->whole("inputs_bank", x.inputs_bank, 0, 1));
      if (simulated) cfg.ports.drive_sim.mm_s_per_volt[a] = ax->number("sim_mm_s_per_volt", cfg.ports.drive_sim.mm_s_per_volt[a], 1e-3, 1e4);
      ax->finish();
    }
    axes->finish("one object per axis letter of axes.letters (" + layout.names() + ")");
  }
  read_drive_outputs(b, cfg.ports);
  if (simulated) cfg.ports.drive_sim.period_ns = b.number("sim_period_us", cfg.ports.drive_sim.period_ns / 1000, 1, 10000) * 1000;
}

void finish_stepper_config(DaemonConfig& cfg, bool simulated) {
  auto& p = cfg.ports;
  auto& s = p.stepper;
  s.servo_period_ns = cfg.period_us * 1000;
  s.tip_reversed = cfg.card.tip_reversed;
  // The simulator knows where the machine stands; a real one starts at the configured place.
  if (simulated && !p.initial_position_set) s.initial_position = cfg.sim.mechanics.start.head<3>();
  for (int a = 0; a < hal::kParportAxes; ++a) {
    s.axes[a].home_direction = cfg.core.axes[a].home_direction;
  }
  auto& ss = p.stepper_sim;
  ss.pins = s.pins;
  ss.base = s.base;
  for (int a = 0; a < hal::kParportAxes; ++a) {
    ss.steps_per_mm[a] = s.axes[a].steps_per_mm;
    ss.home_direction[a] = cfg.core.axes[a].home_direction;
  }
}

void finish_drive_config(DaemonConfig& cfg, bool simulated) {
  auto& p = cfg.ports;
  auto& d = p.drive;
  d.servo_period_ns = cfg.period_us * 1000;
  d.tip_reversed = cfg.card.tip_reversed;
  if (simulated && !p.initial_position_set) d.initial_position = cfg.sim.mechanics.start;
  d.layout = cfg.core.layout;
  for (int a = 0; a < d.layout.count; ++a) d.axes[a].home_direction = cfg.core.axes[a].home_direction;
  p.drive_sim.ports = d;
}

void read_card_keys(JsonObject& b, DaemonConfig& cfg) {
  cfg.card.firmware = b.text("firmware", cfg.card.firmware);
  const double ferr = b.number("max_following_error", cfg.card.max_following_error[0], 0.01, 100);
  cfg.card.max_following_error = {ferr, ferr, ferr};
  // docs/servo-card-link.md, "Host stalls"
  cfg.card.stream.lead = b.number("lead_ms", cfg.card.stream.lead * 1000, 5, cfg.card.stream.max_lead * 1000) / 1000;
}

}  // namespace imess::app
