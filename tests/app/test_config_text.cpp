// Configuration text -> DaemonConfig without starting anything: ranges, overflow, duplicate
// keys at any depth, travel checks, messdrc; every error names file and key.
#include <catch2/catch.hpp>

#include <string>

#include "config.hpp"
#include "json_object.hpp"

using namespace imess::app;

namespace {
// The ConfigError message for `text`, or "" when it loads.
std::string json_error(const std::string& text) {
  DaemonConfig cfg;
  try {
    load_config_text(text, "t.json", cfg);
    finish_config(cfg);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}
std::string rc_error(const std::string& text) {
  DaemonConfig cfg;
  try {
    load_messdrc_text(text, "rc", cfg);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

TEST_CASE("numbers too large for a double are refused with the key and its range") {
  CHECK(json_error(R"({"motion":{"max_speed":1e400}})") ==
        "t.json: key 'motion.max_speed' must be a number from 0.1 to 1000, got \"1e400\"");
  CHECK(contains(json_error(R"({"motion":{"tip_radius":-1e999}})"), "key 'motion.tip_radius' must be a number from 0 to 50"));
  CHECK(contains(json_error(R"({"sim":{"scene":[{"type":"sphere","diameter":2e308}]}})"),
                 "key 'sim.scene[0].diameter' must be a number from 0.01 to 10000"));
  CHECK(contains(json_error(R"({"sim":{"start":[0, 1e400, 0]}})"), "key 'sim.start' must be an array of three numbers"));
  CHECK(contains(json_error(R"({"server":{"port":1e400}})"), "key 'server.port' must be a whole number from 0 to 65535"));
  CHECK(contains(json_error(R"({"server":{"max_clients":2.5}})"), "must be a whole number from 1 to 10000"));
}

TEST_CASE("a number too small to represent is zero where zero is allowed") {
  DaemonConfig cfg;
  load_config_text(R"({"motion":{"tip_radius":1e-400}})", "t.json", cfg);
  CHECK(cfg.core.params.tip_radius == 0.0);
}

TEST_CASE("duplicate keys are refused at any depth, naming the key") {
  CHECK(json_error(R"({"motion":{}, "motion":{}})") == "t.json: key 'motion' appears twice in the same object; give each key once");
  CHECK(contains(json_error(R"({"axes":{"Z":{"travel_max":600, "travel_max":500}}})"), "key 'axes.Z.travel_max' appears twice"));
  CHECK(contains(json_error(R"({"sim":{"scene":[{"type":"plane"},{"type":"box","size":[1,1,1],"size":[2,2,2]}]}})"),
                 "key 'sim.scene[1].size' appears twice"));
  CHECK(json_error(R"({"a":{"x":1},"b":{"x":1}})").find("appears twice") == std::string::npos);  // same name, other objects
}

TEST_CASE("empty text, bad JSON and absurd nesting are refused") {
  CHECK(contains(json_error(""), "t.json: is empty"));
  CHECK(contains(json_error(" \n\t"), "t.json: is empty"));
  CHECK(contains(json_error("{"), "t.json: not valid JSON"));
  CHECK(contains(json_error("[]"), "'the top level' must be a JSON object"));
  CHECK(contains(json_error("{\"_comment\":" + std::string(100, '[') + std::string(100, ']') + "}"), "deeper than 32 levels"));
}

TEST_CASE("home_position lies within the travel") {
  CHECK(contains(json_error(R"({"axes":{"X":{"home_position":5000}}})"),
                 "key 'axes.X.home_position' must be a coordinate within the travel, from travel_min 0 to travel_max 1000, got 5000"));
  CHECK(contains(json_error(R"({"axes":{"Y":{"travel_min":-10,"travel_max":10,"home_position":-10.5}}})"), "axes.Y.home_position"));
  CHECK(json_error(R"({"axes":{"Y":{"travel_min":-10,"travel_max":10,"home_position":10}}})").empty());
  CHECK(json_error(R"({"axes":{"Z":{"travel_min":-10,"travel_max":10}}})").empty());  // default: the travel end
}

TEST_CASE("addresses and port numbers are checked where they are read") {
  CHECK(contains(json_error(R"({"server":{"listen":"localhost:80"}})"), "key 'server.listen' must be an IPv4 or IPv6 address"));
  CHECK(json_error(R"({"server":{"listen":"::1","port":1066.0}})").empty());
  CHECK(contains(json_error(R"({"backend":{"type":"sim-parport","parport_base":"0x1FFFF"}})"), "a port address from 0 to 0xFFFF"));
  CHECK(contains(json_error(R"({"backend":{"type":"sim-parport","parport_base":"-1"}})"), "a port address from 0 to 0xFFFF"));
  CHECK(contains(json_error(R"({"backend":{"type":"sim-parport","parport_base":true}})"), "a port address from 0 to 0xFFFF"));
  CHECK(json_error(R"({"backend":{"type":"sim-parport","parport_base":"0x378"}})").empty());
}

TEST_CASE("drive-kit outputs: the port map's, or the backend's \"outputs\" table in their order") {
  auto drive = [](const std::string& backend) {
    DaemonConfig cfg;
    load_config_text(R"({"backend":{"type":"sim-portio-drive")" + backend + "}}", "t.json", cfg);
    finish_config(cfg);
    return cfg.ports.drive;
  };
  auto b = drive("");
  REQUIRE(b.output_count == 8);  // map B: 0x302 bits 0..7
  CHECK(b.outputs[0].port == 0x302);
  CHECK(b.outputs[0].mask == 0x0001);
  CHECK(b.outputs[7].mask == 0x0080);
  auto a = drive(R"(,"port_map":"mrm-a")");
  REQUIRE(a.output_count == 7);  // map A: outputs port 0x30C bits 9..15
  CHECK(a.outputs[0].port == 0x30C);
  CHECK(a.outputs[0].mask == 0x0200);
  CHECK(a.outputs[6].mask == 0x8000);
  auto t = drive(R"(,"outputs":[{"port":"0x302","bit":3},{"port":769,"bit":15},{"port":"0x303","bit":8}])");
  REQUIRE(t.output_count == 3);
  CHECK(t.outputs[0].port == 0x302);
  CHECK(t.outputs[0].mask == 0x0008);
  CHECK(t.outputs[1].port == 0x301);
  CHECK(t.outputs[1].mask == 0x8000);
  CHECK(t.outputs[2].port == 0x303);
  CHECK(t.outputs[2].mask == 0x0100);
  CHECK(drive(R"(,"outputs":[])").output_count == 0);
  CHECK(contains(json_error(R"({"backend":{"type":"sim-portio-drive","outputs":[{"port":"0x302","bit":0,"pin":3}]}})"),
                 "unknown key 'backend.outputs[0].pin'"));
}

TEST_CASE("messdrc text: values, underflow, repeats, empty files and bad values") {
  DaemonConfig cfg;
  auto warnings = load_messdrc_text("# stylus\nTipRadius 1e-400\nSpeedLevel 0.5\nColour red\n", "rc", cfg);
  CHECK(cfg.core.params.tip_radius == 0.0);
  CHECK(cfg.core.params.speed_level == 0.5);
  REQUIRE(warnings.size() == 1);
  CHECK(contains(warnings[0], "rc:4: unknown setting 'Colour' ignored"));
  CHECK(rc_error("TipRadius 1e400\n") == "rc:1: TipRadius takes one number from 0 to 50, got '1e400'");
  CHECK(rc_error("SpeedLevel 1\n\nSpeedLevel 1\n") == "rc:3: SpeedLevel is set again (first on line 1); give each setting once");
  CHECK(contains(rc_error(""), "rc: is empty"));
  CHECK(contains(rc_error("TipReversed yes\n"), "rc:1: TipReversed takes true or false"));
}

TEST_CASE("messdrc text: no TipRadius line means radius 0.0, as the 1996 manual says") {
  DaemonConfig cfg;
  REQUIRE(cfg.core.params.tip_radius > 0);  // the built-in simulated machine's 2 mm ball
  load_messdrc_text("SpeedLevel 0.5\n", "rc", cfg);
  CHECK(cfg.core.params.tip_radius == 0.0);
  CHECK(contains(cfg.notes.back(), "no TipRadius line, so TipRadius 0.000"));
  DaemonConfig with;
  load_messdrc_text("TipRadius 1.5\n", "rc", with);
  CHECK(with.core.params.tip_radius == 1.5);
}

TEST_CASE("config: frames.file names the part frames' store, unknown keys in frames are refused") {
  DaemonConfig cfg;
  load_config_text(R"({"frames": {"file": "/var/lib/messd/frames.json"}})", "c.json", cfg);
  CHECK(cfg.server.frames_file == "/var/lib/messd/frames.json");
  CHECK(contains(json_error(R"({"frames": {"path": "x"}})"), "unknown key 'frames.path'"));
}

// Issue 26, 8: connections from a control host that never command are dropped after this.
TEST_CASE("control.no_command_drop_s: 0 turns it off, a negative value is refused with its range") {
  DaemonConfig cfg;
  CHECK(cfg.server.control.no_command_drop_s == 300);
  load_config_text(R"({"control":{"no_command_drop_s": 0}})", "t.json", cfg);
  CHECK(cfg.server.control.no_command_drop_s == 0);
  CHECK(contains(json_error(R"({"control":{"no_command_drop_s": -1}})"), "key 'control.no_command_drop_s'"));
  CHECK(contains(json_error(R"({"control":{"no_command_drop_s": -1}})"), "from 0 to 86400"));
}

TEST_CASE("config: programs.g30 is G30's pose, programs.gcode.block_delete the block-delete switch (on by default)") {
  DaemonConfig cfg;
  load_config_text(R"({"programs": {"home": [1, 2, 3], "g30": [10, 20, 30]}})", "c.json", cfg);
  finish_config(cfg);
  CHECK(cfg.server.programs.home == std::vector<double>{1, 2, 3});
  CHECK(cfg.server.programs.g30 == std::vector<double>{10, 20, 30});
  CHECK(cfg.server.programs.block_delete);
  DaemonConfig off;
  load_config_text(R"({"programs": {"gcode": {"block_delete": false}}})", "c.json", off);
  CHECK_FALSE(off.server.programs.block_delete);
  CHECK(contains(json_error(R"({"programs": {"gcode": {"block_delete": "off"}}})"), "programs.gcode.block_delete"));
}

TEST_CASE("config: programs.gcode mist and flood name outputs, tool_change_pause is on by default") {
  DaemonConfig cfg;
  load_config_text(R"({"programs": {"gcode": {"tool_change_pause": false}}})", "c.json", cfg);
  CHECK_FALSE(cfg.server.programs.tool_change_pause);
  CHECK(DaemonConfig{}.server.programs.tool_change_pause);
  CHECK(contains(json_error(R"({"programs": {"gcode": {"mist": "nozzle"}}})"), "programs.gcode.mist"));
}

TEST_CASE("sim.probe.type: a trigger probe by default, an analog probe with its range, noise, spring rate and seed") {
  DaemonConfig plain;
  load_config_text(R"({"sim":{"probe":{"ball_radius":2}}})", "t.json", plain);
  CHECK(plain.sim.mechanics.probe.type == imess::sim::ProbeType::Trigger);
  DaemonConfig cfg;
  load_config_text(R"({"sim":{"probe":{"type":"analog","range":0.8,"noise":0.0005,"spring_rate":0.3,"seed":42}}})",
                   "t.json", cfg);
  const auto& p = cfg.sim.mechanics.probe;
  CHECK(p.type == imess::sim::ProbeType::Analog);
  CHECK(p.analog.range == 0.8);
  CHECK(p.analog.noise == 0.0005);
  CHECK(p.analog.spring_rate == 0.3);
  CHECK(p.analog.seed == 42);
  CHECK(json_error(R"({"sim":{"probe":{"type":"analog","seed":-1}}})") ==
        "t.json: key 'sim.probe.seed' must be a whole number from 0 to 2147483647, got -1");
  CHECK(json_error(R"({"sim":{"probe":{"noise":0.001}}})") ==
        "t.json: key 'sim.probe.noise' must be left out: it is a setting of an analog probe (\"type\": \"analog\") and "
        "this probe is a trigger probe, got 0.001");
}
