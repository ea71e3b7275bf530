// The page's files and fits, by messcap's code: a capture file as `messcap -o points.EXT`
// writes it for the same hits (hit numbers included: the .csv `hit` column, the "# hit N"
// comments), a fit as `messcap fit KIND points.hits` prints it (probe-compensated when the
// hits have their approach and tip radius, as messcap does).
#include <nlohmann/json.hpp>

#include "imess/exchange/export_format.hpp"
#include "imess/exchange/fit_report.hpp"
#include "imess/webpoints/points_request.hpp"

namespace imess::webpoints {
namespace {

constexpr std::string_view kExportFormats = "csv, xyz, dmi, hits";

nlohmann::ordered_json head(const PointsRequest& r) {
  nlohmann::ordered_json out;
  out["type"] = r.kind == PointsRequest::Kind::Fit ? "Fit" : "Export";
  out["id"] = r.id;
  return out;
}

std::string failed(const PointsRequest& r, const std::string& why) {
  auto out = head(r);
  out["error"] = why;
  return out.dump();
}

bool all_probed(const std::vector<PageHit>& hits) {
  for (const auto& h : hits)
    if (!h.hit.has_approach() || h.hit.radius != hits.front().hit.radius) return false;
  return !hits.empty();
}

// The line formats carry the hit number as messcap's capture writes it (hit_numbers.hpp there).
std::string line_with_number(std::string_view format, std::string line, std::uint64_t seq) {
  if (format == "csv") return std::to_string(seq) + "," + line.insert(line.size() - 1, ",");  // the scan column empty
  line.insert(line.size() - 1, " # hit " + std::to_string(seq));
  return line;
}

std::string export_text(const PointsRequest& r, const std::string& name) {
  const auto& format = exchange::export_format_for(name);
  if (format.appendable()) {  // csv, xyz, hits: a capture's header and one line per hit
    const bool hits = format.needs_approach();
    if (hits && !all_probed(r.hits))
      throw std::invalid_argument("a .hits file needs every hit's approach (i j k) and one tip radius (r)");
    std::string out = r.what == "csv" ? "hit,x,y,z,scan\n" : format.header();
    for (const auto& h : r.hits)
      out += line_with_number(r.what, hits ? format.hit_line(h.hit, exchange::kHitDecimals)
                                           : format.point_line(h.hit.surface, 3), h.seq);
    return out;
  }
  exchange::ExportData data;  // as the capture's: MeasPt's 3 decimals, the file's own name
  data.file_name = name;
  for (const auto& h : r.hits) data.points.push_back(h.hit.surface);
  return format.write(data);
}

std::string export_reply(const PointsRequest& r) {
  if (r.what != "csv" && r.what != "xyz" && r.what != "dmi" && r.what != "hits")
    return failed(r, "no export format \"" + r.what + "\"; accepted: " + std::string(kExportFormats));
  const std::string name = "points." + r.what;
  std::string text;
  try {
    text = export_text(r, name);
  } catch (const std::exception& e) {
    return failed(r, name + ": " + e.what());
  }
  auto out = head(r);
  out["format"] = r.what;
  out["name"] = name;
  out["n"] = r.hits.size();
  out["text"] = text;
  return out.dump();
}

std::string fit_reply(const PointsRequest& r) {
  exchange::FitKind kind;
  try {
    kind = exchange::parse_fit_kind(r.what);
  } catch (const exchange::FitKindError& e) {
    return failed(r, e.what());
  }
  std::vector<Eigen::Vector3d> surface;
  std::vector<metrology::ProbedPoint> probed;
  for (const auto& h : r.hits) {
    surface.push_back(h.hit.surface);
    probed.push_back(h.hit);
  }
  const bool compensated = all_probed(r.hits);
  auto fit = compensated ? exchange::fit_probed_points(kind, probed) : exchange::fit_points(kind, surface);
  auto out = head(r);
  out["kind"] = exchange::to_string(kind);
  out["n"] = r.hits.size();
  out["probed"] = compensated && exchange::has_probed_fit(kind);
  if (!fit) {  // messcap fit's wording
    out["error"] = "fit " + std::string(exchange::to_string(kind)) + " to the " + std::to_string(r.hits.size()) +
                   (r.hits.size() == 1 ? " point" : " points") + " failed (" +
                   std::string(metrology::to_string(fit.error().code)) + "): " + fit.error().message;
    return out.dump();
  }
  const std::string line = exchange::to_json(*fit);
  out["result"] = nlohmann::json::parse(line);
  out["text"] = line;
  return out.dump();
}

}  // namespace

std::string points_reply(const PointsRequest& request) {
  return request.kind == PointsRequest::Kind::Fit ? fit_reply(request) : export_reply(request);
}

}  // namespace imess::webpoints
