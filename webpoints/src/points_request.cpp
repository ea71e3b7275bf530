// Reading the page's points requests strictly: every key known, every number finite, the
// approach a unit vector (to the decimals the Hit line prints) or none at all.
#include <cmath>

#include "imess/jsontext/strict_json.hpp"
#include "imess/webpoints/points_request.hpp"

namespace imess::webpoints {
namespace {

constexpr const char* kAccepted =
    "accepted: {\"export\":\"csv\"|\"xyz\"|\"dmi\"|\"hits\" or \"fit\":KIND, \"id\":NUMBER, \"hits\":[{\"seq\":N,"
    "\"x\":X,\"y\":Y,\"z\":Z,\"i\":I,\"j\":J,\"k\":K,\"r\":R},...]} (docs/web.md)";

struct Bad : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double number(const nlohmann::json& hit, const char* key, std::size_t n, bool needed) {
  const auto it = hit.find(key);
  if (it == hit.end()) {
    if (needed) throw Bad("hit " + std::to_string(n + 1) + " has no \"" + key + "\"");
    return 0.0;
  }
  if (!it->is_number() || !std::isfinite(it->get<double>()))
    throw Bad("\"" + std::string(key) + "\" of hit " + std::to_string(n + 1) + " is not a finite number");
  return it->get<double>();
}

PageHit page_hit(const nlohmann::json& j, std::size_t n) {
  if (!j.is_object()) throw Bad("hit " + std::to_string(n + 1) + " is not an object");
  for (const auto& [key, v] : j.items())
    if (key.size() != 1 || std::string_view("xyzijkr").find(key[0]) == std::string_view::npos)
      if (key != "seq") throw Bad("hit " + std::to_string(n + 1) + " has an unknown key \"" + key + "\"");
  PageHit h;
  const auto seq = j.find("seq");
  if (seq == j.end() || !seq->is_number_unsigned())
    throw Bad("hit " + std::to_string(n + 1) + " has no \"seq\" (its journal number, 1 or more)");
  h.seq = seq->get<std::uint64_t>();
  h.hit.surface = {number(j, "x", n, true), number(j, "y", n, true), number(j, "z", n, true)};
  h.hit.approach = {number(j, "i", n, false), number(j, "j", n, false), number(j, "k", n, false)};
  h.hit.radius = number(j, "r", n, false);
  if (h.hit.has_approach()) {
    if (std::abs(h.hit.approach.norm() - 1.0) > metrology::kApproachLengthTolerance)
      throw Bad("the approach (i j k) of hit " + std::to_string(n + 1) + " is not a unit vector");
    h.hit.approach.normalize();  // 6 decimals on the wire, as messcap takes them
  }
  if (h.hit.radius < 0) throw Bad("\"r\" of hit " + std::to_string(n + 1) + " is negative");
  return h;
}

std::string refusal(const PointsRequest& r, const std::string& why) {
  nlohmann::ordered_json out;
  out["type"] = r.kind == PointsRequest::Kind::Fit ? "Fit" : "Export";
  out["id"] = r.id;
  out["error"] = why + "; " + kAccepted;
  return out.dump();
}

}  // namespace

std::variant<NotPoints, PointsRequest, Refused> parse_points_request(std::string_view message) {
  jsontext::Options options;
  options.max_depth = 3;
  options.depth_hint = "a points request is an object with a list of hits";
  const auto request = jsontext::object_naming(message, {"export", "fit"}, options);
  if (!request) return NotPoints{};  // webjson refuses it, saying why
  const nlohmann::json& j = *request;
  PointsRequest r;
  r.kind = j.contains("fit") ? PointsRequest::Kind::Fit : PointsRequest::Kind::Export;
  try {
    if (j.contains("fit") && j.contains("export")) throw Bad("a request is either \"export\" or \"fit\"");
    for (const auto& [key, v] : j.items())
      if (key != "export" && key != "fit" && key != "id" && key != "hits") throw Bad("unknown key \"" + key + "\"");
    if (const auto id = j.find("id"); id != j.end()) {
      if (!id->is_number_integer()) throw Bad("\"id\" is not an integer");
      r.id = id->get<std::int64_t>();
    }
    const auto& what = j.contains("fit") ? j["fit"] : j["export"];
    if (!what.is_string()) throw Bad(std::string(j.contains("fit") ? "\"fit\"" : "\"export\"") + " is not a string");
    r.what = what.get<std::string>();
    const auto hits = j.find("hits");
    if (hits == j.end() || !hits->is_array()) throw Bad("\"hits\" is missing or not a list");
    if (hits->size() > kMaxHits) throw Bad("more than " + std::to_string(kMaxHits) + " hits");
    r.hits.reserve(hits->size());
    for (std::size_t n = 0; n < hits->size(); ++n) r.hits.push_back(page_hit((*hits)[n], n));
  } catch (const Bad& e) {
    return Refused{refusal(r, e.what())};
  }
  return r;
}

std::optional<std::string> answer_points_message(std::string_view message) {
  auto parsed = parse_points_request(message);
  if (auto* refused = std::get_if<Refused>(&parsed)) return refused->reply;
  if (auto* request = std::get_if<PointsRequest>(&parsed)) return points_reply(*request);
  return std::nullopt;
}

}  // namespace imess::webpoints
