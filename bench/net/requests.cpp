// Request/reply over the pool, and the small word helpers the figures parse lines with.
#include "requests.hpp"

#include <stdexcept>

#include "clock.hpp"

namespace imess::bench {

bool starts_with(std::string_view line, std::string_view prefix) { return line.substr(0, prefix.size()) == prefix; }

std::string_view word(std::string_view line, int n) {
  std::size_t pos = 0;
  for (int i = 0;; ++i) {
    while (pos < line.size() && line[pos] == ' ') ++pos;
    if (pos >= line.size()) return {};
    std::size_t end = line.find(' ', pos);
    if (end == std::string_view::npos) end = line.size();
    if (i == n) return line.substr(pos, end - pos);
    pos = end;
  }
}

std::string_view value_after(std::string_view line, std::string_view name) {
  for (int i = 0;; ++i) {
    auto w = word(line, i);
    if (w.empty()) return {};
    if (w == name) return word(line, i + 1);
  }
}

std::optional<Reply> request(ClientPool& pool, int client, const std::string& line, double timeout_s) {
  auto previous = pool.on_line;
  std::optional<Reply> reply;
  Reply r;
  pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
    if (previous) previous(c, l, t);
    if (c == client && !reply && (starts_with(l, "Ok ") || l == "Ok" || starts_with(l, "Err "))) {
      r.line.assign(l);
      r.arrived_ns = t;
      reply = r;
    }
  };
  r.sent_ns = mono_ns();
  pool.send(client, line);
  pool.run_until([&] { return reply.has_value() || !pool.is_open(client); }, timeout_s);
  pool.on_line = previous;
  return reply;
}

Reply request_ok(ClientPool& pool, int client, const std::string& line, double timeout_s) {
  auto r = request(pool, client, line, timeout_s);
  if (!r)
    throw std::runtime_error("'" + line + "' got no reply within " + std::to_string(timeout_s) + " s" +
                             (pool.is_open(client) ? std::string() : " (connection closed: " + pool.close_reason(client) + ")"));
  if (!r->ok()) throw std::runtime_error("'" + line + "' was refused: " + r->line);
  return *r;
}

bool request_until(ClientPool& pool, int client, const std::string& line, std::string_view until, double timeout_s) {
  auto previous = pool.on_line;
  std::string refused;
  bool seen = false;
  pool.on_line = [&](int c, std::string_view l, std::int64_t t) {
    if (previous) previous(c, l, t);
    if (c != client) return;
    if (starts_with(l, "Err ") && refused.empty()) refused.assign(l);
    if (starts_with(l, until)) seen = true;
  };
  pool.send(client, line);
  pool.run_until([&] { return seen || !refused.empty() || !pool.is_open(client); }, timeout_s);
  pool.on_line = previous;
  if (!refused.empty()) throw std::runtime_error("'" + line + "' was refused: " + refused);
  return seen;
}

}  // namespace imess::bench
