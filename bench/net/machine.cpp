// Moving to rest with Reset and retries.
#include "machine.hpp"

#include <stdexcept>

#include "requests.hpp"

namespace imess::bench {

void reset_fault(ClientPool& pool, int owner) { request(pool, owner, "Reset"); }

int move_to_rest(ClientPool& pool, int owner, std::uint32_t id, const std::string& words) {
  int faults = 0;
  std::string why;
  for (int attempt = 0; attempt < 3; ++attempt) {
    bool idle = false;
    std::string failed;
    auto previous = pool.on_line;
    pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
      if (previous) previous(c, l, t);
      if (c != owner) return;
      if (starts_with(l, "State idle")) idle = true;
      if (failed.empty() && (starts_with(l, "Fault ") || starts_with(l, "Failed ") || starts_with(l, "Err "))) failed.assign(l);
    };
    pool.send(owner, "MoveTo " + std::to_string(id) + " " + words);
    pool.run_until([&] { return idle || !failed.empty() || !pool.is_open(owner); }, 10.0);
    pool.on_line = previous;
    if (idle && failed.empty()) return faults;
    why = !failed.empty() ? failed : "no State idle within 10 s (last line: " + pool.last_line(owner) + ")";
    ++faults;
    pool.run_for(0.2);
    reset_fault(pool, owner);
    // A fault while the ball pressed on the part leaves the loops open and the tip deflected
    // (TipTouched): lift the carriage by hand, as an operator would (the simulator's HandMv).
    if (why.find("TipTouched") != std::string::npos || why.find("Err 200") != std::string::npos) {
      request(pool, owner, "HandMv 0 0 3 20");
      pool.run_for(0.4);
    }
  }
  throw std::runtime_error("MoveTo " + words + " did not end at rest in three tries; last: " + why + kFaultHint);
}

}  // namespace imess::bench
