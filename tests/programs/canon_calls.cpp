// Reading canonical calls back: a regex per call, the canon's units and feed kept as it runs.
#include "canon_calls.hpp"

#include <array>
#include <cmath>
#include <regex>
#include <sstream>

namespace imess::programs::test {

std::vector<Motion> motions(const std::string& text) {
  static const std::regex call(
      R"((USE_LENGTH_UNITS|SET_FEED_RATE|SELECT_PLANE|STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED|STRAIGHT_PROBE|DWELL)\(([^)]*)\))");
  static const std::regex number(R"([-+]?[0-9]+(\.[0-9]+)?)");
  std::vector<Motion> out;
  bool inches = false;
  double feed_mm = 0;
  int first = 0, second = 1, normal = 2;  // the plane's axes among X Y Z
  std::array<double, 3> pos{};            // mm; NaN: not known
  for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1], args = (*it)[2];
    Motion m{name, {}, 0};
    for (auto n = std::sregex_iterator(args.begin(), args.end(), number); n != std::sregex_iterator(); ++n)
      m.args.push_back(std::stod((*n)[0]));
    const double unit = inches ? 25.4 : 1.0;
    if (name == "USE_LENGTH_UNITS") {
      inches = args.find("INCHES") != std::string::npos;
    } else if (name == "SET_FEED_RATE") {
      feed_mm = m.args.empty() ? 0 : m.args[0] * unit;
    } else if (name == "SELECT_PLANE") {
      if (args.find("XZ") != std::string::npos) first = 2, second = 0, normal = 1;
      else if (args.find("YZ") != std::string::npos) first = 1, second = 2, normal = 0;
      else first = 0, second = 1, normal = 2;
    } else if (name == "DWELL") {
      out.push_back(m);
    } else if (name == "ARC_FEED") {
      for (std::size_t k : {0, 1, 2, 3, 5})
        if (k < m.args.size()) m.args[k] *= unit;
      if (m.args.size() >= 6) pos[first] = m.args[0], pos[second] = m.args[1], pos[normal] = m.args[5];
      m.feed_mm = feed_mm;
      m.tolerance = 0.00015 * unit;
      out.push_back(m);
    } else if (m.args.size() >= 3) {
      for (std::size_t k = 0; k < 3; ++k) m.args[k] *= unit;
      m.tolerance = 0.00015 * unit;
      const std::array<double, 3> to{m.args[0], m.args[1], m.args[2]};
      bool same = name != "STRAIGHT_PROBE";
      for (int k = 0; k < 3; ++k) same = same && std::fabs(to[k] - pos[k]) < 1e-9;
      for (std::size_t k = 3; k < m.args.size(); ++k) same = same && m.args[k] == 0;  // A B C at 0 only
      pos = to;
      if (same) continue;  // LinuxCNC prints G0/G1 without axis words and G28's via point
      if (name != "STRAIGHT_TRAVERSE") m.feed_mm = feed_mm;
      out.push_back(m);
    }
  }
  return out;
}

std::string difference(const std::vector<Motion>& ours, const std::vector<Motion>& theirs) {
  auto text = [](const Motion& m) {
    std::ostringstream s;
    s << m.name << "(";
    for (std::size_t k = 0; k < m.args.size(); ++k) s << (k ? ", " : "") << m.args[k];
    s << ")";
    if (m.name != "STRAIGHT_TRAVERSE" && m.name != "DWELL") s << " at " << m.feed_mm << " mm/min";
    return s.str();
  };
  const std::size_t n = std::min(ours.size(), theirs.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Motion &a = ours[i], &b = theirs[i];
    // Feeds printed with 4 decimals in inches come back 0.0025 mm/min off at most.
    bool same = a.name == b.name && a.args.size() == b.args.size() &&
                std::fabs(a.feed_mm - b.feed_mm) <= 0.003 + 1e-6 * std::fabs(b.feed_mm);
    const double tol = std::max(a.tolerance, b.tolerance);
    for (std::size_t k = 0; same && k < a.args.size(); ++k) same = std::fabs(a.args[k] - b.args[k]) <= tol;
    if (!same) return "motion " + std::to_string(i + 1) + ": ours " + text(a) + ", LinuxCNC's " + text(b);
  }
  if (ours.size() != theirs.size())
    return std::to_string(ours.size()) + " motions against LinuxCNC's " + std::to_string(theirs.size()) +
           (ours.size() > n ? ", ours goes on with " + text(ours[n]) : ", LinuxCNC's goes on with " + text(theirs[n]));
  return "";
}

}  // namespace imess::programs::test
