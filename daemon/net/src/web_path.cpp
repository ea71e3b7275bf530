// The loaded program's path for the web panel's 3-D view: {"path":"loaded","id":N} is answered
// by the web front end at once with the path the program's check plans (the very planning of
// Load and messprog check: check_program_for), its segments joined into moves per source line
// and kind (rapid, feed, probe), arcs sampled. The page highlights the moves of the line a
// Block event names.
#include <cmath>

#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"
#include "imess/net/program_runner.hpp"
#include "web_shared.hpp"

namespace imess::net {

namespace {

constexpr std::size_t kMaxPathPoints = 200000;  // a reply stays a few MiB even for a long program

double rounded(double v) { return std::round(v * 1e4) / 1e4; }

nlohmann::json xyz_of(const planner::Pose& p, const core::AxisLayout& layout) {
  nlohmann::json out = nlohmann::json::array();
  for (int c = 0; c < 3; ++c) {
    const int a = layout.cartesian_axis(c);
    out.push_back(a >= 0 ? rounded(p[a]) : 0.0);
  }
  return out;
}

std::string path_reply(std::int64_t id, const ProgramRunner& programs) {
  nlohmann::ordered_json out;
  out["type"] = "Path";
  out["id"] = id;
  const auto& layout = programs.layout();
  nlohmann::json moves = nlohmann::json::array();
  std::size_t segments = 0, points = 0;
  int line = -1;
  std::string kind;
  auto visit = [&](const planner::PlannedSegment& seg, const programs::Item& item) {
    ++segments;
    if (seg.kind != planner::SegmentKind::Line && seg.kind != planner::SegmentKind::Arc) return;
    if (seg.length <= 0 || points >= kMaxPathPoints) return;
    const std::string k = seg.probe != planner::ProbePhase::None ? "probe" : item.rapid ? "rapid" : "feed";
    if (item.line != line || k != kind || moves.empty()) {
      moves.push_back({{"line", item.line}, {"kind", k}, {"points", nlohmann::json::array({xyz_of(seg.start, layout)})}});
      line = item.line;
      kind = k;
      ++points;
    }
    auto& to = moves.back()["points"];
    if (seg.kind == planner::SegmentKind::Arc) {
      constexpr int kSteps = 32;
      planner::Pose pose{}, dpose{};
      for (int i = 1; i < kSteps; ++i) {
        planner::pose_at(seg, seg.length * i / kSteps, pose, dpose);
        to.push_back(xyz_of(pose, layout));
      }
      points += kSteps - 1;
    }
    to.push_back(xyz_of(seg.end, layout));
    ++points;
  };
  std::string name, error;
  if (!programs.loaded_path(visit, name, error)) {
    out["error"] = error;
    return out.dump();
  }
  out["name"] = name;
  out["segments"] = segments;
  out["truncated"] = points >= kMaxPathPoints;
  out["moves"] = std::move(moves);
  return out.dump();
}

}  // namespace

std::optional<std::string> answer_path_message(std::string_view message, const ProgramRunner* programs) {
  jsontext::Options options;
  options.max_depth = 1;
  const auto request = jsontext::object_naming(message, {"path"}, options);
  if (!request) return std::nullopt;  // webjson refuses it, saying why
  const nlohmann::json& j = *request;
  nlohmann::ordered_json refusal{{"type", "Path"}, {"id", 0}};
  const auto id = j.find("id");
  if (id != j.end() && id->is_number_integer()) refusal["id"] = id->get<std::int64_t>();
  for (const auto& [key, v] : j.items())
    if (key != "path" && key != "id") {
      refusal["error"] = "unknown key \"" + key + "\"; accepted: {\"path\":\"loaded\",\"id\":NUMBER}";
      return refusal.dump();
    }
  if (j["path"] != "loaded" || (id != j.end() && !id->is_number_integer())) {
    refusal["error"] = "accepted: {\"path\":\"loaded\",\"id\":NUMBER}, the loaded program's path";
    return refusal.dump();
  }
  if (!programs) {
    refusal["error"] = "this messd runs no programs";
    return refusal.dump();
  }
  return path_reply(refusal["id"].get<std::int64_t>(), *programs);
}

}  // namespace imess::net
