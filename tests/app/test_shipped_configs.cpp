// Every shipped configuration (config/*.json and every config/ file the README names) loads as
// messd loads it, builds its machine through the backend registry and says what the file says.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "shipped_config.hpp"
#include "backend_registry.hpp"
#include "config_rig.hpp"
#include "imess/sim/scene.hpp"
#include "imess/core/loop_runner.hpp"
#include "json_object.hpp"

using namespace imess;
using namespace imess::test;
namespace fs = std::filesystem;

namespace {

const std::string kRoot = IMESS_SOURCE_DIR;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// config/*.json, sorted.
std::vector<std::string> globbed_configs() {
  std::vector<std::string> files;
  for (const auto& f : fs::directory_iterator(kRoot + "/config"))
    if (f.path().extension() == ".json" && simulated_config(f.path())) files.push_back("config/" + f.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

// Every "config/<name>.json" the README mentions.
std::set<std::string> readme_configs() {
  const std::string text = slurp(kRoot + "/README.md");
  std::set<std::string> named;
  const std::regex path(R"(config/[A-Za-z0-9._-]+\.json)");
  for (std::sregex_iterator it(text.begin(), text.end(), path), end; it != end; ++it) named.insert(it->str());
  return named;
}

std::vector<std::string> shipped_configs() {
  auto files = globbed_configs();
  for (const auto& n : readme_configs())
    if (simulated_config(n) && std::find(files.begin(), files.end(), n) == files.end()) files.push_back(n);
  return files;
}

}  // namespace

TEST_CASE("the configurations the README names are shipped in config/") {
  const auto named = readme_configs();
  CHECK(named.size() >= 4);  // the README's "Other machines" and "Configuration" paragraphs
  for (const auto& n : named) {
    INFO(n);
    CHECK(fs::is_regular_file(kRoot + "/" + n));
  }
  CHECK(globbed_configs().size() >= 5);
}

TEST_CASE("every shipped configuration builds its machine, and it is the machine the file describes") {
  for (const auto& rel : shipped_configs()) {
    const std::string path = kRoot + "/" + rel;
    INFO(rel);
    // The file read on its own, to compare with what the loader made of it.
    const auto j = nlohmann::json::parse(slurp(path), nullptr, true, /*ignore_comments=*/true);
    std::unique_ptr<ConfigRig> rig;
    REQUIRE_NOTHROW(rig = std::make_unique<ConfigRig>(path));  // load_json_config, finish_config, make_machine
    const auto& cfg = rig->config();

    // The backend: the type the file names, registered, and a machine that says what it is.
    const std::string type = j.contains("backend") ? j["backend"].value("type", "sim-servo-card") : "sim-servo-card";
    CHECK(cfg.backend == type);
    REQUIRE(app::find_backend(type) != nullptr);
    CHECK_FALSE(rig->machine().describe().empty());

    // The axes: the file's axes are the machine's (axes.letters, X Y Z when absent), of the
    // kind given, with the travel and limits given.
    const auto& layout = cfg.core.layout;
    CHECK(rig->core().config().layout.names() == layout.names());
    if (j.contains("axes")) {
      const std::string letters = j["axes"].value("letters", "XYZ");
      CHECK(layout.names() == letters);
      CHECK(j["axes"].size() == static_cast<std::size_t>(layout.count) + (j["axes"].contains("letters") ? 1 : 0));
      for (int a = 0; a < layout.count; ++a) {
        const std::string name(1, layout.letters[a]);
        INFO("axis " << name);
        REQUIRE(j["axes"].contains(name));
        const auto& ja = j["axes"][name];
        const auto& ca = cfg.core.axes[a];
        const auto& live = rig->core().config().axes[a];
        CHECK(ca.travel_min == ja.value("travel_min", 0.0));
        CHECK(ca.travel_max == ja.value("travel_max", 1000.0));
        CHECK(live.travel_min == ca.travel_min);
        CHECK(live.travel_max == ca.travel_max);
        CHECK(ca.home_direction == (ja.value("home_direction", "neg") == std::string("neg") ? -1 : 1));
        const std::string kind = ja.value("kind", std::string(hal::default_kind(layout.letters[a]) == hal::AxisKind::Rotary ? "rotary" : "linear"));
        CHECK((layout.kinds[a] == hal::AxisKind::Rotary) == (kind == "rotary"));
        const double vmax = j.contains("motion") ? j["motion"].value("max_velocity", 150.0) : 150.0;
        CHECK(ca.max_velocity == ja.value("max_velocity", vmax));
        CHECK(live.max_velocity == ca.max_velocity);
        if (ja.contains("max_accel")) CHECK(ca.max_accel == ja["max_accel"].get<double>());
        CHECK(live.max_accel > 0);
      }
    }
    if (j.contains("motion") && j["motion"].contains("period_us")) CHECK(cfg.period_us == j["motion"]["period_us"].get<double>());
    if (j.contains("server") && j["server"].contains("port")) CHECK(cfg.server.port == j["server"]["port"].get<int>());

    // The machine runs: a quarter second of motion cycles without a fault, standing within its travel.
    for (int i = 0; i < 250; ++i) rig->step([](const core::Event&) {});
    const auto& snap = rig->core().snapshot();
    CHECK(snap.mode != core::Mode::Fault);
    CHECK(snap.hardware_errors == 0);
    for (int a = 0; a < layout.count; ++a) {
      CHECK(snap.position[a] >= cfg.core.axes[a].travel_min - 1e-6);
      CHECK(snap.position[a] <= cfg.core.axes[a].travel_max + 1e-6);
    }
  }
}

TEST_CASE("the shipped simulated tables are the built-in one: the worked example and the reference sphere on its stem") {
  const auto built_in = sim::default_scene();
  const auto sphere = sim::reference_sphere();
  // A point on the sphere 10 degrees above its equator, one at its pole, one on the stem, one
  // on the cube's top: the same distances everywhere, and zero on the reference sphere.
  const std::vector<sim::Vec3> probes = {
      sphere.center + sphere.diameter / 2 * sim::Vec3(std::cos(0.1745), 0, std::sin(0.1745)),
      sphere.center + sim::Vec3(0, 0, sphere.diameter / 2), sim::Vec3(755, 650, 20), sim::Vec3(460, 320, 80),
      sim::Vec3(750, 650, 90)};
  CHECK(built_in.distance(probes[0]) == Approx(0).margin(1e-9));
  CHECK(built_in.distance(probes[1]) == Approx(0).margin(1e-9));
  for (const auto& rel : globbed_configs()) {
    ConfigRig rig(kRoot + "/" + rel);
    const auto& scene = rig.config().sim.scene;
    if (rig.config().backend.rfind("sim-", 0) != 0 || scene.solids().empty()) continue;  // no simulated table
    INFO(rel);
    CHECK(scene.solids().size() == built_in.solids().size());
    for (const auto& p : probes) CHECK(scene.distance(p) == Approx(built_in.distance(p)).margin(1e-9));
    // Inside the travel, with room above it for the touches and the moves between them.
    const auto& z = rig.config().core.axes[2];
    CHECK(sphere.center.z() + sphere.diameter / 2 + 40 < z.travel_max);
  }
}

TEST_CASE("config/servo-card.json: the card on /dev/ttyIMESS0, streamed — without the device it refuses to start, saying so") {
  app::DaemonConfig cfg;
  app::load_json_config(kRoot + "/config/servo-card.json", cfg);
  app::finish_config(cfg);
  CHECK(cfg.backend == "servo-card");
  CHECK(cfg.card_line.device == "/dev/ttyIMESS0");
  CHECK(cfg.card_line.baud == 115200);
  CHECK(cfg.card.stream.baud == 115200);
  core::MonotonicClock clock;
  if (fs::exists("/dev/ttyIMESS0")) return;  // a machine with the card: nothing more to say here
  try {
    app::make_machine(cfg, clock, false);
    FAIL("the machine was built without its device");
  } catch (const app::ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("/dev/ttyIMESS0") && Catch::Contains("no such device"));
  }
}
