// load: a load generator for the other benchmarks. --clients idle clients stay connected and
// read everything; one more client sends --lines-per-s command lines (Status and Get
// ReportHz in turn), paced every millisecond, and reads the replies (at most 200 unanswered:
// beyond that it waits, as messd would stop reading it at 256). Ends cleanly after --seconds.
// Against a running messd (--port) or one started here.
#include <deque>
#include <stdexcept>

#include "client_pool.hpp"
#include "clock.hpp"
#include "figures.hpp"
#include "requests.hpp"
#include "stats.hpp"

namespace imess::bench {

void run_load(Context& ctx) {
  Report& r = ctx.report();
  const int idle = ctx.options().clients.value_or(100);
  const double rate = ctx.options().lines_per_s;
  const double seconds = ctx.options().seconds.value_or(ctx.quick() ? 5 : 10);
  constexpr std::size_t kMaxOpen = 200;
  auto messd = ctx.start_messd(idle + 1);
  ClientPool pool;
  pool.open_ready(messd->port(), idle);
  const int sender = pool.open_ready(messd->port(), 1)[0];

  std::deque<std::int64_t> sent_at;  // of the lines not yet answered
  std::vector<double> reply_ms;
  std::uint64_t sent = 0, answered = 0, refused = 0, held_back = 0;
  std::string first_refusal;
  pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
    if (c != sender || sent_at.empty()) return;
    const bool ok = starts_with(l, "Ok ");
    if (!ok && !starts_with(l, "Err ")) return;
    if (!ok) {
      ++refused;
      if (first_refusal.empty()) first_refusal.assign(l);
    }
    reply_ms.push_back(ns_to_ms(t - sent_at.front()));
    sent_at.pop_front();
    ++answered;
  };
  const std::int64_t start = mono_ns();
  const std::int64_t end = start + static_cast<std::int64_t>(seconds * 1e9);
  for (std::int64_t now = start; now < end; now = mono_ns()) {
    const auto due = static_cast<std::uint64_t>(ns_to_s(now - start) * rate);
    while (sent < due) {
      if (sent_at.size() >= kMaxOpen) {
        ++held_back;
        break;
      }
      sent_at.push_back(mono_ns());
      pool.send(sender, sent % 2 == 0 ? "Status" : "Get ReportHz");
      ++sent;
    }
    if (!pool.is_open(sender)) throw std::runtime_error("messd closed the sending client: " + pool.close_reason(sender));
    pool.poll(0.001);
  }
  const double wall = ns_to_s(mono_ns() - start);
  pool.run_until([&] { return sent_at.empty(); }, 2.0);  // the last replies
  pool.on_line = nullptr;
  int still_open = 0;
  for (int c = 0; c < pool.size(); ++c) still_open += pool.is_open(c) ? 1 : 0;
  pool.close_all();
  if (refused > 0) note("load: " + std::to_string(refused) + " lines refused, the first: " + first_refusal);
  if (held_back > 0) note("load: the sender waited " + std::to_string(held_back) + " times with 200 lines unanswered");

  const std::string cond = " (" + std::to_string(idle) + " idle clients, " + std::to_string(static_cast<long>(rate)) + " lines/s asked, " +
                           std::to_string(static_cast<long>(seconds)) + " s)";
  r.add({"load.sent_per_s", "lines sent a second", "command lines the sender sent / duration" + cond + "; reference: none (a generator)",
         static_cast<double>(sent) / wall, "1/s", "", std::nullopt, std::nullopt});
  r.add({"load.answered_per_s", "replies read a second", "Ok/Err replies the sender read / duration" + cond, static_cast<double>(answered) / wall,
         "1/s", "", std::nullopt, std::nullopt});
  r.add({"load.refused", "lines refused (Err)", "replies that were Err" + cond, static_cast<double>(refused), "lines", "", std::nullopt,
         std::nullopt});
  r.add({"load.clients_open", "clients still connected at the end", "clients (idle and the sender) still connected at the end" + cond,
         static_cast<double>(still_open), "clients", "", std::nullopt, std::nullopt});
  LatencySet replies{"load.reply", "reply time under load", "a command line sent -> its reply read, under the load itself" + cond,
                     std::move(reply_ms)};
  add_latency(r, replies, nullptr, std::nullopt, std::nullopt);
}

}  // namespace imess::bench
