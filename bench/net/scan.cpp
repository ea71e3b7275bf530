// scan: how fast a scan's points reach every client. A measuring probe on the simulated CMM
// (request/reply card link: a point can come every 1 ms cycle; its watchdog at 100 ms, so a
// loaded host without real-time scheduling bridges a late cycle instead of faulting) scans the worked example's
// bore with ScanStep 0.01 mm at 10 mm/s — 1 000 points a second, one `Scan` line each — to
// 100 clients: each point's t (messd's loop cycle, CLOCK_MONOTONIC) -> its Scan line read by
// all 100 clients, against bench_echo's timer at the same 1 000 lines a second to 100 clients.
// Whether one line per point keeps the push path's figures, or points must be batched, is
// what this measures (docs/performance.md, "Scanning").
#include <charconv>
#include <map>
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
constexpr int kScanClients = 100;
constexpr const char* kScanningMachine =
    R"("backend": { "type": "sim-servo-card", "link": "request-reply" }, "sim": { "watchdog_ms": 100, "probe": { "type": "analog" } })";
}  // namespace

void run_scan(Context& ctx) {
  const int samples = ctx.options().samples.value_or(ctx.quick() ? 300 : 3000);
  LatencySet floor{"floor.stamped1k.100", "floor: stamp -> line at all 100 clients, 1000/s",
                   "floor: bench_echo timer at 1000 Hz, the CLOCK_MONOTONIC stamp in its line -> read by all 100 clients", {}};
  {
    auto timer = ctx.start_echo("timer", 1000);
    ClientPool pool;
    pool.open_ready(timer->port(), kScanClients);
    floor.ms = stamped_fan_out(pool, samples, 30.0);
  }
  LatencySet scan{"push.scan.100", "scan point t -> Scan line at all 100 clients, 1000/s",
                  "a scan of the bore, ScanStep 0.01 mm at 10 mm/s (a point every 1 ms cycle): the Scan line's t (the loop "
                  "cycle that took it, messd's CLOCK_MONOTONIC) -> the line read by all 100 clients",
                  {}};
  auto messd = ctx.start_messd(kScanClients * 2, kScanningMachine);
  ClientPool pool;
  auto ids = pool.open_ready(messd->port(), kScanClients);
  const int owner = ids[0];
  request_ok(pool, owner, "Take");
  request_ok(pool, owner, "Set ScanStep 0.01");
  move_to_rest(pool, owner, 100000, "X460 Y350 Z100 F100");
  move_to_rest(pool, owner, 100001, "Z60 F100");
  struct Point {
    double t = 0;
    int count = 0;
    std::int64_t last = 0;
  };
  std::map<std::uint64_t, Point> points;
  bool ended = false;
  std::string failed;
  pool.on_line = [&](int c, std::string_view l, std::int64_t at) {
    if (starts_with(l, "Scan ")) {
      std::uint64_t seq = 0;
      const auto s = word(l, 1);
      std::from_chars(s.data(), s.data() + s.size(), seq);
      Point& p = points[seq];
      if (p.count++ == 0) {
        const auto w = word(l, 10);
        std::from_chars(w.data(), w.data() + w.size(), p.t);
      }
      p.last = std::max(p.last, at);
    } else if (c == owner && starts_with(l, "Done 7")) {
      ended = true;
    } else if (c == owner && (starts_with(l, "Failed 7") || starts_with(l, "Err ") || starts_with(l, "Fault "))) {
      failed.assign(l);
    }
  };
  const std::int64_t start = mono_ns();
  pool.send(owner, "ScanCirc 7 460 350 60 475 350 60 0 0 1 360 bore 10");
  pool.run_until([&] { return ended || !failed.empty() || static_cast<int>(points.size()) >= samples + 50; }, 30.0);
  const double seconds = ns_to_s(mono_ns() - start);
  pool.on_line = nullptr;
  if (!failed.empty()) throw std::runtime_error("the scan failed: " + failed);
  int skip = 50;  // the first points: the scan settling into contact
  for (const auto& [seq, p] : points) {
    if (p.count < kScanClients) continue;
    if (skip > 0) {
      --skip;
      continue;
    }
    if (static_cast<int>(scan.ms.size()) < samples) scan.ms.push_back(ns_to_ms(p.last) - p.t * 1e3);
  }
  request(pool, owner, "StopMv");
  request(pool, owner, "Release");
  if (scan.ms.empty()) throw std::runtime_error("no Scan point reached all 100 clients");
  scan.what += " (" + std::to_string(points.size()) + " points in " + std::to_string(seconds).substr(0, 4) + " s)";
  add_latency(ctx.report(), floor, nullptr, std::nullopt, std::nullopt);
  add_latency(ctx.report(), scan, &floor, std::nullopt, Goal{true, 2, "ms", ""});
}

}  // namespace imess::bench
