// Reader of labelled measured points: text lines `FEATURE x y z [i j k r]` or the "points" of
// messcap inspect's JSON report.
#include "imess/metrology/inspection_points.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"

namespace imess::metrology {
namespace {

[[noreturn]] void fail_line(std::string_view source, std::size_t line, const std::string& why) {
  throw MeasuredPointsError(std::string(source) + ":" + std::to_string(line) + ": " + why);
}

bool to_double(std::string_view word, double& out) {
  const char* end = word.data() + word.size();
  auto [ptr, ec] = std::from_chars(word.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

// Approach (i j k) and radius r: a hit; a zero approach with r 0: a plain point.
void set_probe(MeasuredPoint& p, const Eigen::Vector3d& approach, double radius, const auto& fail) {
  if (radius < 0) fail("the tip radius r must be 0 or more");
  if (approach.norm() == 0.0) {
    if (radius != 0) fail("a point with tip radius " + std::to_string(radius) + " needs an approach direction i j k");
    return;
  }
  p.approach = approach.normalized();
  p.radius = radius;
}

std::vector<MeasuredPoint> parse_text(std::string_view text, std::string_view source) {
  std::vector<MeasuredPoint> out;
  std::size_t line_no = 0;
  while (!text.empty()) {
    ++line_no;
    const auto nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    const auto words = words_of(line);
    if (words.empty()) continue;
    if (words.size() != 4 && words.size() != 8)
      fail_line(source, line_no,
                "expected FEATURE x y z (a surface point) or FEATURE x y z i j k r (a hit: point, approach, tip radius), got " +
                    std::to_string(words.size()) + " words");
    MeasuredPoint p;
    p.feature = std::string(words[0]);
    double v[7] = {};
    for (std::size_t k = 1; k < words.size(); ++k)
      if (!to_double(words[k], v[k - 1]))
        fail_line(source, line_no, "'" + std::string(words[k]) + "' (word " + std::to_string(k + 1) + ") is not a finite number");
    p.point = {v[0], v[1], v[2]};
    if (words.size() == 8)
      set_probe(p, Eigen::Vector3d(v[3], v[4], v[5]), v[6], [&](const std::string& why) { fail_line(source, line_no, why); });
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<MeasuredPoint> parse_json(std::string_view text, std::string_view source) {
  using nlohmann::json;
  const std::string src(source);
  json doc;
  try {
    doc = imess::jsontext::parse_strict(text, source);
  } catch (const imess::jsontext::JsonTextError& e) {
    throw MeasuredPointsError(e.what());
  }
  auto fail = [&](const std::string& path, const std::string& why) -> void {
    throw MeasuredPointsError(src + ": " + path + ": " + why);
  };
  auto number = [&](const json& v, const std::string& path) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(path, "expected a finite number");
    return v.get<double>();
  };
  auto vec = [&](const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 3) fail(path, "expected [x, y, z]");
    return Eigen::Vector3d(number(v[0], path + "[0]"), number(v[1], path + "[1]"), number(v[2], path + "[2]"));
  };
  if (!doc.is_object() || !doc.contains("points") || !doc["points"].is_array())
    fail("points", "expected an array of {\"feature\", \"machine\", \"approach\", \"radius\"} (what messcap inspect --json writes)");
  std::vector<MeasuredPoint> out;
  const json& pts = doc["points"];
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::string path = "points[" + std::to_string(i) + "]";
    const json& p = pts[i];
    if (!p.is_object()) fail(path, "expected an object");
    MeasuredPoint m;
    if (!p.contains("feature") || !p["feature"].is_string() || p["feature"].get<std::string>().empty())
      fail(path + ".feature", "expected the feature's name");
    m.feature = p["feature"].get<std::string>();
    if (!p.contains("machine")) fail(path + ".machine", "missing (the measured point in machine coordinates)");
    m.point = vec(p["machine"], path + ".machine");
    if (p.contains("approach")) {
      const double r = p.contains("radius") ? number(p["radius"], path + ".radius") : 0.0;
      set_probe(m, vec(p["approach"], path + ".approach"), r, [&](const std::string& why) { fail(path, why); });
    }
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace

std::vector<MeasuredPoint> parse_measured_points(std::string_view text, std::string_view source) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && text[first] == '{') return parse_json(text, source);
  return parse_text(text, source);
}

}  // namespace imess::metrology
