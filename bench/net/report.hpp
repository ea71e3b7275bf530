// The results of one bench_net run: figures (printed one line each as they are made),
// distributions of raw samples and curves for plots; written as the JSON of the benchmark
// contract (bench/README-style: /docs/performance.md, "Network figures").
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace imess::bench {

// A goal of the issue: value <= limit (at_most) or value >= limit.
struct Goal {
  bool at_most = true;
  double limit = 0;
  std::string unit;
  std::string note;  // how the limit was made, e.g. "1.2 x floor"
  std::string text() const;
  bool met(double value) const { return at_most ? value <= limit : value >= limit; }
};

struct Figure {
  std::string id;
  std::string label;  // the printed description, short (JSON: what)
  std::string what;   // the whole description: from where to where, the conditions
  std::optional<double> value;  // nullopt: unavailable (what says why)
  std::string unit;
  std::string reference_id;           // empty: no reference (what says why)
  std::optional<double> reference;
  std::optional<Goal> goal;
};

struct Curve {
  std::string id, what, x, y;
  std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> series;
};

class Report {
 public:
  explicit Report(bool quick) : quick_(quick) {}
  // Prints the figure's line on stdout at once and keeps it.
  void add(Figure f);
  // reference_id: the distribution drawn beside it (bench/report.py overlays them), empty: none.
  void add_distribution(std::string id, std::string what, std::string unit, const std::vector<double>& samples,
                        std::string reference_id = {});
  void add_curve(Curve c);
  // The value of a figure already added (nullopt: none, or unavailable).
  std::optional<double> value(const std::string& id) const;
  bool empty() const { return figures_.empty(); }
  // Whether any figure has a value.
  bool measured() const;
  // Throws std::runtime_error naming the file when it cannot be written.
  void write_json(const std::string& path) const;

 private:
  struct Distribution {
    std::string id, what, unit;
    std::vector<double> samples;
    std::string reference_id;
  };
  bool quick_;
  std::vector<Figure> figures_;
  std::vector<Distribution> distributions_;
  std::vector<Curve> curves_;
};

// Prints a line of context (what was started, the load, a reversal) on stderr, so stdout
// holds only the figure lines.
void note(const std::string& text);

}  // namespace imess::bench
