// stream: the CurrCor stream at ReportHz 100 to N clients (default 200) while the owner jogs
// for the whole window: each client's received rate, and messd's CPU from /proc (the whole
// process, its motion-loop thread, the rest). Reference: bench_echo's timer at 100 Hz to as
// many clients. Also: the highest rate a client may choose for itself (Stream) and the
// highest shared ReportHz, and messd's CPU and io wake-ups with
// no client and with the owner alone (the baselines the streaming adds to).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "client_pool.hpp"
#include "clock.hpp"
#include "figures.hpp"
#include "proc_stats.hpp"
#include "requests.hpp"
#include "stats.hpp"

namespace imess::bench {

namespace {

constexpr double kRate = 100;  // Hz, the rate the issue asks for

struct StreamResult {
  std::vector<double> rates;  // Hz, per client
  std::optional<double> cpu, motion_cpu;  // % of one core
  std::optional<double> io_wakeups;       // per second, the threads other than the motion loop's
  double bench_cpu = 0, window_s = 0;
};

// Counts CurrCor lines per client for `seconds`, reading the server's CPU over the same time;
// every line also goes to `base`, the pool's handler before and after.
StreamResult measure(ClientPool& pool, double seconds, int pid, const ClientPool::LineHandler& base) {
  std::vector<std::uint32_t> count(static_cast<std::size_t>(pool.size()), 0);
  pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
    if (starts_with(l, "CurrCor ")) ++count[static_cast<std::size_t>(c)];
    if (base) base(c, l, t);
  };
  pool.poll(0);
  std::fill(count.begin(), count.end(), 0);
  const auto cpu0 = process_cpu_s(pid);
  const auto motion0 = threads_cpu_s(pid, "messd-motion", false);
  const auto wake0 = threads_wakeups(pid, "messd-motion", true);
  const double own0 = own_cpu_s();
  const std::int64_t t0 = mono_ns();
  pool.run_for(seconds);
  const std::int64_t t1 = mono_ns();
  const auto cpu1 = process_cpu_s(pid);
  const auto motion1 = threads_cpu_s(pid, "messd-motion", false);
  const auto wake1 = threads_wakeups(pid, "messd-motion", true);
  pool.on_line = base;
  StreamResult r;
  r.window_s = ns_to_s(t1 - t0);
  for (int c = 0; c < pool.size(); ++c)
    if (pool.is_open(c)) r.rates.push_back(static_cast<double>(count[static_cast<std::size_t>(c)]) / r.window_s);
  if (cpu0 && cpu1) r.cpu = cpu_percent(*cpu1 - *cpu0, r.window_s);
  if (motion0 && motion1) r.motion_cpu = cpu_percent(*motion1 - *motion0, r.window_s);
  if (wake0 && wake1) r.io_wakeups = (*wake1 - *wake0) / r.window_s;
  r.bench_cpu = cpu_percent(own_cpu_s() - own0, r.window_s);
  return r;
}

// Keeps the owner jogging along X between lo and hi for as long as the pool is served:
// reverses (StartMv with the other sign) when a CurrCor shows it past an end.
struct Jogger {
  ClientPool& pool;
  int owner;
  double lo, hi, percent;
  int direction = 1;
  int reversals = 0;
  int faults = 0;
  std::string last_fault;

  std::string command() const {
    char buf[64];
    std::snprintf(buf, sizeof buf, "StartMv %.3f 0 0", direction * percent);
    return buf;
  }
  void on_line(int c, std::string_view l) {
    if (c == owner && starts_with(l, "Fault ")) {  // a starved loop on a loaded host: clear it, jog on
      ++faults;
      last_fault.assign(l);
      pool.send(owner, "Reset");
      pool.send(owner, command());
    }
    if (c != owner || !starts_with(l, "CurrCor ")) return;
    const auto w = word(l, 1);
    double x = 0;
    std::from_chars(w.data(), w.data() + w.size(), x);
    if ((direction > 0 && x > hi) || (direction < 0 && x < lo)) {
      direction = -direction;
      ++reversals;
      pool.send(owner, command());
    }
  }
};

double number_after(std::string_view line, std::string_view name) {
  const auto w = value_after(line, name);
  double v = NAN;
  std::from_chars(w.data(), w.data() + w.size(), v);
  return v;
}

// The highest of the loop rate, 500, 200 and 100 Hz that `command hz` is answered Ok for.
struct Accepted {
  double hz = 0;
  std::string refusal;  // the first refusal
};
Accepted highest_accepted(ClientPool& pool, int client, const std::string& command, double loop_hz) {
  Accepted a;
  for (double hz : {loop_hz, 500.0, 200.0, kRate}) {
    if (!(hz > 0) || a.hz > 0) continue;
    char line[64];
    std::snprintf(line, sizeof line, "%s %g", command.c_str(), hz);
    auto reply = request(pool, client, line);
    if (reply && reply->ok()) a.hz = hz;
    else if (a.refusal.empty()) a.refusal = reply ? reply->line : "no reply";
  }
  return a;
}

Figure rate_figure(const std::string& id, const std::string& label, const std::string& what, const std::vector<double>& rates,
                   bool minimum, const std::string& ref_id, const std::vector<double>* ref, std::optional<Goal> goal) {
  Figure f{id, label, what, std::nullopt, "Hz", ref_id, std::nullopt, goal};
  if (!rates.empty()) f.value = minimum ? min_of(rates) : median(rates);
  if (ref && !ref->empty()) f.reference = minimum ? min_of(*ref) : median(*ref);
  if (!ref) f.reference_id.clear();
  return f;
}

}  // namespace

void run_stream(Context& ctx) {
  Report& r = ctx.report();
  const int n = ctx.options().clients.value_or(200);
  const double window = ctx.options().seconds.value_or(ctx.quick() ? 2 : 30);
  const double baseline = ctx.quick() ? 0.5 : 5;
  const std::string ns = std::to_string(n);
  auto messd = ctx.start_messd(n);
  if (messd->pid() <= 0) note("stream: no --pid, so no CPU figures for messd");

  // The floor: bench_echo's timer at 100 Hz to n clients.
  StreamResult floor;
  {
    auto echo = ctx.start_echo("timer", kRate);
    ClientPool pool;
    pool.open_ready(echo->port(), n);
    pool.run_for(0.5);
    floor = measure(pool, window, echo->pid(), nullptr);
  }

  // messd alone, no client, the machine standing: what the rest is measured on top of.
  StreamResult idle;
  {
    ClientPool none;
    none.run_for(0.5);
    idle = measure(none, baseline, messd->pid(), nullptr);
  }

  ClientPool pool;
  const int owner = pool.open_ready(messd->port(), 1)[0];
  request_ok(pool, owner, "Take");
  const double period_us = number_after(request_ok(pool, owner, "Get Period").line, "Period");
  const double loop_hz = period_us > 0 ? 1e6 / period_us : std::numeric_limits<double>::quiet_NaN();
  const Accepted shared = highest_accepted(pool, owner, "Set ReportHz", loop_hz);
  request_ok(pool, owner, "Set ReportHz 100");

  // Jog along X for the whole run: about 800 mm of room on the default table.
  const auto status = request_ok(pool, owner, "Status").line;
  const double x = number_after(status, "Pos");
  const double max_speed = number_after(request_ok(pool, owner, "Get MaxSpeed").line, "MaxSpeed");
  const double lo = 100, hi = 900;
  if (!(x >= lo && x <= hi))
    throw std::runtime_error("stream jogs X between 100 and 900 mm and the machine stands at x = " + std::to_string(x) +
                             "; move it there first");
  const double run_s = window + baseline + 3;
  const double speed = std::clamp(0.9 * std::max(hi - x, x - lo) / run_s, 2.0, 50.0);
  Jogger jog{pool, owner, lo, hi, 100 * speed / (max_speed > 0 ? max_speed : 100), 1, 0, 0, {}};
  const ClientPool::LineHandler keep_jogging = [&](int c, std::string_view l, std::int64_t) { jog.on_line(c, l); };
  pool.on_line = keep_jogging;
  jog.direction = hi - x >= x - lo ? 1 : -1;  // toward the more room
  if (!request_until(pool, owner, jog.command(), "State jog"))
    throw std::runtime_error("the jog did not start (last line: " + pool.last_line(owner) + ")");
  pool.run_for(0.5);

  const StreamResult alone = measure(pool, baseline, messd->pid(), keep_jogging);
  pool.open_ready(messd->port(), n - 1);
  pool.run_for(0.5);
  const StreamResult m = measure(pool, window, messd->pid(), keep_jogging);
  request(pool, owner, "StopMv");
  // Can a client choose its own rate, up to the loop's? A new observer asks (after the window:
  // it changes nothing measured), then returns to the shared rate.
  const int observer = pool.open_ready(messd->port(), 1)[0];
  const Accepted own = highest_accepted(pool, observer, "Stream", loop_hz);
  request(pool, observer, "Stream 0");
  char loop_text[32];
  std::snprintf(loop_text, sizeof loop_text, "%g", loop_hz);
  const std::string tried = " trying the motion loop's rate (1e6/Period = " + std::string(loop_text) + " Hz), 500, 200, 100";
  r.add({"stream.client_hz.max", "highest rate a client may choose (Stream)",
         "the highest own CurrCor rate an observer's 'Stream hz' is granted," + tried +
             (own.refusal.empty() ? "" : "; refused: '" + own.refusal + "'") + "; reference: none (a setting)",
         own.hz > 0 ? std::optional<double>(own.hz) : std::nullopt, "Hz", "", std::nullopt,
         std::isfinite(loop_hz) ? std::optional<Goal>(Goal{false, loop_hz, "Hz", "the loop rate"}) : std::nullopt});
  r.add({"stream.reporthz.max", "highest shared ReportHz accepted",
         "the highest shared CurrCor rate the owner's 'Set ReportHz' accepts (every client without a Stream rate of its own)," + tried +
             (shared.refusal.empty() ? "" : "; refused: '" + shared.refusal + "'") + "; reference: none (a setting)",
         shared.hz > 0 ? std::optional<double>(shared.hz) : std::nullopt, "Hz", "", std::nullopt, std::nullopt});

  request(pool, owner, "Release");
  if (jog.reversals > 0) note("stream: the jog reversed " + std::to_string(jog.reversals) + " times (a few reports are lost at each)");
  const std::string faults = jog.faults == 0 ? "" : "; " + std::to_string(jog.faults) + " faults during the run (last: " + jog.last_fault + ")";
  if (!faults.empty()) note("stream" + faults);

  const std::string fid = "floor.timer." + ns;
  r.add(rate_figure(fid + ".rate.min", "floor: timer 100 Hz, slowest of " + ns + " clients",
                    "floor: bench_echo's timer at 100 Hz to " + ns + " clients, lines received by the slowest client / window", floor.rates,
                    true, "", nullptr, std::nullopt));
  r.add(rate_figure(fid + ".rate.median", "floor: timer 100 Hz, median of " + ns + " clients",
                    "floor: bench_echo's timer at 100 Hz to " + ns + " clients, median per-client rate", floor.rates, false, "", nullptr,
                    std::nullopt));
  const std::string window_text = " over " + std::to_string(static_cast<int>(std::lround(m.window_s))) + " s";
  r.add(rate_figure("stream.rate.min", "CurrCor rate, slowest of " + ns + " clients",
                    "CurrCor lines received by the slowest of " + ns + " clients / window" + window_text +
                        ", ReportHz 100, owner jogging" + faults,
                    m.rates, true, fid + ".rate.min", &floor.rates, Goal{false, 99, "Hz", ""}));
  r.add(rate_figure("stream.rate.median", "CurrCor rate, median of " + ns + " clients",
                    "median per-client CurrCor rate" + window_text + ", ReportHz 100, owner jogging", m.rates, false, fid + ".rate.median",
                    &floor.rates, Goal{false, 99, "Hz", ""}));
  r.add({fid + ".cpu", "floor: bench_echo CPU, timer 100 Hz to " + ns,
         "floor: bench_echo's CPU (utime+stime from /proc) while its timer sends 100 Hz to " + ns + " clients, % of one core",
         floor.cpu, "%", "", std::nullopt, std::nullopt});
  r.add({"stream.cpu", "messd CPU, " + ns + " clients at 100 Hz, jogging",
         "messd's CPU (utime+stime of the process from /proc/<pid>/stat over the window), " + ns +
             " clients at ReportHz 100, owner jogging, % of one core",
         m.cpu, "%", fid + ".cpu", floor.cpu, Goal{true, 8, "%", ""}});
  r.add({"stream.cpu.motion", "messd motion-loop thread CPU, same window",
         "the messd-motion thread's share of stream.cpu (the 1 kHz loop; sim card included); reference: none (floor has no loop)",
         m.motion_cpu, "%", "", std::nullopt, std::nullopt});
  std::optional<double> rest;
  if (m.cpu && m.motion_cpu) rest = *m.cpu - *m.motion_cpu;
  r.add({"stream.cpu.io", "messd other threads CPU (io), same window",
         "stream.cpu minus the motion-loop thread: the io thread and the rest; reference bench_echo's whole CPU", rest, "%", fid + ".cpu",
         floor.cpu, std::nullopt});
  r.add({fid + ".io_wakeups", "floor: bench_echo wake-ups a second",
         "floor: bench_echo's voluntary context switches (sleeps that ended in a wake-up) a second, same window", floor.io_wakeups, "1/s", "",
         std::nullopt, std::nullopt});
  r.add({"stream.io_wakeups", "messd io wake-ups a second, " + ns + " clients",
         "voluntary context switches a second of messd's threads other than the motion loop (the io thread: each is a wake-up), "
         "same window",
         m.io_wakeups, "1/s", fid + ".io_wakeups", floor.io_wakeups, std::nullopt});
  r.add({"stream.cpu.idle", "messd CPU, no client, standing",
         "messd's CPU with no client connected and the machine standing, % of one core; reference: none (a baseline)", idle.cpu, "%", "",
         std::nullopt, std::nullopt});
  std::optional<double> idle_io;
  if (idle.cpu && idle.motion_cpu) idle_io = *idle.cpu - *idle.motion_cpu;
  r.add({"stream.cpu.idle.io", "messd io CPU, no client, standing",
         "the part of stream.cpu.idle outside the motion-loop thread (the io thread's timers); reference: none", idle_io, "%", "",
         std::nullopt, std::nullopt});
  r.add({"stream.io_wakeups.idle", "messd io wake-ups a second, no client",
         "voluntary context switches a second of messd's threads other than the motion loop, no client, standing; reference: none",
         idle.io_wakeups, "1/s", "", std::nullopt, std::nullopt});
  r.add({"stream.cpu.1client", "messd CPU, owner alone at 100 Hz, jogging",
         "messd's CPU with only the owner connected, ReportHz 100, jogging, % of one core; reference: none (a baseline)", alone.cpu, "%", "",
         std::nullopt, std::nullopt});
  r.add({"stream.bench_cpu", "bench_net's own CPU serving the clients",
         "this program's CPU (getrusage) while its one thread read the " + ns +
             " clients' streams: the client side kept up when well below 100 %; reference: none",
         m.bench_cpu, "%", "", std::nullopt, std::nullopt});
  r.add_distribution("stream.rates", "per-client CurrCor rate, " + ns + " clients, ReportHz 100, owner jogging", "Hz", m.rates,
                     fid + ".rates");
  r.add_distribution(fid + ".rates", "floor: per-client rate of bench_echo's 100 Hz timer, " + ns + " clients", "Hz", floor.rates);
  auto sorted_series = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    std::vector<std::pair<double, double>> s;
    for (std::size_t i = 0; i < v.size(); ++i) s.push_back({static_cast<double>(i), v[i]});
    return s;
  };
  r.add_curve({"stream.rates.sorted", "per-client CurrCor rate, clients sorted slowest first", "client rank", "Hz",
               {{"messd", sorted_series(m.rates)}, {"floor", sorted_series(floor.rates)}}});
}

}  // namespace imess::bench
