// jog: how soon a jog shows. From rest the owner sends StartMv (alternately +X and -X at
// 10 mm/s); measured from just before the send() to the first CurrCor whose position differs
// from the last one at rest, at the jogging client, at ReportHz 10 and 100 and at the client's
// own Stream 1000; then StopMv, State idle, 2.5 report periods, repeat at a random phase.
// Also StartMv -> State jog (the loop took the jog). Random phases: uniform over one report
// period, then 0-2 ms.
// Reference: the Status round trip measured between the jogs.
#include <stdexcept>

#include "client_pool.hpp"
#include "clock.hpp"
#include "figures.hpp"
#include "machine.hpp"
#include "requests.hpp"

namespace imess::bench {

void run_jog(Context& ctx) {
  Report& r = ctx.report();
  const int samples = ctx.options().samples.value_or(ctx.quick() ? 6 : 200);
  auto messd = ctx.start_messd(4);
  ClientPool pool;
  const int owner = pool.open_ready(messd->port(), 1)[0];
  std::string rest_pos;  // the position of the last CurrCor
  auto track = [&](int c, std::string_view l, std::int64_t) {
    if (c == owner && starts_with(l, "CurrCor ")) rest_pos.assign(l.substr(8));
  };
  pool.on_line = track;
  request_ok(pool, owner, "Take");

  LatencySet status{"jog.status_rtt", "Status round trip between the jogs",
                    "reference: Status sent (just before its send()) -> Ok Status read, at rest between the jogs", {}};
  LatencySet state{"jog.state", "StartMv -> State jog",
                   "StartMv sent from rest -> State jog read by the jogging client (the motion loop took the jog), ReportHz 10 and 100", {}};
  std::vector<LatencySet> shown;
  int direction = 1;
  int faults = 0;
  std::string last_fault;
  // The shared ReportHz 10 and 100, then the client's own rate at the loop's (Stream 1000):
  // what remains there is the loop taking the jog and the carriage moving a printed 0.001 mm.
  for (int hz : {10, 100, 1000}) {
    const bool own = hz > 100;
    request_ok(pool, owner, own ? "Stream " + std::to_string(hz) : "Set ReportHz " + std::to_string(hz));
    const std::string rate = own ? "Stream " + std::to_string(hz) + " (the client's own rate)" : "ReportHz " + std::to_string(hz);
    LatencySet set{own ? "jog.currcor.stream" + std::to_string(hz) : "jog.currcor." + std::to_string(hz),
                   "StartMv -> first moved CurrCor, " + (own ? "Stream " + std::to_string(hz) : "ReportHz " + std::to_string(hz)),
                   "StartMv sent from rest -> the first CurrCor with another position read by the jogging client, " + rate, {}};
    for (int i = -2; i < samples; ++i) {
      // At rest as messd counts it: the stop's last CurrCor has come (within a report period
      // of State idle) and a whole report period passed without a change; and a margin.
      pool.run_for(2.5 / hz + 0.02);
      if (auto s = request(pool, owner, "Status"); s && s->ok() && i >= 0) status.ms.push_back(ns_to_ms(s->arrived_ns - s->sent_ns));
      const std::string before = rest_pos;
      std::int64_t moved = 0, jogging = 0;
      std::string refused, fault;
      pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
        if (c != owner) return;
        if (starts_with(l, "CurrCor ") && !moved && l.substr(8) != before) moved = t;
        if (starts_with(l, "State jog") && !jogging) jogging = t;
        if (starts_with(l, "Err ")) refused.assign(l);
        if (starts_with(l, "Fault ")) fault.assign(l);
        track(c, l, t);
      };
      // A random phase against the CurrCor reporter's period as well as the loop's.
      std::uniform_real_distribution<double> phase(0, 1.0 / hz);
      sleep_until_ns(mono_ns() + static_cast<std::int64_t>(phase(ctx.rng()) * 1e9));
      ctx.random_phase();
      const std::int64_t t0 = mono_ns();
      pool.send(owner, direction > 0 ? "StartMv 10 0 0" : "StartMv -10 0 0");
      const bool ok = pool.run_until([&] { return (moved && jogging) || !refused.empty() || !fault.empty(); }, 5.0);
      bool rest = ok && refused.empty() && fault.empty() && request_until(pool, owner, "StopMv", "State idle", 5.0);
      pool.on_line = track;
      if (!rest || !fault.empty()) {
        // Faulted (a starved loop on a loaded host: CommLost) or refused because of it: Reset, repeat.
        const std::string why = !fault.empty() ? fault : !refused.empty() ? refused : "no moved CurrCor or no rest within 5 s";
        if (++faults > 10) throw std::runtime_error("jogging fails too often; last: " + why + kFaultHint);
        last_fault = why;
        pool.run_for(0.2);
        reset_fault(pool, owner);
        --i;
        continue;
      }
      if (i >= 0) {
        set.ms.push_back(ns_to_ms(moved - t0));
        state.ms.push_back(ns_to_ms(jogging - t0));
      }
      direction = -direction;  // back and forth: the machine stays near where it started
    }
    shown.push_back(std::move(set));
  }
  if (faults > 0) {
    note("jog: " + std::to_string(faults) + " samples were repeated after a fault or refusal; last: " + last_fault);
    for (auto& set : shown) set.what += "; " + std::to_string(faults) + " samples repeated after a fault (last: " + last_fault + ")";
  }
  request(pool, owner, "Stream 0");
  request(pool, owner, "Set ReportHz 10");
  request(pool, owner, "Release");
  add_latency(r, status, nullptr, std::nullopt, std::nullopt);
  add_latency(r, state, &status, std::nullopt, std::nullopt);
  for (const auto& set : shown) add_latency(r, set, &status, std::nullopt, Goal{true, 1.5, "ms", ""});
}

}  // namespace imess::bench
