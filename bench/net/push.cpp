// push: how fast a measured point reaches every client.
//  (a) ForcePt sent by the owner -> MeasPt read by all of N clients (N 1 10 100 1000), against
//      bench_echo's broadcast (one client's line -> read by all N);
//  (b) a real probe hit on the simulated cube: the Hit's trigger time t (messd's loop cycle,
//      CLOCK_MONOTONIC) -> MeasPt read by all of 100 clients, against bench_echo's timer
//      (its CLOCK_MONOTONIC stamp -> read by all of 100 clients).
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "client_pool.hpp"
#include "clock.hpp"
#include "fan_out.hpp"
#include "figures.hpp"
#include "machine.hpp"
#include "requests.hpp"
#include "stats.hpp"

namespace imess::bench {

namespace {

constexpr int kProbeClients = 100;

// The probing cycle, repeated: from 82.5 mm (the retract after the previous hit, the ball's
// centre 2.5 mm above the cube's top at z = 80, tip radius 2) a Probe toward z = 81 searches
// at ProbeSpeed from rest and touches at z = 82; retract to 82.5; Done.
struct ProbeCycle {
  Context& ctx;
  ClientPool& pool;
  int owner;
  std::uint32_t next_id = 1;
  int failures = 0;
  std::string last_failure;

  // One hit; the latency in ms from t to the MeasPt at the last client, nullopt when the cycle
  // failed (UnexpectedHit, PartNotFound …: recorded, the machine is moved back up).
  std::optional<double> hit() {
    const std::uint32_t id = next_id++;
    const std::string ids = std::to_string(id);
    std::vector<char> got(static_cast<std::size_t>(pool.size()), 0);
    int remaining = 0;
    for (int c = 0; c < pool.size(); ++c) remaining += pool.is_open(c) ? 1 : 0;
    std::int64_t last = 0;
    double t = NAN;
    bool done = false;
    std::string failed;
    pool.on_line = [&](int c, std::string_view l, std::int64_t at) {
      if (starts_with(l, "Hit ") && std::isnan(t) && word(l, 2) == ids) {
        const auto w = word(l, 10);
        std::from_chars(w.data(), w.data() + w.size(), t);
      } else if (starts_with(l, "MeasPt ") && !std::isnan(t) && !got[static_cast<std::size_t>(c)]) {
        got[static_cast<std::size_t>(c)] = 1;
        --remaining;
        last = std::max(last, at);
      } else if (c == owner && word(l, 1) == ids && starts_with(l, "Done ")) {
        done = true;
      } else if (c == owner && word(l, 1) == ids && starts_with(l, "Failed ")) {
        failed.assign(l);
      } else if (c == owner && (starts_with(l, "Err ") || starts_with(l, "Fault "))) {
        failed.assign(l);
      }
    };
    ctx.random_phase();
    pool.send(owner, "Probe " + ids + " Z81");
    const bool ended = pool.run_until([&] { return (done && remaining == 0) || !failed.empty(); }, 10.0);
    pool.on_line = nullptr;
    if (ended && failed.empty()) return ns_to_ms(last) - t * 1e3;
    ++failures;
    last_failure = ended ? failed : "no Done within 10 s";
    pool.run_for(0.3);  // the stop or retract settles
    if (last_failure.rfind("Fault ", 0) == 0 || last_failure.find("Faulted") != std::string::npos) reset_fault(pool, owner);
    move_to_rest(pool, owner, next_id++, "Z84");
    if (failures > 5 + static_cast<int>(next_id) / 4)
      throw std::runtime_error("probing fails too often (" + std::to_string(failures) + " times; last: " + last_failure + ")" +
                               kFaultHint);
    return std::nullopt;
  }
};

std::string clients_text(int n) { return std::to_string(n) + (n == 1 ? " client" : " clients"); }

}  // namespace

void run_push(Context& ctx) {
  Report& r = ctx.report();
  const std::vector<int> counts = ctx.quick() ? std::vector<int>{1, 10, 100} : std::vector<int>{1, 10, 100, 1000};
  const int samples = ctx.options().samples.value_or(ctx.quick() ? 100 : 1000);
  auto messd = ctx.start_messd(counts.back() * 2);
  auto echo = ctx.start_echo("broadcast");

  Curve curve{"push.clients", "clients vs p99 of ForcePt -> MeasPt at all clients (messd) and of one line -> all clients (floor)",
              "clients", "ms", {{"messd", {}}, {"floor", {}}}};
  for (int n : counts) {
    LatencySet floor{"floor.broadcast." + std::to_string(n), "floor: a line -> all " + clients_text(n),
                     "floor: bench_echo broadcast, one client's line (just before its send()) -> read by all " + clients_text(n), {}};
    {
      ClientPool pool;
      auto ids = pool.open_ready(echo->port(), n);
      floor.ms = fan_out(ctx, pool, {ids[0], "MeasPt 430.000 330.000 100.000", "MeasPt ", "", samples});
    }
    LatencySet m{"push.forcept." + std::to_string(n), "ForcePt -> MeasPt at all " + clients_text(n),
                 "ForcePt sent by the owner (just before its send()) -> MeasPt read by all " + clients_text(n) +
                     " (the owner among them), random phases 0-2 ms",
                 {}};
    {
      ClientPool pool;
      auto ids = pool.open_ready(messd->port(), n);
      request_ok(pool, ids[0], "Take");
      m.ms = fan_out(ctx, pool, {ids[0], "ForcePt", "MeasPt ", "Ok ForcePt", samples});
      request(pool, ids[0], "Release");
    }
    std::optional<Goal> goal;
    if (n == 100) goal = Goal{true, 2, "ms", ""};
    if (n == 1000) goal = Goal{true, 5, "ms", ""};
    add_latency(r, floor, nullptr, std::nullopt, std::nullopt);
    add_latency(r, m, &floor, std::nullopt, goal);
    curve.series[0].second.push_back({static_cast<double>(n), percentile(m.ms, 0.99)});
    curve.series[1].second.push_back({static_cast<double>(n), percentile(floor.ms, 0.99)});
    ctx.random_phase();
  }
  r.add_curve(curve);

  // (b) probe hits at 100 clients.
  const int hits = ctx.options().samples.value_or(ctx.quick() ? 10 : 300);
  LatencySet stamped{"floor.stamped.100", "floor: stamp -> line at all 100 clients",
                     "floor: bench_echo timer at 200 Hz, the CLOCK_MONOTONIC stamp in its line -> read by all 100 clients", {}};
  {
    auto timer = ctx.start_echo("timer", 200);
    ClientPool pool;
    pool.open_ready(timer->port(), kProbeClients);
    stamped.ms = stamped_fan_out(pool, std::max(hits, 200), 30.0);
  }
  LatencySet probe{"push.probe.100", "probe trigger t -> MeasPt at all 100 clients",
                   "probe hit on the simulated cube: Hit's t (the loop cycle that read the latch, messd's CLOCK_MONOTONIC) "
                   "-> MeasPt read by all 100 clients",
                   {}};
  {
    ClientPool pool;
    auto ids = pool.open_ready(messd->port(), kProbeClients);
    const int owner = ids[0];
    request_ok(pool, owner, "Take");
    request_ok(pool, owner, "Set ProbeSpeed 20");
    request_ok(pool, owner, "Set RetractSpeed 20");
    move_to_rest(pool, owner, 100000, "X430 Y330 Z84 F100");
    ProbeCycle cycle{ctx, pool, owner, 1, 0, {}};
    for (int i = 0; static_cast<int>(probe.ms.size()) < hits; ++i)
      if (auto ms = cycle.hit(); ms && i >= 2) probe.ms.push_back(*ms);
    if (cycle.failures > 0) {
      note(std::to_string(cycle.failures) + " probing cycles failed (not counted); last: " + cycle.last_failure);
      probe.what += "; " + std::to_string(cycle.failures) + " cycles failed and were not counted (last: " + cycle.last_failure + ")";
    }
    request(pool, owner, "Release");
  }
  add_latency(r, stamped, nullptr, std::nullopt, std::nullopt);
  add_latency(r, probe, &stamped, std::nullopt, Goal{true, 1.5, "ms", ""});
}

}  // namespace imess::bench
