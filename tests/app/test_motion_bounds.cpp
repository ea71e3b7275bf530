// Property: whatever a client sends, every motion stays within the machine's configured
// limits — seeded random command sequences (every motion verb, the stop lane, every runtime
// parameter, extreme values) on every shipped configuration, run in virtual time.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "shipped_config.hpp"
#include "config_rig.hpp"
#include "imess/net/params.hpp"

using namespace imess;
using namespace imess::test;
using core::Mode;

namespace {

constexpr int kWindow = 10;  // cycles over which a speed is measured (10 ms): a stepper's step is 0.5 mm/s here
// A servo card streamed over a serial line reports positions in status frames every 5 ms,
// each arriving up to 2 ms after it was sampled (a frame with latched positions is longer on
// the line), so a position seen at a cycle may be one frame old. Speeds there are measured
// between the cycles at which two frames arrived, at least 40 ms apart, with those 2 ms of
// uncertainty at either end.
constexpr int kStreamedWindow = 40;
constexpr double kStreamedJitter = 0.002;  // s
constexpr int kFrameAge = 7;  // cycles: a frame period plus its delay
constexpr int kHistory = kStreamedWindow + kFrameAge + 1;  // cycles kept
// Measured speeds are encoder positions, so they include the servo's tracking overshoot
// (up to 3 % seen on the drive kits' PID) and quantisation; the commanded path is within 1.
constexpr double kSpeedTolerance = 1.04;

// Values a careless or hostile client sends: zero, the smallest and largest magnitudes the
// parser lets through, and ordinary ones.
double extreme_or_random(std::mt19937_64& rng, double lo, double hi) {
  static constexpr std::array kSpecial{0.0, 1e-300, -1e-300, 1e-8, -5e-8, 0.01, -0.01, 1.0, -1.0};
  if (std::uniform_int_distribution<int>(0, 3)(rng) == 0) {
    double v = kSpecial[std::uniform_int_distribution<std::size_t>(0, kSpecial.size() - 1)(rng)];
    return std::clamp(v, lo, hi);
  }
  if (std::uniform_int_distribution<int>(0, 5)(rng) == 0) return std::uniform_int_distribution<int>(0, 1)(rng) ? lo : hi;
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Watches one machine cycle by cycle and records the first violation.
class BoundsWatch {
 public:
  explicit BoundsWatch(const app::DaemonConfig& cfg)
      : cfg_(cfg), streamed_(cfg.backend == "sim-servo-card" && cfg.sim.streamed), window_(streamed_ ? kStreamedWindow : kWindow),
        jitter_(streamed_ ? kStreamedJitter : 0) {
    for (int a = 0; a < n(); ++a) {
      envelope_lo_[a] = cfg.core.axes[a].travel_min;
      envelope_hi_[a] = cfg.core.axes[a].travel_max;
    }
  }

  void observe(const core::Snapshot& s, Mode mode) {
    ++cycle_;
    mode_ = mode;
    const Sample& before = at(cycle_ - 1);
    const hal::AxisVec step = s.position - before.p;
    // A cycle measures a speed where a position arrived: every cycle on a machine read each
    // cycle, a changed position on a streamed card (an unchanged one may be a frame old).
    const bool arrived = !streamed_ || step != hal::AxisVec::Zero();
    history_[cycle_ % kHistory] = {s.position, loops_moving(mode), arrived ? cycle_ : before.arrival};
    if ((mode == Mode::Home || homing_) && redefined(step))  // homing gave an axis its coordinate: not motion
      for (auto& h : history_) h.motor = false;
    since_hands_ = loops_moving(mode) ? since_hands_ + 1 : 0;
    if (mode == Mode::Home && !homing_) {  // a homing begins: from where the axes stand, or the switches
      referenced_homing_ = s.referenced;
      for (int a = 0; a < n(); ++a) {
        const double margin = cfg_.sim.mechanics.axes[a].limit_margin + 1.0;
        homing_lo_[a] = std::min(cfg_.core.axes[a].travel_min - margin, s.position[a]);
        homing_hi_[a] = std::max(cfg_.core.axes[a].travel_max + margin, s.position[a]);
      }
    }
    const bool was_homing = homing_;
    if (mode == Mode::Home) homing_ = true;
    else if (mode != Mode::Stopping) homing_ = false;  // braking after a stopped homing counts as homing
    if (was_homing && !homing_)  // where homing left an axis (at most its creep past the index) counts as inside
      for (int a = 0; a < n(); ++a) {
        envelope_lo_[a] = std::min(envelope_lo_[a], s.position[a]);
        envelope_hi_[a] = std::max(envelope_hi_[a], s.position[a]);
      }
    check_speed();
    if (s.referenced) check_travel(s.position);
  }

  bool ok() const { return failure_.empty(); }
  int n() const { return cfg_.core.layout.count; }
  const std::string& failure() const { return failure_; }
  double top_speed_ratio() const { return top_ratio_; }

 private:
  struct Sample {
    hal::AxisVec p = hal::AxisVec::Zero();
    bool motor = false;  // the loops drive the machine (not pushed by hand, not coasting in a fault)
    long arrival = 0;    // the cycle at which this position arrived
  };
  const Sample& at(long cycle) const { return history_[static_cast<std::size_t>(cycle % kHistory)]; }
  static bool loops_moving(Mode m) { return m != Mode::Free && m != Mode::Fault; }
  double resolution(int a) const {
    return cfg_.backend == "sim-portio-drive" ? cfg_.ports.drive.axes[a].position_unit_mm : 0.0;
  }
  bool redefined(const hal::AxisVec& step) const {
    for (int a = 0; a < n(); ++a)
      if (std::abs(step[a]) > 3 * cfg_.core.axes[a].max_velocity * 1e-3) return true;
    return false;
  }

  void fail(const std::string& what) {
    if (failure_.empty()) failure_ = "cycle " + std::to_string(cycle_) + " mode " + std::to_string(int(mode_)) + ": " + what;
  }

  void check_speed() {
    const Sample& now = at(cycle_);
    if (now.arrival != cycle_ || cycle_ <= window_) return;
    const long start = at(cycle_ - window_).arrival;  // the position shown a window ago arrived here
    if (cycle_ - start > window_ + kFrameAge) return;  // held over several frames: the machine stood there
    for (long c = start; c <= cycle_; ++c)
      if (!at(c).motor) return;
    const Sample& then = at(start);
    const double dt = static_cast<double>(cycle_ - start) * 1e-3, tolerance = kSpeedTolerance + jitter_ / dt;
    hal::AxisVec v = (now.p - then.p) / dt;
    for (int a = 0; a < n(); ++a) {
      const double limit = cfg_.core.axes[a].max_velocity;
      top_ratio_ = std::max(top_ratio_, std::abs(v[a]) / limit);
      if (std::abs(v[a]) > limit * tolerance + 1.0 + resolution(a) / dt)
        fail(std::string("axis ") + cfg_.core.layout.letters[a] + " at " + std::to_string(std::abs(v[a])) + " mm/s, limit " +
             std::to_string(limit));
    }
    const double path_limit = cfg_.core.max_velocity;
    top_ratio_ = std::max(top_ratio_, v.norm() / path_limit);
    double quantum = 0;
    for (int a = 0; a < n(); ++a) quantum += resolution(a) / dt;
    if (v.norm() > path_limit * tolerance + 1.0 + quantum)
      fail("path speed " + std::to_string(v.norm()) + " mm/s (" + std::to_string(v[0]) + " " + std::to_string(v[1]) +
           " " + std::to_string(v[2]) + "), max_velocity " + std::to_string(path_limit));
  }

  // Once referenced the machine stays within the soft limits; homing alone may go beyond
  // them to its switches, by at most the switch margin plus the braking distance, and may
  // leave an axis there — from where it may only come back.
  void check_travel(const hal::AxisVec& p) {
    for (int a = 0; a < n(); ++a) {
      const auto& ax = cfg_.core.axes[a];
      if (homing_ && referenced_homing_) {
        const double settle = 0.05 + resolution(a);  // the loops catching the axis where it stood
        if (since_hands_ < 50) {  // a homing begun while a hand push still moved the carriage
          homing_lo_[a] = std::min(homing_lo_[a], p[a]);
          homing_hi_[a] = std::max(homing_hi_[a], p[a]);
        }
        if (p[a] < homing_lo_[a] - settle || p[a] > homing_hi_[a] + settle)
          fail(std::string("homing took axis ") + cfg_.core.layout.letters[a] + " to " + std::to_string(p[a]) +
               ", beyond its switches (allowed " + std::to_string(homing_lo_[a]) + " .. " +
               std::to_string(homing_hi_[a]) + ")");
        envelope_lo_[a] = std::min(envelope_lo_[a], p[a]);
        envelope_hi_[a] = std::max(envelope_hi_[a], p[a]);
        continue;
      }
      if (homing_) continue;  // coordinates are not machine coordinates until homed
      // Pushed by hand, or coasting in a fault (and the motor catching the carriage in the
      // first 50 ms after the loops close): from there the motors may only bring it back.
      if (since_hands_ < 50) {
        envelope_lo_[a] = std::min(envelope_lo_[a], p[a]);
        envelope_hi_[a] = std::max(envelope_hi_[a], p[a]);
        continue;
      }
      const double kOvershoot = 0.05 + resolution(a);  // servo overshoot at a soft limit, plus one count
      if (p[a] < envelope_lo_[a] - kOvershoot || p[a] > envelope_hi_[a] + kOvershoot)
        fail(std::string("axis ") + cfg_.core.layout.letters[a] + " at " + std::to_string(p[a]) + " outside [" +
             std::to_string(envelope_lo_[a]) + ", " + std::to_string(envelope_hi_[a]) + "]");
      envelope_lo_[a] = std::max(ax.travel_min, std::min(envelope_lo_[a], p[a]) );
      envelope_hi_[a] = std::min(ax.travel_max, std::max(envelope_hi_[a], p[a]));
      if (p[a] < ax.travel_min) envelope_lo_[a] = p[a];  // still out there: it may only come back
      if (p[a] > ax.travel_max) envelope_hi_[a] = p[a];
    }
  }

  const app::DaemonConfig& cfg_;
  bool streamed_;  // the servo card streamed: positions come in status frames
  int window_;
  double jitter_;
  std::array<Sample, kHistory> history_{};
  long cycle_ = 0;
  Mode mode_ = Mode::Free;
  long since_hands_ = 0;  // cycles since the loops last held the machine
  bool homing_ = false, referenced_homing_ = false;
  hal::AxisArray<double> envelope_lo_{}, envelope_hi_{}, homing_lo_{}, homing_hi_{};
  double top_ratio_ = 0;
  std::string failure_;
};

// A random command as the io thread would hand it to the loop (parser ranges respected).
void send_random(ConfigRig& rig, std::mt19937_64& rng, std::uint32_t seq) {
  auto& core = rig.core();
  const auto& cfg = rig.config();
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  auto travel = [&](int a) {
    const auto& ax = cfg.core.axes[a];
    const double span = ax.travel_max - ax.travel_min;
    if (pick(10) == 0) return pick(2) ? 1e9 : -1e9;
    return std::uniform_real_distribution<double>(ax.travel_min - 0.2 * span, ax.travel_max + 0.2 * span)(rng);
  };
  const int n = cfg.core.layout.count;
  core::Command c;
  c.client = 1;
  c.seq = seq;
  const int verb = pick(100);
  if (verb < 30) {
    c.kind = core::CommandKind::StartMv;
    for (int a = 0; a < n; ++a) c.v[a] = pick(3) == 0 ? 0.0 : extreme_or_random(rng, -100, 100);
  } else if (verb < 45) {
    core.request_stop();
    return;
  } else if (verb < 63) {
    c.kind = core::CommandKind::GoTo;
    for (int a = 0; a < n; ++a) c.v[a] = travel(a);
    c.speed = pick(3) == 0 ? 0.0 : extreme_or_random(rng, 1e-300, 1e9);
  } else if (verb < 76) {
    static const auto settable = [] {  // what a client can Set; read-only entries are not drawn
      std::vector<net::ParamSpec> out;
      for (const auto& p : net::param_table())
        if (!p.read_only) out.push_back(p);
      return out;
    }();
    const auto& p = settable[static_cast<std::size_t>(pick(static_cast<int>(settable.size())))];
    if (p.home == net::ParamHome::Core) core.set_param(p.core_id, extreme_or_random(rng, p.min, std::min(p.max, 1e6)));
    return;
  } else if (verb < 80) {
    c.kind = core::CommandKind::ForcePt;
  } else if (verb < 84) {
    c.kind = core::CommandKind::Free;
  } else if (verb < 88) {
    c.kind = core::CommandKind::Reset;
  } else if (verb < 99) {
    c.kind = core::CommandKind::HandMv;
    for (int a = 0; a < 3; ++a) c.v[a] = extreme_or_random(rng, -60, 60);  // X Y Z, by hand
    c.speed = pick(2) ? 0.0 : extreme_or_random(rng, 1e-300, 1e9);
  } else {
    c.kind = core::CommandKind::Home;
  }
  core.submit(c);
}

long commands_per_config() {
  if (const char* n = std::getenv("IMESS_BOUNDS_COMMANDS")) return std::max(1L, std::atol(n));
  return 100000;
}

// share: the fraction of the commands to send (a machine that differs from another covered one
// in no part of its motion).
void run_property(const std::string& name, std::uint64_t seed, double share = 1.0) {
  const std::string path = std::string(IMESS_SOURCE_DIR) + "/config/" + name;
  ConfigRig rig(path);
  BoundsWatch watch(rig.config());
  std::mt19937_64 rng(seed);
  long homed = 0, hits = 0, stops = 0, commands = 0;
  auto on_event = [&](const core::Event& e) {
    if (e.kind == core::EventKind::Homed) ++homed;
    if (e.kind == core::EventKind::MeasPt) ++hits;
  };
  auto cycle = [&] {
    rig.step(on_event);
    watch.observe(rig.core().snapshot(), rig.core().mode());
  };
  // Machines without absolute scales are homed first, so the soft limits hold afterwards.
  if (!rig.config().core.referenced_at_start) {
    core::Command home;
    home.kind = core::CommandKind::Home;
    rig.core().submit(home);
    for (int i = 0; i < 300000 && homed == 0; ++i) cycle();
    REQUIRE(homed == 1);
  }
  const long n = std::max(1L, static_cast<long>(static_cast<double>(commands_per_config()) * share));
  for (std::uint32_t seq = 1; seq <= n && watch.ok(); ++seq) {
    send_random(rig, rng, seq);
    ++commands;
    const int cycles = std::uniform_int_distribution<int>(0, 32)(rng) == 0
                           ? std::uniform_int_distribution<int>(100, 2500)(rng)
                           : std::uniform_int_distribution<int>(1, 30)(rng);
    for (int i = 0; i < cycles && watch.ok(); ++i) cycle();
    if (seq % 97 == 0) ++stops;
  }
  INFO(name << " seed " << seed << ": " << commands << " commands, " << hits << " points, " << homed << " homings");
  CHECK(watch.failure() == "");
  CHECK(watch.top_speed_ratio() > 0.5);  // the sequences did drive the machine fast
  WARN(name << ": " << commands << " commands, " << hits << " points, top speed " << watch.top_speed_ratio()
            << " of the limit");
}

}  // namespace

TEST_CASE("bounded motion on sim-servo-card.json", "[long]") { run_property("sim-servo-card.json", 1); }
TEST_CASE("bounded motion on sim-parport-shd.json", "[long]") { run_property("sim-parport-shd.json", 2); }
TEST_CASE("bounded motion on sim-parport-3dstep.json", "[long]") { run_property("sim-parport-3dstep.json", 3); }
TEST_CASE("bounded motion on sim-portio-drive.json", "[long]") { run_property("sim-portio-drive.json", 4); }
TEST_CASE("bounded motion on sim-portio-drive-map-a.json", "[long]") { run_property("sim-portio-drive-map-a.json", 5); }
TEST_CASE("bounded motion on sim-servo-card-request-reply.json", "[long]") { run_property("sim-servo-card-request-reply.json", 6); }
TEST_CASE("bounded motion on sim-mrm-arm.json", "[long]") { run_property("sim-mrm-arm.json", 7); }
TEST_CASE("bounded motion on sim-servo-card-loop-time.json", "[long]") { run_property("sim-servo-card-loop-time.json", 8); }
// The default machine with a measuring probe: its motion is the default's, but the status frames
// are longer and come every 6 ms (docs/servo-card-link.md, "The measuring probe").
TEST_CASE("bounded motion on sim-servo-card-scanning.json", "[long]") { run_property("sim-servo-card-scanning.json", 9, 0.1); }

TEST_CASE("every shipped configuration is covered by the bounded-motion property") {
  std::vector<std::string> shipped;
  for (const auto& f : std::filesystem::directory_iterator(std::string(IMESS_SOURCE_DIR) + "/config"))
    if (f.path().extension() == ".json" && imess::test::simulated_config(f.path())) shipped.push_back(f.path().filename().string());
  std::sort(shipped.begin(), shipped.end());
  CHECK(shipped == std::vector<std::string>{"sim-mrm-arm.json", "sim-parport-3dstep.json", "sim-parport-shd.json",
                                            "sim-portio-drive-map-a.json", "sim-portio-drive.json",
                                            "sim-servo-card-loop-time.json", "sim-servo-card-request-reply.json",
                                            "sim-servo-card-scanning.json", "sim-servo-card.json"});
}
