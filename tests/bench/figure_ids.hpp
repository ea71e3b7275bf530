// The figure ids bench_net and bench_rt promise (docs/performance.md, "The figures"), for the
// smoke tests of the programs and of scripts/bench. Quick mode keeps every id but push's
// 1000 clients.
#pragma once
#include <string>
#include <vector>

namespace imess::test::bench_ids {

inline void add_stats(std::vector<std::string>& ids, const std::string& stem, const std::vector<std::string>& stats) {
  for (const auto& s : stats) ids.push_back(stem + "." + s);
}

// bench_net push: ForcePt and the probe hit, each with its floor, p50 and p99.
inline std::vector<std::string> net_push(bool quick) {
  std::vector<std::string> ids;
  std::vector<std::string> counts{"1", "10", "100"};
  if (!quick) counts.push_back("1000");
  for (const auto& n : counts) {
    add_stats(ids, "floor.broadcast." + n, {"p50", "p99"});
    add_stats(ids, "push.forcept." + n, {"p50", "p99"});
  }
  add_stats(ids, "floor.stamped.100", {"p50", "p99"});
  add_stats(ids, "push.probe.100", {"p50", "p99"});
  return ids;
}

// bench_net all (push stream jog rtt memory scan) with stream's default 200 clients.
inline std::vector<std::string> net_all(bool quick) {
  std::vector<std::string> ids = net_push(quick);
  for (const char* id : {"stream.client_hz.max", "stream.reporthz.max", "floor.timer.200.rate.min", "floor.timer.200.rate.median",
                         "stream.rate.min", "stream.rate.median", "floor.timer.200.cpu", "stream.cpu", "stream.cpu.motion", "stream.cpu.io",
                         "floor.timer.200.io_wakeups", "stream.io_wakeups", "stream.cpu.idle", "stream.cpu.idle.io",
                         "stream.io_wakeups.idle", "stream.cpu.1client", "stream.bench_cpu"})
    ids.push_back(id);
  for (const char* stem : {"jog.status_rtt", "jog.state", "jog.currcor.10", "jog.currcor.100", "jog.currcor.stream1000", "floor.echo",
                           "rtt.status", "rtt.version"})
    add_stats(ids, stem, {"p50", "p99"});
  for (const char* prefix : {"floor.memory", "memory"})
    add_stats(ids, prefix, {"rss.0", "rss.100", "rss.1000", "rss.after", "per_client.100", "per_client.1000"});
  add_stats(ids, "memory.soak", {"start", "max", "end", "slope"});
  add_stats(ids, "floor.stamped1k.100", {"p50", "p99"});
  add_stats(ids, "push.scan.100", {"p50", "p99"});
  return ids;
}

inline const std::vector<std::string> kLatencyStats{"p50", "p99", "p999", "max", "overruns"};

// bench_rt loop: messd's loop and cyclictest, idle and loaded.
inline std::vector<std::string> rt_loop() {
  std::vector<std::string> ids;
  for (const char* condition : {"idle", "loaded"})
    for (const char* side : {"rt.loop.", "floor.loop."}) add_stats(ids, side + std::string(condition), kLatencyStats);
  return ids;
}

// bench_rt all: the loop, then the base thread at 25 and 50 us.
inline std::vector<std::string> rt_all() {
  std::vector<std::string> ids = rt_loop();
  for (const char* period : {"25", "50"}) {
    add_stats(ids, std::string("rt.base.") + period, kLatencyStats);
    add_stats(ids, std::string("floor.base.") + period, kLatencyStats);
    add_stats(ids, std::string("rt.base.") + period,
              {"jitter", "step_rate", "jitter.p999", "step_rate.p999", "tick.p50", "tick.p99", "tick.ports", "tick.cost", "tick.share"});
  }
  return ids;
}

}  // namespace imess::test::bench_ids
