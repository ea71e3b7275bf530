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
    bool fault = false;
    auto previous = pool.on_line;
    pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
      if (previous) previous(c, l, t);
      if (c == owner && (starts_with(l, "Fault ") || starts_with(l, "Failed "))) {
        fault = true;
        why.assign(l);
      }
    };
    bool idle = false;
    try {
      idle = request_until(pool, owner, "MoveTo " + std::to_string(id) + " " + words, "State idle");
    } catch (const std::runtime_error& e) {
      why = e.what();
    }
    pool.on_line = previous;
    if (idle && !fault) return faults;
    if (!idle && why.empty()) why = "no State idle within 10 s (last line: " + pool.last_line(owner) + ")";
    ++faults;
    pool.run_for(0.2);
    reset_fault(pool, owner);
  }
  throw std::runtime_error("MoveTo " + words + " did not end at rest in three tries; last: " + why + kFaultHint);
}

}  // namespace imess::bench
