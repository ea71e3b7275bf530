// What the seeded property tests over the golden harness share (test_program_properties.cpp,
// test_ippdme_properties.cpp): a random source that gives the same script on every standard
// library, the seeds (fixed, or IMESS_PROPERTY_SEEDS to explore), MESSD reply reading, and the
// transcript of a failing seed with its steps numbered as the failure messages count them.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "golden_files.hpp"
#include "transcript.hpp"

namespace imess::golden {

// mt19937_64's output is fixed by the standard (its distributions are not): the same seed
// gives the same script with every standard library.
class Random {
 public:
  explicit Random(std::uint64_t seed) : rng_(seed) {}
  int pick(int lo, int hi) { return lo + static_cast<int>(rng_() % static_cast<std::uint64_t>(hi - lo + 1)); }
  double real(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng_() >> 11) * 0x1.0p-53; }
  bool chance(double p) { return real(0, 1) < p; }
  // A value rounded to 3 decimals, as written in a program or a command.
  double coord(double lo, double hi) { return std::round(real(lo, hi) * 1000) / 1000; }

 private:
  std::mt19937_64 rng_;
};

inline std::string num(double v, int decimals = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

inline std::string zero_padded(int n, int width) {  // 42, 5 -> "00042"
  char buf[32];
  std::snprintf(buf, sizeof buf, "%0*d", width, n);
  return buf;
}

inline std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  return w;
}

inline bool starts(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// "Ok Status State idle Pos 1 2 3 … Control name@host" (docs/protocol.md, Status).
struct StatusReply {
  std::string state;
  std::vector<double> pos;
  std::string control;  // "none", "name@host"; empty when the line has no Control word
};

inline std::optional<StatusReply> parse_status(const std::string& line) {
  const auto w = words(line);
  if (w.size() < 5 || w[0] != "Ok" || w[1] != "Status" || w[2] != "State" || w[4] != "Pos") return std::nullopt;
  StatusReply r{w[3], {}, {}};
  std::size_t i = 5;
  for (; i < w.size(); ++i) {
    char* end = nullptr;
    const double v = std::strtod(w[i].c_str(), &end);
    if (end == w[i].c_str() || *end) break;
    r.pos.push_back(v);
  }
  for (; i + 1 < w.size(); ++i)
    if (w[i] == "Control") r.control = w[i + 1];
  return r;
}

// IMESS_PROPERTY_SEEDS="1 2 99" replaces a test's fixed seeds.
inline std::vector<std::uint64_t> property_seeds(std::vector<std::uint64_t> fixed) {
  if (const char* env = std::getenv("IMESS_PROPERTY_SEEDS")) {
    std::vector<std::uint64_t> out;
    std::istringstream in(env);
    for (std::uint64_t s; in >> s;) out.push_back(s);
    if (!out.empty()) return out;
  }
  return fixed;
}

// The generator's seed: the test's seed and the configuration (the machines of the same
// axes get different sessions for the same seed).
inline std::uint64_t mixed_seed(std::uint64_t seed, const std::string& config) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (unsigned char ch : config) h = (h ^ ch) * 1099511628211ull;
  return seed * 0x9E3779B97F4A7C15ull ^ h;
}

// The transcript with "# step N" before each step (the numbers the failure messages use).
inline std::string numbered(const std::vector<Entry>& out) {
  std::vector<Entry> n;
  int step = -1;
  for (const auto& e : out) {
    if (e.kind != EntryKind::Comment && !observed(e) && !(e.kind == EntryKind::Send && e.joined))
      n.push_back({EntryKind::Comment, 1, "# step " + std::to_string(++step)});
    n.push_back(e);
  }
  return format_transcript(n);
}

}  // namespace imess::golden
