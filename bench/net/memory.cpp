// memory: messd's resident memory (VmRSS) with 0, 100 and 1000 clients connected -> per
// client (bench_echo the same way as reference); then a soak: clients connecting and
// disconnecting continually (some with a reset), some sending commands, the owner taking a
// point every second, RSS sampled every second -> start, max, end and the slope.
#include <deque>
#include <stdexcept>
#include <string>
#include <tuple>

#include "client_pool.hpp"
#include "clock.hpp"
#include "figures.hpp"
#include "proc_stats.hpp"
#include "requests.hpp"
#include "stats.hpp"

namespace imess::bench {

namespace {

struct Footprint {
  std::optional<double> rss0, rss100, rss1000, after;  // KiB
};

std::optional<double> settled_rss(ClientPool* pool, int pid) {
  if (pool) pool->run_for(0.5);
  else sleep_until_ns(mono_ns() + 500'000'000);
  return rss_kib(pid);
}

// RSS with 0, 100, 1000 clients (each got its first line), and after all left again.
Footprint footprint(int port, int pid) {
  Footprint f;
  f.rss0 = settled_rss(nullptr, pid);
  {
    ClientPool pool;
    pool.open_ready(port, 100);
    f.rss100 = settled_rss(&pool, pid);
    pool.open_ready(port, 900);
    f.rss1000 = settled_rss(&pool, pid);
  }
  sleep_until_ns(mono_ns() + 500'000'000);
  f.after = settled_rss(nullptr, pid);
  return f;
}

std::optional<double> per_client(const std::optional<double>& with, const std::optional<double>& without, int n) {
  if (!with || !without) return std::nullopt;
  return (*with - *without) / n;
}

const char* const kCommands[] = {"Status", "Get", "Help", "Version", "Frames", "Queue", "Stats", "Outputs", "PartPos", "Get ReportHz"};

}  // namespace

void run_memory(Context& ctx) {
  Report& r = ctx.report();
  const double soak = ctx.options().soak_seconds.value_or(ctx.quick() ? 4 : 600);
  auto messd = ctx.start_messd(1000);
  if (messd->pid() <= 0) throw std::runtime_error("memory needs messd's process id: give --pid with --port");
  Footprint floor;
  {
    auto echo = ctx.start_echo("echo");
    floor = footprint(echo->port(), echo->pid());
  }
  sleep_until_ns(mono_ns() + 500'000'000);  // messd settles after its start
  const Footprint m = footprint(messd->port(), messd->pid());

  const struct {
    const char* stem;
    const char* label;
    const char* when;
    std::optional<double> messd, floor;
  } footprints[] = {{"rss.0", "RSS, no client", "with no client connected (0.5 s after start)", m.rss0, floor.rss0},
             {"rss.100", "RSS, 100 clients", "with 100 clients connected", m.rss100, floor.rss100},
             {"rss.1000", "RSS, 1000 clients", "with 1000 clients connected", m.rss1000, floor.rss1000},
             {"rss.after", "RSS, after the 1000 left", "1 s after the 1000 clients disconnected", m.after, floor.after}};
  for (const auto& k : footprints) {
    const std::string floor_id = std::string("floor.memory.") + k.stem;
    r.add({floor_id, std::string("floor: bench_echo ") + k.label, std::string("floor: bench_echo's VmRSS ") + k.when, k.floor, "KiB", "",
           std::nullopt, std::nullopt});
    r.add({std::string("memory.") + k.stem, std::string("messd ") + k.label, std::string("messd's VmRSS ") + k.when, k.messd, "KiB",
           floor_id, k.floor, std::nullopt});
  }
  for (const auto& [n, floor_rss, messd_rss] : {std::tuple{100, floor.rss100, m.rss100}, std::tuple{1000, floor.rss1000, m.rss1000}}) {
    const std::string c = std::to_string(n);
    const std::string floor_id = "floor.memory.per_client." + c;
    const auto floor_per = per_client(floor_rss, floor.rss0, n);
    r.add({floor_id, "floor: bench_echo RSS per client, " + c,
           "floor: (bench_echo's VmRSS with " + c + " clients - with none) / " + c, floor_per, "KiB", "", std::nullopt,
           std::nullopt});
    r.add({"memory.per_client." + c, "messd RSS per client, " + c, "(messd's VmRSS with " + c + " clients - with none) / " + c,
           per_client(messd_rss, m.rss0, n), "KiB", floor_id, floor_per, std::nullopt});
  }

  // The soak: 50 observers and the owner stay; a client connects every 20 ms and the oldest
  // of the churning ones (50 at a time) leaves, every fourth with a reset; each new client
  // says Hello and asks Status; every 10 ms a random client sends a command; the owner
  // sends ForcePt every second (a Hit and a MeasPt to everyone, a journal append).
  ClientPool pool;
  auto stay = pool.open_ready(messd->port(), 51);
  const int owner = stay[0];
  request_ok(pool, owner, "Take");
  std::deque<int> churn;
  std::vector<char> greeted;
  std::uint64_t connects = 0, commands = 0;
  pool.on_line = [&](int c, std::string_view, std::int64_t) {
    if (static_cast<std::size_t>(c) >= greeted.size()) greeted.resize(static_cast<std::size_t>(c) + 1, 0);
    if (!greeted[static_cast<std::size_t>(c)] && c > stay.back()) {
      greeted[static_cast<std::size_t>(c)] = 1;
      pool.send(c, "Hello churn" + std::to_string(c));
      pool.send(c, "Status");
    }
  };
  std::vector<double> t_s, rss;
  std::uniform_int_distribution<int> pick_command(0, static_cast<int>(std::size(kCommands)) - 1);
  const std::int64_t start = mono_ns();
  std::int64_t next_connect = start, next_command = start, next_point = start, next_sample = start;
  std::uint64_t round = 0;
  for (;;) {
    const std::int64_t now = mono_ns();
    if (now - start >= static_cast<std::int64_t>(soak * 1e9)) break;
    if (now >= next_sample) {
      if (auto k = rss_kib(messd->pid())) {
        t_s.push_back(ns_to_s(now - start));
        rss.push_back(*k);
      }
      next_sample += 1'000'000'000;
    }
    if (now >= next_connect) {
      churn.push_back(pool.open(messd->port()));
      ++connects;
      if (churn.size() > 50) {
        if (++round % 4 == 0) pool.reset(churn.front());
        else pool.close(churn.front());
        churn.pop_front();
      }
      next_connect += 20'000'000;
    }
    if (now >= next_command) {
      std::vector<int> live(stay.begin() + 1, stay.end());
      for (int c : churn)
        if (pool.connected(c)) live.push_back(c);
      std::uniform_int_distribution<std::size_t> who(0, live.size() - 1);
      pool.send(live[who(ctx.rng())], kCommands[pick_command(ctx.rng())]);
      ++commands;
      next_command += 10'000'000;
    }
    if (now >= next_point) {
      pool.send(owner, "ForcePt");
      next_point += 1'000'000'000;
    }
    pool.poll(0.001);
  }
  if (!pool.is_open(owner)) throw std::runtime_error("the owner was disconnected during the soak: " + pool.close_reason(owner));
  request(pool, owner, "Release");
  pool.on_line = nullptr;
  note("memory soak: " + std::to_string(connects) + " connections, " + std::to_string(commands) + " commands in " +
       std::to_string(static_cast<int>(soak)) + " s");

  // The slope over the second half: the first lets the allocator's pools and the buffers
  // reach their working size.
  std::vector<double> tx, ty;
  for (std::size_t i = t_s.size() / 2; i < t_s.size(); ++i) {
    tx.push_back(t_s[i] / 60.0);
    ty.push_back(rss[i]);
  }
  const std::string during = " during the " + std::to_string(static_cast<int>(soak)) + " s churn";
  std::optional<double> start_k, max_k, end_k, slope_k;
  if (!rss.empty()) {
    start_k = rss.front();
    max_k = max_of(rss);
    end_k = rss.back();
  }
  if (tx.size() >= 2) slope_k = slope(tx, ty);
  r.add({"memory.soak.start", "messd RSS at the start of the churn", "messd's VmRSS, first sample" + during, start_k, "KiB", "",
         std::nullopt, std::nullopt});
  r.add({"memory.soak.max", "messd RSS, max during the churn", "messd's VmRSS, largest 1 s sample" + during, max_k, "KiB", "",
         std::nullopt, std::nullopt});
  r.add({"memory.soak.end", "messd RSS at the end of the churn", "messd's VmRSS, last sample" + during, end_k, "KiB", "",
         std::nullopt, std::nullopt});
  r.add({"memory.soak.slope", "messd RSS slope, second half of the churn",
         "least-squares slope of messd's VmRSS (1 s samples) over the second half" + during +
             " (51 clients staying, 50 connections a second, 100 commands a second, 1 ForcePt a second); reference: none",
         slope_k, "KiB/min", "", std::nullopt, Goal{true, 16, "KiB/min", "flat"}});
  std::vector<std::pair<double, double>> series;
  for (std::size_t i = 0; i < t_s.size(); ++i) series.push_back({t_s[i], rss[i]});
  r.add_curve({"memory.soak", "messd's VmRSS during the churn, every second", "s", "KiB", {{"messd", series}}});
}

}  // namespace imess::bench
