// Report: the figures, distributions and set-up of one bench_rt run, printed one line per
// figure as they come and written as the benchmarks' shared JSON (/work/notes contract:
// {bench, quick, figures, distributions, curves}, plus "setup": how the run was made).
#pragma once
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace imess::bench {

struct Figure {
  std::string id, what, unit;
  std::optional<double> value;        // none: unavailable, `unavailable` says why
  std::string unavailable;
  std::string reference_id;           // the floor figure it is compared with ("" none)
  std::optional<double> reference;
  std::optional<double> goal_ratio;   // goal: value <= goal_ratio × reference
  bool virtual_time = false;
  int decimals = 1;
  std::optional<double> ratio() const;
  std::optional<bool> met() const;
};

// A figure without reference or goal.
Figure plain_figure(std::string id, std::string what, std::string unit, double value, int decimals = 1);

class Report {
 public:
  Report(std::string bench, bool quick);
  void add(Figure f);  // prints it
  // reference_id: the distribution drawn beside this one in its plot ("" none).
  void add_distribution(const std::string& id, const std::string& what, const std::string& unit,
                        std::vector<double> samples, const std::string& reference_id = "");
  void note(const std::string& text);  // a "# ..." line on stdout, kept in setup.notes
  nlohmann::ordered_json& setup() { return setup_; }
  const std::vector<Figure>& figures() const { return figures_; }
  // Writes the JSON; false (and a message on stderr) when the file cannot be written.
  bool write(const std::string& path) const;

 private:
  std::string bench_;
  bool quick_;
  std::vector<Figure> figures_;
  nlohmann::ordered_json distributions_ = nlohmann::ordered_json::array();
  nlohmann::ordered_json setup_ = nlohmann::ordered_json::object();
};

}  // namespace imess::bench
