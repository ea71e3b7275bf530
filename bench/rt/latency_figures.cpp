// p50, p99, p99.9, max and overruns, measured against the floor.
#include "latency_figures.hpp"

#include <algorithm>

namespace imess::bench {

namespace {
struct Stat {
  const char* key;
  const char* name;
  double p;  // < 0: max; > 1: overruns
  double goal;
};
constexpr Stat kStats[] = {{"p50", "p50", 0.5, 0},      {"p99", "p99", 0.99, 1.2}, {"p999", "p99.9", 0.999, 1.5},
                           {"max", "max", -1, 0},       {"overruns", "overruns", 2, 0}};

std::optional<double> value_of(const LatencySide& s, const Stat& st) {
  if (!s.histogram) return std::nullopt;
  if (st.p > 1) return static_cast<double>(s.overruns);
  if (st.p < 0) return s.histogram->max();
  return s.histogram->percentile(st.p);
}

Figure figure(const LatencySide& s, const Stat& st, const std::string& condition) {
  Figure f;
  f.id = s.id + "." + st.key;
  const bool overruns = st.p > 1;
  f.what = s.subject + (overruns ? " overruns, " : " wake-up latency " + std::string(st.name) + ", ") + condition;
  f.unit = overruns ? "n" : "us";
  f.decimals = overruns ? 0 : 1;
  f.value = value_of(s, st);
  f.unavailable = s.unavailable;
  return f;
}

std::vector<double> subsample_sorted(std::vector<double> v, std::size_t limit) {
  std::sort(v.begin(), v.end());
  if (v.size() <= limit) return v;
  std::vector<double> out;
  out.reserve(limit);
  for (std::size_t i = 0; i < limit; ++i) out.push_back(v[i * (v.size() - 1) / (limit - 1)]);
  return out;
}

void add_distribution(Report& report, const LatencySide& s, const std::string& condition, const LatencySide* reference) {
  if (!s.histogram) return;
  const bool raw = !s.raw_samples_us.empty();
  report.add_distribution(s.id, s.subject + " wake-up latency, " + condition +
                                    (raw ? " (raw samples at evenly spaced ranks)"
                                         : " (1 us buckets, bucket middles at evenly spaced ranks)"),
                          "us", raw ? subsample_sorted(s.raw_samples_us, 20000) : s.histogram->plot_samples(20000),
                          reference && reference->histogram ? reference->id : "");
}
}  // namespace

void add_latency_figures(Report& report, const LatencySide& measured, const LatencySide& floor,
                         const std::string& condition, bool goals) {
  for (const auto& st : kStats) {
    Figure f = figure(measured, st, condition);
    f.reference_id = floor.id + "." + st.key;
    f.reference = value_of(floor, st);
    if (goals && st.goal > 0) f.goal_ratio = st.goal;
    report.add(std::move(f));
  }
  for (const auto& st : kStats) report.add(figure(floor, st, condition));
  add_distribution(report, measured, condition, &floor);  // plotted with the floor beside it
  add_distribution(report, floor, condition, nullptr);
}

}  // namespace imess::bench
