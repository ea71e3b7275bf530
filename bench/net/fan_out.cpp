// Sending one line and waiting for its copy at every client; the stamped variant for the
// timer of bench_echo.
#include "fan_out.hpp"

#include <charconv>
#include <map>
#include <stdexcept>

#include "clock.hpp"
#include "requests.hpp"

namespace imess::bench {

std::vector<double> fan_out(Context& ctx, ClientPool& pool, const FanOutRun& run) {
  std::vector<std::uint32_t> got(static_cast<std::size_t>(pool.size()), 0);  // the round a client last got the line in
  std::uint32_t round = 0;
  int open = 0;
  for (int c = 0; c < pool.size(); ++c) open += pool.is_open(c) ? 1 : 0;
  int remaining = 0;
  std::int64_t last = 0;
  bool replied = true;
  std::string reply;
  pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
    if (starts_with(l, run.prefix) && got[static_cast<std::size_t>(c)] != round) {
      got[static_cast<std::size_t>(c)] = round;
      --remaining;
      last = std::max(last, t);
    }
    if (c == run.sender && !replied && (starts_with(l, "Ok ") || starts_with(l, "Err "))) {
      replied = true;
      reply.assign(l);
    }
  };
  std::vector<double> ms;
  ms.reserve(static_cast<std::size_t>(run.samples));
  for (int i = -run.warmup; i < run.samples; ++i) {
    ctx.random_phase();
    pool.poll(0);  // anything that came meanwhile is not this sample's
    ++round;
    remaining = open;
    last = 0;
    replied = run.sender_reply.empty();
    reply.clear();
    const std::int64_t t0 = mono_ns();
    pool.send(run.sender, run.line);
    if (!pool.run_until([&] { return remaining == 0 && replied; }, 5.0))
      throw std::runtime_error("'" + run.line + "': " + std::to_string(remaining) + " of " + std::to_string(open) + " clients got no '" +
                               std::string(run.prefix) + "' within 5 s" + (replied ? "" : " and the sender no reply"));
    if (!run.sender_reply.empty() && !starts_with(reply, run.sender_reply))
      throw std::runtime_error("'" + run.line + "' was answered '" + reply + "'");
    if (i >= 0) ms.push_back(ns_to_ms(last - t0));
  }
  pool.on_line = nullptr;
  return ms;
}

std::vector<double> stamped_fan_out(ClientPool& pool, int samples, double timeout_s) {
  int open = 0;
  for (int c = 0; c < pool.size(); ++c) open += pool.is_open(c) ? 1 : 0;
  struct Tick {
    int count = 0;
    std::int64_t last = 0;
  };
  std::map<std::int64_t, Tick> ticks;  // by stamp, µs
  std::vector<double> ms;
  int skip = 2;  // the first ticks may have reached only part of the clients as they came in
  pool.on_line = [&](int, std::string_view l, std::int64_t t) {
    const auto stamp = word(l, 1);
    const auto dot = stamp.find('.');
    if (!starts_with(l, "CurrCor ") || dot == std::string_view::npos) return;
    long long sec = 0, usec = 0;
    std::from_chars(stamp.data(), stamp.data() + dot, sec);
    std::from_chars(stamp.data() + dot + 1, stamp.data() + stamp.size(), usec);
    const std::int64_t key = sec * 1'000'000 + usec;
    Tick& k = ticks[key];
    ++k.count;
    k.last = std::max(k.last, t);
    if (k.count < open) return;
    if (skip > 0) --skip;
    else if (static_cast<int>(ms.size()) < samples) ms.push_back(ns_to_ms(k.last - key * 1000));
    ticks.erase(ticks.begin(), ticks.upper_bound(key));  // older ticks that never completed are dropped with it
  };
  pool.run_until([&] { return static_cast<int>(ms.size()) >= samples; }, timeout_s);
  pool.on_line = nullptr;
  return ms;
}

}  // namespace imess::bench
