// Bad configurations: each is refused with ONE message (one line, naming the file) that says
// what was wrong and what is accepted — loaded from a file as messd loads it, and through the
// messd binary (exit status 2, that line on stderr, no abort).
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "backend_registry.hpp"
#include "config.hpp"
#include "core_rig.hpp"
#include "daemon_process.hpp"
#include "json_object.hpp"
#include "machine.hpp"

using namespace imess;
namespace fs = std::filesystem;

namespace {

struct BadConfig {
  const char* what;
  const char* text;                    // written to the file; nullptr: the case makes its own path
  std::vector<std::string> must_say;   // parts the one message must contain, besides the file name
};

std::string all_backend_names() {
  std::string s;
  for (const auto& n : app::backend_types()) s += (s.empty() ? "" : ", ") + ("\"" + n + "\"");
  return s;
}

const std::vector<BadConfig>& bad_configs() {
  static const std::vector<BadConfig> kCases{
      {"unknown backend", R"({"backend": {"type": "servo-kard"}})",
       {"key 'backend.type'", "\"servo-kard\"", "one of " + all_backend_names()}},
      {"unknown top-level section", R"({"motoin": {"tip_radius": 2}})",
       {"unknown key 'motoin'", "accepted here: ", "motion", "axes", "backend", "server", "sim", "journal", "control"}},
      {"unknown key in a section", R"({"motion": {"max_sped": 40}})",
       {"unknown key 'motion.max_sped'", "accepted here: ", "max_speed", "tip_radius", "period_us"}},
      {"unknown axis", R"({"axes": {"W": {"travel_max": 10}}})", {"unknown key 'axes.W'", "accepted here: X, Y, Z"}},
      {"axis letter not one of XYZABCUVW", R"({"axes": {"letters": "XYQ"}})",
       {"axes.letters", "'Q' is not an axis letter", "X Y Z A B C U V W"}},
      {"axis letter twice", R"({"axes": {"letters": "XYX"}})", {"axes.letters", "axis X is named twice"}},
      {"too many axes", R"({"axes": {"letters": "XYZABCUVWX"}})", {"axes.letters", "1 to 9 axis letters"}},
      {"an axis not in letters", R"({"axes": {"letters": "XYC", "Z": {"travel_max": 10}}})",
       {"unknown key 'axes.Z'", "accepted here: C, X, Y, letters"}},
      {"axis kind", R"({"axes": {"letters": "XYC", "C": {"kind": "angular"}}})", {"axes.C.kind", "linear", "rotary"}},
      {"other axes on the servo card", R"({"axes": {"letters": "XYCUV"}})",
       {"sim-servo-card", "drives the three linear axes X Y Z", "XYCUV", "drive-kit backend"}},
      {"other axes on the parallel port", R"({"axes": {"letters": "XYZA"}, "backend": {"type": "sim-parport"}})",
       {"sim-parport", "drives the three linear axes X Y Z"}},
      {"loop time on a backend with a base thread", R"({"backend": {"type": "sim-parport"}, "sim": {"time": "loop"}})",
       {"sim.time \"loop\" is for the sim-servo-card backend", "'sim-parport' keeps \"real\""}},
      {"an unknown sim time", R"({"sim": {"time": "virtual"}})", {"key 'sim.time'", "\"virtual\"", "real", "loop"}},
      {"a faster clock on the wall clock", R"({"sim": {"speed": 4}})",
       {"sim.speed 4 needs sim.time \"loop\"", "only a machine on loop time can run faster"}},
      {"a speed that is no whole number", R"({"sim": {"time": "loop", "speed": 2.5}})",
       {"key 'sim.speed'", "a whole number from 1 to 20"}},
      {"a speed beyond 20", R"({"sim": {"time": "loop", "speed": 50}})", {"key 'sim.speed'", "a whole number from 1 to 20"}},
      {"an output name that is no word", R"({"outputs": {"on": {"number": 1}}})",
       {"key 'outputs.on'", "an output name of 1 to 15 letters, digits or '_' (not on/off)"}},
      {"two names for one output", R"({"outputs": {"a": {"number": 1}, "b": {"number": 1}}})",
       {"key 'outputs.b.number'", "a number no other output has (1 is 'a')"}},
      {"two outputs power the probe", R"({"outputs": {"p1": {"number": 1, "probe_power": true}, "p2": {"number": 2, "probe_power": true}}})",
       {"key 'outputs.p2.probe_power'", "'p1' does"}},
      {"an output number out of range", R"({"outputs": {"pen": {"number": 0}}})", {"key 'outputs.pen.number'", "1", "32"}},
      {"an output without its number", R"({"outputs": {"pen": {"settle_ms": 10}}})",
       {"key 'outputs.pen.number'", "the backend's output number", "docs/hardware.md"}},
      {"an unknown output key", R"({"outputs": {"pen": {"number": 1, "colour": "red"}}})",
       {"unknown key 'outputs.pen.colour'", "number", "settle_ms", "probe_power", "at_start"}},
      {"sim.start of the wrong length", R"({"axes": {"letters": "XYC"}, "backend": {"type": "sim-portio-drive"}, "sim": {"start": [1, 2, 3, 4]}})",
       {"sim.start", "an array of 3 numbers [X, Y, C]"}},
      {"unknown card link", R"({"backend": {"type": "sim-servo-card", "link": "wireless"}})",
       {"key 'backend.link'", "\"wireless\"", "request-reply", "serial"}},
      {"line too slow", R"({"backend": {"type": "sim-servo-card", "link": "serial", "baud": 300}})",
       {"key 'backend.baud'", "9600"}},
      {"a baud rate no tty can be set to", R"({"backend": {"type": "servo-card", "device": "/dev/ttyUSB0", "baud": 12345}})",
       {"key 'backend.baud'", "a rate a serial line can be set to", "115200", "12345"}},
      {"the simulated card's link on the real one", R"({"backend": {"type": "servo-card", "device": "/dev/ttyUSB0", "link": "serial"}})",
       {"unknown key 'backend.link'", "device", "baud"}},
      {"key of another backend type", R"({"backend": {"type": "sim-parport", "port_map": "mrm-a"}})",
       {"unknown key 'backend.port_map'", "accepted here: ", "pins", "parport_base", "type"}},
      {"drive-kit output on an amplifier enable",
       R"({"backend": {"type": "sim-portio-drive", "outputs": [{"port": "0x302", "bit": 0}, {"port": "0x303", "bit": 1}]}})",
       {"key 'backend.outputs'", "output 2 (port 0x303 bit 1)", "axis Y's amplifier enable", "give a free output bit"}},
      {"drive-kit output outside the port space", R"({"backend": {"type": "sim-portio-drive", "outputs": [{"port": "0x400", "bit": 0}]}})",
       {"key 'backend.outputs[0].port'", "a port address from 0x300 to 0x363", "got \"0x400\""}},
      {"drive-kit output bit beyond 15", R"({"backend": {"type": "sim-portio-drive", "outputs": [{"port": "0x302", "bit": 16}]}})",
       {"key 'backend.outputs[0].bit'", "a whole number from 0 to 15", "got 16"}},
      {"drive-kit output without its bit", R"({"backend": {"type": "sim-portio-drive", "outputs": [{"port": "0x302"}]}})",
       {"key 'backend.outputs[0].bit'", "a bit number from 0 to 15", "got nothing"}},
      {"drive-kit output on an inputs port", R"({"backend": {"type": "sim-portio-drive", "outputs": [{"port": 772, "bit": 0}]}})",
       {"key 'backend.outputs'", "output 1 (port 0x304 bit 0)", "inputs port"}},
      {"unknown pin", R"({"backend": {"type": "sim-parport", "pins": {"map": "shd-adapter", "18": "probe"}}})",
       {"unknown key 'backend.pins.18'", "\"map\" and the pin numbers \"1\" to \"17\""}},
      {"whole number out of range", R"({"server": {"port": 70000}})",
       {"key 'server.port'", "a whole number from 0 to 65535", "got 70000"}},
      {"unknown probe type", R"({"sim": {"probe": {"type": "laser"}}})",
       {"key 'sim.probe.type'", "\"trigger\"", "\"analog\"", "laser"}},
      {"analog setting on a trigger probe", R"({"sim": {"probe": {"range": 0.5}}})",
       {"key 'sim.probe.range'", "left out", "analog probe", "got 0.5"}},
      {"analog probe range out of range", R"({"sim": {"probe": {"type": "analog", "range": 20}}})",
       {"key 'sim.probe.range'", "a number from 0.01 to 10", "got 20"}},
      {"analog probe noise above a tenth of its range", R"({"sim": {"probe": {"type": "analog", "range": 0.5, "noise": 0.08}}})",
       {"key 'sim.probe.noise'", "at most a tenth of the range (0.5 mm)", "got 0.08"}},
      {"number out of range", R"({"motion": {"tip_radius": 51}})", {"key 'motion.tip_radius'", "a number from 0 to 50", "got 51"}},
      {"period out of range", R"({"motion": {"period_us": 1}})", {"key 'motion.period_us'", "from 100 to 100000", "got 1"}},
      {"travel inverted", R"({"axes": {"X": {"travel_min": 5, "travel_max": 5}}})",
       {"key 'axes.X.travel_max'", "greater than travel_min", "got 5"}},
      {"number given as text", R"({"motion": {"tip_radius": "2.0"}})",
       {"key 'motion.tip_radius'", "a number from 0 to 50", "got \"2.0\""}},
      {"boolean given as text", R"({"motion": {"realtime": "yes"}})", {"key 'motion.realtime'", "true or false", "got \"yes\""}},
      {"section given as array", R"({"motion": [1, 2]})", {"key 'motion'", "an object { ... }", "got [1,2]"}},
      {"pins given as number", R"({"backend": {"type": "sim-parport", "pins": 5}})",
       {"key 'backend.pins'", "\"shd-adapter\", \"3d-step\" or an object", "got 5"}},
      {"scene given as object", R"({"sim": {"scene": {"type": "plane"}}})", {"key 'sim.scene'", "an array of objects", "got {"}},
      {"missing required key", R"({"sim": {"scene": [{"center": [0, 0, 0]}]}})",
       {"key 'sim.scene[0].type'", "one of \"plane\", \"box\", \"sphere\", \"cylinder\"", "got nothing"}},
      {"top level not an object", R"(["motion"])", {"'the top level' must be a JSON object"}},
      {"malformed JSON: trailing comma", "{\n  \"motion\": {\n    \"tip_radius\": 2.0,\n  }\n}",
       {"not valid JSON at line 4, column 3", "expected string literal"}},
      {"malformed JSON: unclosed object", "{\"motion\": {}", {"not valid JSON at line 1, column 14", "expected '}'"}},
      {"duplicate key", R"({"motion": {"tip_radius": 1, "tip_radius": 2}})", {"key 'motion.tip_radius' appears twice", "give each key once"}},
      {"number beyond a double", R"({"motion": {"max_speed": 1e400}})", {"key 'motion.max_speed'", "a number from 0.1 to 1000"}},
      {"empty file", "  \n", {"is empty", "a configuration is a JSON object"}},
      {"missing file", nullptr, {"cannot open the configuration file", "--config takes the path of a readable configuration file"}},
      {"a directory", nullptr, {"is a directory, not a configuration file", "--config takes the path"}},
      {"not a regular file", nullptr, {"is not a regular file", "--config takes the path of a readable configuration file"}},
      {"unreadable file", nullptr, {"cannot read the configuration file", "--config takes the path of a readable configuration file"}},
  };
  return kCases;
}

// A private directory for the case files, removed at the end of the run.
struct CaseDir {
  fs::path dir;
  CaseDir() {
    std::string d = (fs::temp_directory_path() / "imess-bad-configs-XXXXXX").string();
    if (!mkdtemp(d.data())) throw std::runtime_error("mkdtemp failed");
    dir = d;
  }
  ~CaseDir() {
    std::error_code ec;
    fs::permissions(dir / "unreadable.json", fs::perms::owner_all, ec);
    fs::remove_all(dir, ec);
  }
  // The file of case `i` (written, or made missing / a directory / unreadable); "" when the
  // case cannot be made here (an unreadable file for root).
  std::string make(std::size_t i, const BadConfig& c) {
    if (c.text) {
      auto p = dir / ("case" + std::to_string(i) + ".json");
      std::ofstream(p) << c.text;
      return p.string();
    }
    std::string what = c.what;
    if (what == "missing file") return (dir / "missing.json").string();
    if (what == "not a regular file") {
      auto p = dir / "fifo.json";
      if (mkfifo(p.c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
      return p.string();
    }
    if (what == "a directory") {
      fs::create_directories(dir / "conf.d");
      return (dir / "conf.d").string();
    }
    auto p = dir / "unreadable.json";
    std::ofstream(p) << "{}";
    fs::permissions(p, fs::perms::none);
    if (std::ifstream(p)) return "";  // root reads anything
    return p.string();
  }
};

// Loads `path` as messd does (load_json_config, finish_config, make_machine); the message of
// the one exception, or "" when it loads.
std::string load_error(const std::string& path) {
  app::DaemonConfig cfg;
  try {
    app::load_json_config(path, cfg);
    cfg.ports.port_io.file = "";  // a private port space, should it get that far
    app::finish_config(cfg);
    test::VirtualClock clock;
    (void)app::make_machine(cfg, clock, false);
  } catch (const app::ConfigError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("not a ConfigError: ") + e.what();
  }
  return "";
}

bool mentions(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    auto nl = text.find('\n', start);
    if (nl == std::string::npos) nl = text.size();
    if (nl > start) lines.push_back(text.substr(start, nl - start));
    start = nl + 1;
  }
  return lines;
}

}  // namespace

TEST_CASE("every bad configuration gives one message naming the file, what is wrong and what is accepted") {
  CaseDir files;
  for (std::size_t i = 0; i < bad_configs().size(); ++i) {
    const auto& c = bad_configs()[i];
    INFO(c.what);
    const std::string path = files.make(i, c);
    if (path.empty()) {
      WARN("skipped (running as root): " << c.what);
      continue;
    }
    const std::string msg = load_error(path);
    INFO(msg);
    REQUIRE_FALSE(msg.empty());
    CHECK(msg.rfind(path + ": ", 0) == 0);          // begins with the file
    CHECK(msg.find('\n') == std::string::npos);      // one line
    CHECK_FALSE(mentions(msg, "json.exception"));    // no library internals
    CHECK_FALSE(mentions(msg, "not a ConfigError"));
    for (const auto& part : c.must_say) {
      INFO("must say: " << part);
      CHECK(mentions(msg, part));
    }
  }
}

TEST_CASE("messd --config with a bad configuration exits 2 with that one message on stderr, no abort") {
  CaseDir files;
  for (std::size_t i = 0; i < bad_configs().size(); ++i) {
    const auto& c = bad_configs()[i];
    INFO(c.what);
    const std::string path = files.make(i, c);
    if (path.empty()) continue;  // root: see above
    const auto run = test::run_messd_to_exit({"--config", path, "--journal", (files.dir / "journal").string()});
    INFO("stderr: " << run.err);
    CHECK(run.status == 2);
    CHECK(run.out.empty());  // no "messd: OK, listening"
    const auto lines = lines_of(run.err);
    REQUIRE(lines.size() == 1);
    CHECK(mentions(lines[0], " error: " + load_error(path)));  // the same message as the library's
    for (const char* crash : {"terminate called", "what():", "Aborted", "stack", "unexpected error"})
      CHECK_FALSE(mentions(run.err, crash));
  }
  CHECK_FALSE(fs::exists(files.dir / "journal"));  // refused before anything was created
}

TEST_CASE("settings the backend cannot run are a bad configuration too: one message, exit 2") {
  CaseDir files;
  // 1e6 steps/mm at the default 25 mm/s: far beyond what the base period can step.
  const BadConfig c{"backend cannot run it", R"({"backend": {"type": "sim-parport", "axes": {"X": {"steps_per_mm": 1e6}}}})", {}};
  const std::string path = files.make(0, c);
  const std::string msg = load_error(path);
  INFO(msg);
  CHECK(msg.rfind("sim-parport: axis X: max_speed", 0) == 0);  // a ConfigError naming backend, axis and key
  CHECK(mentions(msg, "steps/s"));
  CHECK(msg.find('\n') == std::string::npos);

  const auto run = test::run_messd_to_exit({"--config", path, "--journal", (files.dir / "journal").string()});
  INFO("stderr: " << run.err);
  CHECK(run.status == 2);  // packaging/messd.service: no restart for a bad configuration
  CHECK(run.out.empty());
  std::size_t errors = 0;
  for (const auto& l : lines_of(run.err)) errors += mentions(l, " error: ") ? 1 : 0;
  CHECK(errors == 1);
  CHECK(mentions(run.err, "error: controller start failed: " + msg));
  CHECK_FALSE(mentions(run.err, "terminate called"));
}
