// Fan-out latency: one client sends a line, every client of the pool must receive a line
// with a given prefix; a sample is the time from just before the send() to the read() that
// brought it to the last client.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "client_pool.hpp"
#include "context.hpp"

namespace imess::bench {

struct FanOutRun {
  int sender = 0;
  std::string line;              // what the sender sends
  std::string_view prefix;       // what every client must receive
  std::string_view sender_reply; // a reply the sender must also get (messd's "Ok ForcePt"), empty: none
  int samples = 0;
  int warmup = 2;  // samples taken first and not kept
};

// Latencies in ms, one per sample. Throws std::runtime_error when a sample does not complete
// within 5 s or the reply is not Ok.
std::vector<double> fan_out(Context& ctx, ClientPool& pool, const FanOutRun& run);

// Timestamped fan-out from bench_echo's timer: the time from the CLOCK_MONOTONIC stamp in
// each "CurrCor <t> …" line to its arrival at the last of the pool's clients; `samples` ticks.
std::vector<double> stamped_fan_out(ClientPool& pool, int samples, double timeout_s);

}  // namespace imess::bench
