// One line per figure on stdout, the shared JSON layout in the file.
#include "report.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace imess::bench {

std::optional<double> Figure::ratio() const {
  if (!value || !reference || !(*reference > 0)) return std::nullopt;
  return *value / *reference;
}

std::optional<bool> Figure::met() const {
  auto r = ratio();
  if (!goal_ratio || !r) return std::nullopt;
  return *r <= *goal_ratio;
}

Figure plain_figure(std::string id, std::string what, std::string unit, double value, int decimals) {
  Figure f;
  f.id = std::move(id);
  f.what = std::move(what);
  f.unit = std::move(unit);
  f.value = value;
  f.decimals = decimals;
  return f;
}

namespace {
std::string number(std::optional<double> v, int decimals) {
  if (!v) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, *v);
  return buf;
}
std::string goal_text(const Figure& f) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "<= %gx floor", *f.goal_ratio);
  return buf;
}
// JSON numbers: rounded to what the figure means, null when absent.
nlohmann::ordered_json json_number(std::optional<double> v, int decimals) {
  if (!v || !std::isfinite(*v)) return nullptr;
  const double scale = std::pow(10.0, decimals);
  return std::round(*v * scale) / scale;
}
}  // namespace

Report::Report(std::string bench, bool quick) : bench_(std::move(bench)), quick_(quick) {}

void Report::add(Figure f) {
  std::string line;
  char head[200];
  std::snprintf(head, sizeof head, "%-26s %-58s", f.id.c_str(), f.what.substr(0, 58).c_str());
  line = head;
  if (!f.value) {
    line += "   unavailable: " + f.unavailable;
  } else {
    char body[200];
    std::snprintf(body, sizeof body, " %9s %-8s", number(f.value, f.decimals).c_str(), f.unit.c_str());
    line += body;
    if (!f.reference_id.empty()) {
      std::snprintf(body, sizeof body, " floor %9s %-3s x%-6s", number(f.reference, f.decimals).c_str(),
                    f.unit.c_str(), number(f.ratio(), 2).c_str());
      line += body;
    }
    if (f.goal_ratio) line += "  goal " + goal_text(f) + (f.met() ? (*f.met() ? "  met" : "  NOT met") : "  (no floor)");
    if (f.virtual_time) line += "  (virtual time)";
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
  figures_.push_back(std::move(f));
}

void Report::add_distribution(const std::string& id, const std::string& what, const std::string& unit,
                              std::vector<double> samples, const std::string& reference_id) {
  nlohmann::ordered_json d;
  d["id"] = id;
  d["what"] = what;
  d["unit"] = unit;
  if (!reference_id.empty()) d["reference_id"] = reference_id;
  for (auto& s : samples) s = std::round(s * 1000) / 1000;
  d["samples"] = std::move(samples);
  distributions_.push_back(std::move(d));
}

void Report::note(const std::string& text) {
  std::printf("# %s\n", text.c_str());
  std::fflush(stdout);
  setup_["notes"].push_back(text);
}

bool Report::write(const std::string& path) const {
  nlohmann::ordered_json j;
  j["bench"] = bench_;
  j["quick"] = quick_;
  j["setup"] = setup_;
  auto& figs = j["figures"] = nlohmann::ordered_json::array();
  for (const auto& f : figures_) {
    nlohmann::ordered_json o;
    o["id"] = f.id;
    o["what"] = f.what;
    o["value"] = json_number(f.value, f.decimals + 2);
    if (!f.value) o["unavailable"] = f.unavailable;
    o["unit"] = f.unit;
    o["reference_id"] = f.reference_id.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(f.reference_id);
    o["reference"] = json_number(f.reference, f.decimals + 2);
    o["ratio"] = json_number(f.ratio(), 3);
    if (f.goal_ratio) {
      o["goal"] = goal_text(f);
      o["met"] = f.met() ? nlohmann::ordered_json(*f.met()) : nlohmann::ordered_json(nullptr);
    }
    o["virtual_time"] = f.virtual_time;
    figs.push_back(std::move(o));
  }
  j["distributions"] = distributions_;
  j["curves"] = nlohmann::ordered_json::array();
  std::ofstream out(path);
  if (!out) {
    std::fprintf(stderr, "bench_rt: cannot write %s\n", path.c_str());
    return false;
  }
  out << j.dump(1) << "\n";
  return static_cast<bool>(out);
}

}  // namespace imess::bench
