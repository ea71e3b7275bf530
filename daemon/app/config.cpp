// Configuration loading: JSON (strict, documented in docs/configuration.md) and messdrc.
#include "config.hpp"

#include "imess/core/path_machine.hpp"

#include <boost/asio/ip/address.hpp>
#include <algorithm>
#include <cctype>
#include <map>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "backend_registry.hpp"
#include "config_file.hpp"
#include "imess/protocol/numbers.hpp"
#include "json_object.hpp"
#include "json_text.hpp"
#include "param_config.hpp"

namespace imess::app {

namespace {

sim::Solid read_solid(JsonObject& o) {
  auto type = o.text("type", "", {"plane", "box", "sphere", "cylinder"});
  if (type.empty()) o.fail("type", "one of \"plane\", \"box\", \"sphere\", \"cylinder\"");
  if (type == "plane") {
    sim::PlaneSolid p;
    p.point = o.vec3("point", p.point);
    p.normal = o.vec3("normal", p.normal);
    if (p.normal.norm() < 1e-9) o.fail("normal", "a non-zero vector");
    o.finish();
    return p;
  }
  if (type == "box") {
    sim::BoxSolid b;
    b.center = o.vec3("center", b.center);
    b.size = o.vec3("size", Eigen::Vector3d(100, 100, 100));
    if ((b.size.array() <= 0).any()) o.fail("size", "three positive lengths");
    b.yaw_deg = o.number("yaw_deg", 0, -360, 360);
    if (auto f = o.object("fillet")) {
      auto edge = f->text("edge", "front-top", {"front-top", "back-top", "left-top", "right-top"});
      b.fillet = edge == "front-top"  ? sim::FilletEdge::FrontTop
                 : edge == "back-top" ? sim::FilletEdge::BackTop
                 : edge == "left-top" ? sim::FilletEdge::LeftTop
                                      : sim::FilletEdge::RightTop;
      b.fillet_radius = f->number("radius", 5, 0.001, b.size.minCoeff() / 2);
      f->finish();
    }
    if (auto bores = o.objects("bores"))
      for (auto& bo : *bores) {
        sim::Bore bore;
        bore.x = bo.number("x", 0, -b.size.x() / 2, b.size.x() / 2);
        bore.y = bo.number("y", 0, -b.size.y() / 2, b.size.y() / 2);
        bore.diameter = bo.number("diameter", 10, 0.01, b.size.head<2>().minCoeff());
        bo.finish();
        b.bores.push_back(bore);
      }
    o.finish();
    return b;
  }
  if (type == "sphere") {
    sim::SphereSolid s;
    s.center = o.vec3("center", s.center);
    s.diameter = o.number("diameter", 25, 0.01, 1e4);
    o.finish();
    return s;
  }
  sim::CylinderSolid c;
  c.base = o.vec3("base", c.base);
  c.diameter = o.number("diameter", 20, 0.01, 1e4);
  c.height = o.number("height", 50, 0.01, 1e4);
  o.finish();
  return c;
}

std::string checked_address(JsonObject& o, const std::string& key, const std::string& def) {
  std::string text = o.text(key, def);
  boost::system::error_code ec;
  (void)boost::asio::ip::make_address(text, ec);
  if (ec) o.fail(key, "an IPv4 or IPv6 address such as \"0.0.0.0\", \"127.0.0.1\" or \"::\"");
  return text;
}

// "control": who may connect, control and force a take-over; slots and liveness limits.
void read_control(JsonObject& c, const std::string& path, net::ControlConfig& out) {
  auto hosts = [&](const std::string& key, net::HostList& list) {
    auto texts = c.texts(key, "an address with an optional prefix length such as \"127.0.0.0/8\" or \"::1/128\"");
    if (!texts) return;
    try {
      list = net::HostList::parse(*texts);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(path + ": key '" + c.where(key) + "': " + e.what());
    }
  };
  hosts("hosts", out.hosts);
  hosts("observe_hosts", out.observe_hosts);
  hosts("force_hosts", out.force_hosts);
  out.reserved_slots = static_cast<std::size_t>(c.number("reserved_slots", double(out.reserved_slots), 0, 10000));
  out.idle_drop_s = c.number("idle_drop_s", out.idle_drop_s, 1, 86400);
  out.handover_s = c.number("handover_s", out.handover_s, 0, 86400);
  out.no_command_drop_s = c.number("no_command_drop_s", out.no_command_drop_s, 0, 86400);
  out.write_stall_s = c.number("write_stall_s", out.write_stall_s, 0.5, 3600);
  out.max_in_flight = static_cast<std::uint32_t>(c.number("max_in_flight", out.max_in_flight, 1, 200));
  c.finish();
}

}  // namespace

void load_json_config(const std::string& path, DaemonConfig& cfg) {
  load_config_text(read_config_file(path, "configuration file", "--config"), path, cfg);
}

namespace {

void read_server_section(JsonObject& s, const std::string& path, DaemonConfig& cfg) {
  cfg.server.port = static_cast<std::uint16_t>(s.whole("port", cfg.server.port, 0, 65535));
  cfg.server.listen = checked_address(s, "listen", cfg.server.listen);
  const auto ipp = s.whole("ippdme_port", cfg.server.ippdme.on ? cfg.server.ippdme.port : 0, 0, 65535);
  cfg.server.ippdme.on = ipp != 0;
  cfg.server.ippdme.port = static_cast<std::uint16_t>(ipp);
  const auto http = s.whole("http_port", cfg.server.web.on ? cfg.server.web.port : 0, 0, 65535);
  cfg.server.web.on = http != 0;
  cfg.server.web.port = static_cast<std::uint16_t>(http);
  const std::string root = s.text("http_root", "");
  if (!root.empty()) {  // relative to the configuration file, as programs.folder
    std::filesystem::path r(root);
    if (r.is_relative()) r = std::filesystem::absolute(std::filesystem::path(path).parent_path() / r);
    cfg.server.web.root = r.lexically_normal().string();
  }
  cfg.server.web.token = s.text("http_token", cfg.server.web.token);
  read_param_keys(s, "server", cfg);  // report_hz: the ReportHz parameter
  cfg.server.max_clients = static_cast<std::size_t>(s.whole("max_clients", static_cast<long long>(cfg.server.max_clients), 1, 10000));
  cfg.server.event_backstop_ms = s.number("event_backstop_ms", cfg.server.event_backstop_ms, 1, 600000);
  cfg.server.max_queue_bytes = static_cast<std::size_t>(
      s.whole("max_queue_bytes", static_cast<long long>(cfg.server.max_queue_bytes), 4096, 1LL << 30));
  s.finish();
}

void read_motion_section(JsonObject& m, DaemonConfig& cfg) {
  read_param_keys(m, "motion", cfg);  // period_us, tip_radius, ...: the parameter registry's entries
  cfg.realtime = m.boolean("realtime", cfg.realtime);
  cfg.core.max_velocity = m.number("max_velocity", cfg.core.max_velocity, 0.1, 2000);
  cfg.home_on_start = m.boolean("home_on_start", cfg.home_on_start);
  m.finish();
}

// One axis of "axes"; its speed and acceleration default to the motion section's. Rotary
// axes: degrees and deg/s throughout.
void read_axis(JsonObject& ax, DaemonConfig& cfg, int a, core::AxisSettings& s) {
  auto& kind = cfg.core.layout.kinds[a];
  kind = ax.text("kind", kind == hal::AxisKind::Rotary ? "rotary" : "linear", {"linear", "rotary"}) == "rotary"
             ? hal::AxisKind::Rotary
             : hal::AxisKind::Linear;
  s.travel_min = ax.number("travel_min", s.travel_min, -1e5, 1e5);
  s.travel_max = ax.number("travel_max", s.travel_max, -1e5, 1e5);
  if (s.travel_max <= s.travel_min) ax.fail("travel_max", "greater than travel_min");
  auto dir = ax.text("home_direction", s.home_direction < 0 ? "neg" : "pos", {"neg", "pos"});
  s.home_direction = dir == "neg" ? -1 : 1;
  s.home_position = ax.number("home_position", s.home_direction < 0 ? s.travel_min : s.travel_max, -1e5, 1e5);
  if (s.home_position < s.travel_min || s.home_position > s.travel_max)
    ax.fail("home_position", "a coordinate within the travel, from travel_min " + compact(s.travel_min) +
                                 " to travel_max " + compact(s.travel_max));
  s.max_velocity = ax.number("max_velocity", cfg.core.max_velocity, 0.1, 2000);
  s.max_accel = ax.number("max_accel", cfg.core.params.max_accel, 1, 20000);
  ax.finish();
}

// "letters": the machine's axes in their order ("XYZ" when absent: the 1996 machine), then
// one object per letter. An axis beyond the third starts from the first's defaults.
void read_axes_section(JsonObject& axes, DaemonConfig& cfg) {
  const std::string letters = axes.text("letters", cfg.core.layout.names());
  try {
    cfg.core.layout = hal::make_layout(letters);
  } catch (const std::invalid_argument& e) {
    axes.fail("letters", e.what());
  }
  for (int a = 3; a < cfg.core.layout.count; ++a) cfg.core.axes[a] = core::AxisSettings{};
  for (int a = 0; a < cfg.core.layout.count; ++a) {
    auto ax = axes.object(std::string(1, cfg.core.layout.letters[a]));
    if (ax) read_axis(*ax, cfg, a, cfg.core.axes[a]);
  }
  axes.finish();  // names what it accepts: the letters' objects and "letters"
}

void read_backend_section(JsonObject& b, DaemonConfig& cfg) {
  cfg.backend = b.text("type", cfg.backend, backend_types());
  cfg.card.tip_reversed = b.boolean("tip_reversed", cfg.card.tip_reversed);
  load_backend_section(b, cfg);  // the type's own keys: backend_registry.hpp, backends/<name>.cpp
  b.finish();
}

// The hit journal.
void read_journal_section(JsonObject& jn, DaemonConfig& cfg) {
  cfg.journal.dir = jn.text("dir", cfg.journal.dir);
  cfg.journal.fsync_interval = std::chrono::milliseconds(
      static_cast<long>(jn.number("fsync_ms", double(cfg.journal.fsync_interval.count()), 0, 10000)));
  cfg.journal.max_bytes = static_cast<std::uint64_t>(jn.number("max_bytes", double(cfg.journal.max_bytes), 4096, 1 << 30));
  cfg.journal.files = static_cast<std::size_t>(jn.number("files", double(cfg.journal.files), 1, 10000));
  jn.finish();
}

// "outputs": name -> { number, settle_ms, at_start, probe_power }. Names go on the wire
// (SetOut name on|off), so they are one word of letters, digits and '_'.
const double kDefaultProbeArmingMs = core::default_probe_output().settle_s * 1000;

void read_outputs_section(JsonObject& outs, DaemonConfig& cfg) {
  auto& core = cfg.core;
  core.output_count = 0;
  cfg.outputs_given = true;
  for (const auto& name : outs.keys()) {
    if (name == "_comment") {
      outs.text(name, "");
      continue;
    }
    const bool word = !name.empty() && name.size() < core::OutputSettings{}.name.size() &&
                      name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_") ==
                          std::string::npos;
    if (!word || name == "on" || name == "off")
      outs.fail(name, "an output name of 1 to 15 letters, digits or '_' (not on/off), as SetOut names it");
    if (core.output_count == core::kMaxOutputs) outs.fail(name, "at most " + std::to_string(core::kMaxOutputs) + " outputs");
    auto o = outs.object(name);
    if (!o) continue;
    core::OutputSettings s;
    std::copy(name.begin(), name.end(), s.name.begin());
    if (!o->has("number")) o->fail("number", "the backend's output number, a whole number from 1 to 32 (docs/hardware.md)");
    s.number = static_cast<int>(o->whole("number", 1, 1, 32));
    s.probe_power = o->boolean("probe_power", false);
    s.at_start = o->boolean("at_start", s.probe_power);
    s.settle_s = o->number("settle_ms", s.probe_power ? kDefaultProbeArmingMs : 0, 0, 60000) / 1000;
    for (int i = 0; i < core.output_count; ++i) {
      const auto& other = core.outputs[i];
      if (other.number == s.number)
        o->fail("number", "a number no other output has (" + std::to_string(s.number) + " is '" +
                              std::string(other.name_view()) + "')");
      if (other.probe_power && s.probe_power)
        o->fail("probe_power", "false: one output powers the probe, and '" + std::string(other.name_view()) + "' does");
    }
    o->finish();
    core.outputs[core.output_count++] = s;
  }
}

// "ippdme": the tools the I++ DME server offers (docs/configuration.md); the port is
// server.ippdme_port.
void read_ippdme_section(JsonObject& i, DaemonConfig& cfg) {
  auto& tools = cfg.server.ippdme.tools;
  if (auto list = i.objects("tools")) {
    tools.clear();
    for (auto& t : *list) {
      net::IppConfig::Tool tool;
      tool.name = t.text("name", "");
      if (tool.name.empty() || !std::isalpha(static_cast<unsigned char>(tool.name[0])) ||
          !std::all_of(tool.name.begin(), tool.name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)); }))
        t.fail("name", "a tool name of letters and digits starting with a letter");
      if (tool.name == "NoTool" || tool.name == "UnDefTool" || tool.name == "BaseTool")
        t.fail("name", "a name other than the reserved NoTool, UnDefTool and BaseTool");
      for (const auto& other : tools)
        if (other.name == tool.name) t.fail("name", "a name not given to another tool");
      if (t.has("radius")) tool.radius = t.number("radius", 0, 0, 50);
      t.finish();
      tools.push_back(std::move(tool));
    }
    if (list->empty()) i.fail("tools", "at least one tool (or no \"tools\" key: one RefTool with motion.tip_radius)");
  }
  i.finish();
}

// "programs": the folder Load reads, G28's and G30's poses, block delete, and which outputs and axes program words
// switch and move (docs/configuration.md). Read after "axes" and "outputs", whose names it uses.
void read_programs_section(JsonObject& p, const std::string& path, DaemonConfig& cfg) {
  auto& pc = cfg.server.programs;
  const auto& layout = cfg.core.layout;
  std::string folder = p.text("folder", "");
  if (!folder.empty()) {
    std::filesystem::path f(folder);
    if (f.is_relative()) f = std::filesystem::absolute(std::filesystem::path(path).parent_path() / f);
    pc.folder = f.lexically_normal().string();
  }
  if (p.has("home")) {
    const hal::AxisVec home = p.axis_values("home", hal::AxisVec::Zero(), layout, 1e5);
    pc.home.assign(home.data(), home.data() + layout.count);
  }
  if (p.has("g30")) {
    const hal::AxisVec g30 = p.axis_values("g30", hal::AxisVec::Zero(), layout, 1e5);
    pc.g30.assign(g30.data(), g30.data() + layout.count);
  }
  auto output_name = [&](JsonObject& o, const std::string& key, const std::string& name) {
    if (core::find_output(cfg.core, name)) return;
    std::string names;
    for (int i = 0; i < cfg.core.output_count; ++i) names += (names.empty() ? "" : ", ") + std::string(cfg.core.outputs[i].name_view());
    o.fail(key, "the name of an output of the \"outputs\" section (" + (names.empty() ? std::string("none configured") : names) + ")");
  };
  if (auto g = p.object("gcode")) {
    pc.block_delete = g->boolean("block_delete", pc.block_delete);
    pc.tool_change_pause = g->boolean("tool_change_pause", pc.tool_change_pause);
    pc.mist = g->text("mist", "");
    if (!pc.mist.empty()) output_name(*g, "mist", pc.mist);
    pc.flood = g->text("flood", "");
    if (!pc.flood.empty()) output_name(*g, "flood", pc.flood);
    pc.spindle = g->text("spindle", "");
    if (!pc.spindle.empty()) output_name(*g, "spindle", pc.spindle);
    if (auto outs = g->texts("outputs", "an output name")) {
      if (outs->size() > 32) g->fail("outputs", "at most 32 output names (M62-M65 P0 ... P31)");
      for (const auto& n : *outs) output_name(*g, "outputs", n);
      pc.outputs = *outs;
    }
    g->finish();
  }
  if (auto h = p.object("hpgl")) {
    pc.pen = h->text("pen", "z");
    if (pc.pen != "z") output_name(*h, "pen", pc.pen);
    pc.pen_up_z = h->number("pen_up_z", pc.pen_up_z, -1e5, 1e5);
    pc.pen_down_z = h->number("pen_down_z", pc.pen_down_z, -1e5, 1e5);
    pc.pen_feed = h->number("pen_feed", pc.pen_feed, 0.001, 1e4);
    pc.origin_x = h->number("origin_x", pc.origin_x, -1e5, 1e5);
    pc.origin_y = h->number("origin_y", pc.origin_y, -1e5, 1e5);
    pc.hpgl_feed = h->number("feed", pc.hpgl_feed, 0.001, 1e4);
    h->finish();
  }
  if (auto m = p.object("mrm")) {
    auto letter = [&](const std::string& key, char def) {
      if (!m->has(key)) return def;
      const std::string t = m->text(key, "");
      if (t.size() != 1 || layout.index_of(t[0]) < 0)
        m->fail(key, "one axis letter of this machine (" + layout.names() + ")");
      return t[0];
    };
    pc.mrm_a = letter("A", pc.mrm_a);
    pc.mrm_b = letter("B", pc.mrm_b);
    pc.mrm_c = letter("C", pc.mrm_c);
    pc.gripper = m->text("gripper", pc.gripper);
    output_name(*m, "gripper", pc.gripper);
    m->finish();
  }
  p.finish();
}

// sim.probe.type: "trigger" (the switch only) or "analog" (a measuring probe: its deflection
// vector every step, sim/analog_probe.hpp), with the analog probe's range, noise, spring rate and
// noise seed — refused on a trigger probe, where they would silently do nothing.
void read_probe_type(JsonObject& pr, sim::SimProbeConfig& probe) {
  const bool analog = pr.text("type", "trigger", {"trigger", "analog"}) == "analog";
  probe.type = analog ? sim::ProbeType::Analog : sim::ProbeType::Trigger;
  for (const char* key : {"range", "noise", "spring_rate", "seed"})
    if (!analog && pr.has(key)) pr.fail(key, "left out: it is a setting of an analog probe (\"type\": \"analog\") and this probe is a trigger probe");
  auto& a = probe.analog;
  a.range = pr.number("range", a.range, 0.01, 10);
  a.noise = pr.number("noise", a.noise, 0, 0.1);
  if (a.noise * 10 > a.range) {
    std::ostringstream os;
    os << "at most a tenth of the range (" << a.range << " mm)";
    pr.fail("noise", os.str());
  }
  a.spring_rate = pr.number("spring_rate", a.spring_rate, 0.01, 100);
  a.seed = static_cast<std::uint64_t>(pr.whole("seed", static_cast<long long>(a.seed), 0, 2147483647));
}

void read_sim_section(JsonObject& s, DaemonConfig& cfg) {
  auto& m = cfg.sim.mechanics;
  m.start = s.axis_values("start", m.start, cfg.core.layout, 1e5);
  cfg.sim.card.absolute_scales = s.boolean("absolute_scales", cfg.sim.card.absolute_scales);
  cfg.sim.card.firmware = s.text("firmware", cfg.sim.card.firmware);
  cfg.sim.card.follow_watchdog = s.number("watchdog_ms", cfg.sim.card.follow_watchdog * 1e3, 1, 1000) / 1e3;
  cfg.sim_loop_time = s.text("time", "real", {"real", "loop"}) == "loop";
  cfg.sim_speed = static_cast<int>(s.whole("speed", cfg.sim_speed, 1, 20));
  if (auto pr = s.object("probe")) {
    m.probe.ball_radius = pr->number("ball_radius", m.probe.ball_radius, 0, 50);
    m.probe.pretravel = pr->number("pretravel", m.probe.pretravel, 0, 5);
    m.probe.overtravel = pr->number("overtravel", m.probe.overtravel, 0.1, 50);
    if (pr->has("normally_closed")) cfg.sim_probe_nc_set = true;
    m.probe.normally_closed = pr->boolean("normally_closed", m.probe.normally_closed);
    read_probe_type(*pr, m.probe);
    pr->finish();
  }
  if (auto scene = s.objects("scene")) {
    std::vector<sim::Solid> solids;
    for (auto& o : *scene) solids.push_back(read_solid(o));
    cfg.sim.scene = sim::Scene(std::move(solids));
  }
  s.finish();
}

}  // namespace

void load_config_text(const std::string& text, const std::string& path, DaemonConfig& cfg) {
  const nlohmann::json j = parse_json_text(text, path);
  JsonObject top(j, path, "");
  top.text("_comment", "");  // free text for people
  // "mqtt" is messmqtt's, the bridge beside messd that reads this same file and checks every key
  // of it (docs/mqtt.md); messd only makes sure it is an object.
  if (top.has("mqtt") && !top.is_object("mqtt")) top.fail("mqtt", "an object { ... } of messmqtt's keys (docs/mqtt.md)");
  top.accept("mqtt");
  if (auto s = top.object("server")) read_server_section(*s, path, cfg);
  if (auto c = top.object("control")) read_control(*c, path, cfg.server.control);
  if (auto m = top.object("motion")) read_motion_section(*m, cfg);
  if (auto axes = top.object("axes")) read_axes_section(*axes, cfg);
  if (auto b = top.object("backend")) read_backend_section(*b, cfg);
  if (auto jn = top.object("journal")) read_journal_section(*jn, cfg);
  if (auto f = top.object("frames")) {  // the part frames' store
    cfg.server.frames_file = f->text("file", cfg.server.frames_file);
    f->finish();
  }
  if (auto o = top.object("outputs")) read_outputs_section(*o, cfg);
  if (auto p = top.object("programs")) read_programs_section(*p, path, cfg);
  if (auto i = top.object("ippdme")) read_ippdme_section(*i, cfg);
  if (auto s = top.object("sim")) read_sim_section(*s, cfg);
  top.finish();
  const auto* type = find_backend(cfg.backend);
  if (type && !type->any_axes && !cfg.core.layout.is_xyz())
    throw ConfigError(path + ": backend '" + cfg.backend + "' drives the three linear axes X Y Z; axes.letters \"" +
                      cfg.core.layout.names() + "\" needs a drive-kit backend (portio-drive, sim-portio-drive)");
  if (cfg.sim_loop_time && cfg.backend != "sim-servo-card")
    throw ConfigError(path + ": sim.time \"loop\" is for the sim-servo-card backend, whose simulated card runs in the "
                             "motion loop; backend '" + cfg.backend + "' keeps \"real\"");
  if (cfg.sim_speed != 1 && !cfg.sim_loop_time)
    throw ConfigError(path + ": sim.speed " + std::to_string(cfg.sim_speed) +
                      " needs sim.time \"loop\": only a machine on loop time can run faster than the wall clock");
  cfg.notes.push_back("configuration read from " + path);
}

std::vector<std::string> load_messdrc(const std::string& path, DaemonConfig& cfg) {
  return load_messdrc_text(read_config_file(path, "messdrc file", "--rc"), path, cfg);
}

std::vector<std::string> load_messdrc_text(const std::string& text, const std::string& path, DaemonConfig& cfg) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw ConfigError(path + ": is empty; a messdrc holds lines such as 'TipRadius 2.0' (SpeedLevel, TipReversed, TipRadius)");
  std::vector<std::string> warnings;
  std::map<std::string, int> seen;  // setting -> line it was given on
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string key, value, extra;
    if (!(words >> key)) continue;
    words >> value >> extra;
    std::string at = path + ":" + std::to_string(n) + ": ";
    auto number = [&](std::string_view name) {
      return messdrc_number(*net::find_param(name), value, !extra.empty(), at);
    };
    const bool offset = key == "ProbeOffX" || key == "ProbeOffY" || key == "ProbeOffZ";
    const bool known = key == "SpeedLevel" || key == "TipRadius" || key == "TipReversed" || offset;
    if (known) {
      if (auto [it, fresh] = seen.emplace(key, n); !fresh)
        throw ConfigError(at + key + " is set again (first on line " + std::to_string(it->second) +
                          "); give each setting once");
    }
    if (key == "SpeedLevel") {
      cfg.core.params.speed_level = number("SpeedLevel");
      cfg.notes.push_back("messdrc: SpeedLevel " + value);
    } else if (key == "TipRadius") {
      cfg.core.params.tip_radius = number("TipRadius");
      cfg.notes.push_back("messdrc: TipRadius " + value);
    } else if (offset) {  // a qualification's probe offset (messcap qualify --rc writes them)
      const auto* spec = net::find_param(key);
      *config_place(*spec, cfg) = number(key);
      cfg.notes.push_back("messdrc: " + key + " " + value);
    } else if (key == "TipReversed") {
      if ((value != "true" && value != "false") || !extra.empty())
        throw ConfigError(at + "TipReversed takes true or false, got '" + value + "'");
      cfg.card.tip_reversed = value == "true";
      cfg.notes.push_back("messdrc: TipReversed " + value);
    } else {
      std::string shown = key.substr(0, 40);
      for (char& c : shown)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
      warnings.push_back(at + "unknown setting '" + shown + "' ignored (known: SpeedLevel, TipReversed, TipRadius, ProbeOffX, ProbeOffY, ProbeOffZ)");
    }
  }
  if (!seen.count("TipRadius")) {  // the 1996 manual: a messdrc without TipRadius means no compensation
    cfg.core.params.tip_radius = 0.0;
    cfg.notes.push_back("messdrc: no TipRadius line, so TipRadius 0.000 (no radius compensation)");
  }
  return warnings;
}

std::string default_state_file(const std::string& name, const std::string& fallback) {
  if (const char* state = std::getenv("STATE_DIRECTORY"); state && *state) {
    std::string first(state);
    return first.substr(0, first.find(':')) + "/" + name;  // systemd lists several as a:b
  }
  return fallback;
}

std::string default_journal_dir() { return default_state_file("journal", "messd-journal"); }

void finish_config(DaemonConfig& cfg) {
  const auto& layout = cfg.core.layout;
  cfg.core.homing.order = core::default_home_order(layout);
  cfg.sim.mechanics.layout = layout;
  for (int a = 0; a < layout.count; ++a) {
    auto& m = cfg.sim.mechanics.axes[a];
    const auto& c = cfg.core.axes[a];
    m.travel_min = c.travel_min;
    m.travel_max = c.travel_max;
    m.home_direction = c.home_direction;
  }
  if (!cfg.sim_probe_nc_set) cfg.sim.mechanics.probe.normally_closed = cfg.card.tip_reversed;
  const auto* type = find_backend(cfg.backend);
  cfg.core.referenced_at_start = type && type->absolute_scales && cfg.sim.card.absolute_scales;
  if (!cfg.outputs_given && type && type->probe_power_output) {  // the card's probe output
    cfg.core.outputs[0] = core::default_probe_output();
    cfg.core.output_count = 1;
  }
  finish_backend_config(cfg);
  cfg.core = core::resolved_limits(std::move(cfg.core));
  for (int a = 0; a < layout.count; ++a) cfg.card.max_velocity[a] = cfg.core.axes[a].max_velocity;
  for (int a = 0; a < layout.count; ++a) cfg.card.max_accel[a] = 20000;  // the drives' limit; MaxAccel shapes moves
  cfg.server.period_us = cfg.period_us;  // the read-only parameters Period and Backend
  cfg.core.period_s = cfg.period_us * 1e-6;  // the time step of queued segments
  cfg.server.backend = cfg.backend;
}

}  // namespace imess::app
