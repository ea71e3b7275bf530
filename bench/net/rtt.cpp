// rtt: the Status round trip (just before the send() -> the read() that brought the whole
// "Ok Status …" line) against bench_echo's echo round trip of the same "Status" line; one
// client each, random phases 0-2 ms. Also Version's round trip (a constant reply).
#include <stdexcept>

#include "client_pool.hpp"
#include "clock.hpp"
#include "figures.hpp"
#include "requests.hpp"
#include "stats.hpp"

namespace imess::bench {

namespace {
// Round trips of `line` from one client until a line starting with `answer` comes back.
std::vector<double> round_trips(Context& ctx, ClientPool& pool, int client, const std::string& line, std::string_view answer,
                                int samples) {
  std::vector<double> ms;
  std::int64_t arrived = 0;
  pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
    if (c == client && starts_with(l, answer)) arrived = t;
  };
  for (int i = -2; i < samples; ++i) {
    ctx.random_phase();
    pool.poll(0);
    arrived = 0;
    const std::int64_t t0 = mono_ns();
    pool.send(client, line);
    if (!pool.run_until([&] { return arrived != 0; }, 5.0))
      throw std::runtime_error("'" + line + "' got no '" + std::string(answer) + "' within 5 s (last line: " + pool.last_line(client) + ")");
    if (i >= 0) ms.push_back(ns_to_ms(arrived - t0));
  }
  pool.on_line = nullptr;
  return ms;
}
}  // namespace

void run_rtt(Context& ctx) {
  const int samples = ctx.options().samples.value_or(ctx.quick() ? 300 : 5000);
  LatencySet floor{"floor.echo", "floor: echo round trip", "floor: bench_echo, a 'Status' line sent -> its echo read, one client", {}};
  {
    auto echo = ctx.start_echo("echo");
    ClientPool pool;
    const int c = pool.open_ready(echo->port(), 1)[0];
    floor.ms = round_trips(ctx, pool, c, "Status", "Status", samples);
  }
  LatencySet status{"rtt.status", "Status round trip",
                    "Status sent (just before its send()) -> the whole 'Ok Status ...' line read, one client, machine at rest", {}};
  // Version: the same path through messd's reader, dispatcher and writer with the least work in
  // between (a constant reply), so Status minus Version is the cost of the status line itself.
  LatencySet version{"rtt.version", "Version round trip",
                     "Version sent -> 'Ok Version ...' read, one client, machine at rest (the io path with a constant reply)", {}};
  {
    auto messd = ctx.start_messd(4);
    ClientPool pool;
    const int c = pool.open_ready(messd->port(), 1)[0];
    status.ms = round_trips(ctx, pool, c, "Status", "Ok Status", samples);
    version.ms = round_trips(ctx, pool, c, "Version", "Ok Version", samples);
  }
  add_latency(ctx.report(), floor, nullptr, std::nullopt, std::nullopt);
  std::optional<Goal> goal;
  if (!floor.ms.empty()) goal = Goal{true, 1.2 * percentile(floor.ms, 0.5), "ms", "1.2 x floor"};
  add_latency(ctx.report(), status, &floor, goal, std::nullopt);
  add_latency(ctx.report(), version, &floor, std::nullopt, std::nullopt);
}

}  // namespace imess::bench
