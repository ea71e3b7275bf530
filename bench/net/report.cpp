// Figure lines on stdout and the contract's JSON file.
#include "report.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "stats.hpp"

namespace imess::bench {

namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// Three significant digits at least, more when the integer part needs them (1234.5 ms).
std::string shown(double v) {
  char buf[32];
  if (v == std::floor(v) && std::fabs(v) < 1e9)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else if (v >= 1000 || v <= -1000)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else if (v >= 100 || v <= -100)
    std::snprintf(buf, sizeof buf, "%.1f", v);
  else if (v >= 1 || v <= -1)
    std::snprintf(buf, sizeof buf, "%.2f", v);
  else
    std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

nlohmann::json optional_number(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }
}  // namespace

std::string Goal::text() const {
  return std::string(at_most ? "<= " : ">= ") + number(limit) + " " + unit + (note.empty() ? "" : " (" + note + ")");
}

void note(const std::string& text) { std::fprintf(stderr, "bench_net: %s\n", text.c_str()); }

void Report::add(Figure f) {
  std::string line;
  char head[256];
  const std::string& label = f.label.empty() ? f.what : f.label;
  std::snprintf(head, sizeof head, "%-28s %-56s ", f.id.c_str(), label.substr(0, 56).c_str());
  line = head;
  if (f.value) {
    char v[64];
    std::snprintf(v, sizeof v, "%9s %-5s", shown(*f.value).c_str(), f.unit.c_str());
    line += v;
    const bool floor = f.reference_id.rfind("floor.", 0) == 0;
    if (f.reference && *f.reference != 0) {
      char r[96];
      std::snprintf(r, sizeof r, "   %s %9s %-5s x%-6.2f", floor ? "floor" : "ref  ", shown(*f.reference).c_str(), f.unit.c_str(),
                    *f.value / *f.reference);
      line += r;
    } else {
      line += "   ref          -                ";
    }
    if (f.goal) line += "   goal " + f.goal->text() + (f.goal->met(*f.value) ? "   met" : "   NOT met");
  } else {
    line += "unavailable";
  }
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
  figures_.push_back(std::move(f));
}

void Report::add_distribution(std::string id, std::string what, std::string unit, const std::vector<double>& samples,
                              std::string reference_id) {
  distributions_.push_back({std::move(id), std::move(what), std::move(unit), thinned(samples), std::move(reference_id)});
}

void Report::add_curve(Curve c) { curves_.push_back(std::move(c)); }

std::optional<double> Report::value(const std::string& id) const {
  for (const auto& f : figures_)
    if (f.id == id) return f.value;
  return std::nullopt;
}

bool Report::measured() const {
  for (const auto& f : figures_)
    if (f.value) return true;
  return false;
}

void Report::write_json(const std::string& path) const {
  nlohmann::json figures = nlohmann::json::array();
  for (const auto& f : figures_) {
    nlohmann::json j;
    j["id"] = f.id;
    j["what"] = f.what;
    j["value"] = optional_number(f.value);
    j["unit"] = f.unit;
    j["reference_id"] = f.reference_id.empty() ? nlohmann::json(nullptr) : nlohmann::json(f.reference_id);
    j["reference"] = optional_number(f.reference);
    j["ratio"] = f.value && f.reference && *f.reference != 0 ? nlohmann::json(*f.value / *f.reference) : nlohmann::json(nullptr);
    j["goal"] = f.goal ? nlohmann::json(f.goal->text()) : nlohmann::json(nullptr);
    j["met"] = f.goal && f.value ? nlohmann::json(f.goal->met(*f.value)) : nlohmann::json(nullptr);
    j["virtual_time"] = false;
    figures.push_back(std::move(j));
  }
  nlohmann::json distributions = nlohmann::json::array();
  for (const auto& d : distributions_) {
    nlohmann::json j = {{"id", d.id}, {"what", d.what}, {"unit", d.unit}, {"samples", d.samples}};
    if (!d.reference_id.empty()) j["reference_id"] = d.reference_id;
    distributions.push_back(std::move(j));
  }
  nlohmann::json curves = nlohmann::json::array();
  for (const auto& c : curves_) {
    nlohmann::json series = nlohmann::json::object();
    for (const auto& [name, points] : c.series) {
      nlohmann::json pts = nlohmann::json::array();
      for (const auto& [x, y] : points) pts.push_back({x, y});
      series[name] = std::move(pts);
    }
    curves.push_back({{"id", c.id}, {"what", c.what}, {"x", c.x}, {"y", c.y}, {"series", std::move(series)}});
  }
  nlohmann::json out = {{"bench", "net"}, {"quick", quick_}, {"figures", std::move(figures)},
                        {"distributions", std::move(distributions)}, {"curves", std::move(curves)}};
  std::ofstream file(path);
  if (!file) throw std::runtime_error("cannot write the JSON results to '" + path + "'");
  file << out.dump(1) << "\n";
  if (!file) throw std::runtime_error("writing the JSON results to '" + path + "' failed");
}

}  // namespace imess::bench
