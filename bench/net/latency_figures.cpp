// p50/p99 figures and the raw-sample distribution of one latency set.
#include "figures.hpp"
#include "stats.hpp"

namespace imess::bench {

void add_latency(Report& r, const LatencySet& set, const LatencySet* reference, std::optional<Goal> p50_goal,
                 std::optional<Goal> p99_goal) {
  const std::string count = " (" + std::to_string(set.ms.size()) + " samples)";
  for (auto [p, name, goal] : {std::tuple{0.5, "p50", p50_goal}, std::tuple{0.99, "p99", p99_goal}}) {
    Figure f;
    f.id = set.id + "." + name;
    f.label = set.label + ", " + name;
    f.what = set.what + ", " + name + count;
    f.unit = "ms";
    if (!set.ms.empty()) f.value = percentile(set.ms, p);
    else f.what += "; unavailable: no sample was taken";
    if (reference && !reference->ms.empty()) {
      f.reference_id = reference->id + "." + name;
      f.reference = percentile(reference->ms, p);
    }
    f.goal = goal;
    r.add(std::move(f));
  }
  r.add_distribution(set.id, set.what + count, "ms", set.ms, reference && !reference->ms.empty() ? reference->id : std::string());
}

}  // namespace imess::bench
