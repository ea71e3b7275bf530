// The web panel's point tools: the page sends its points (the Hit events it listed) and asks for
// a file or a fit; the web front end answers at once, with messcap's own code (imess::exchange:
// the writers `messcap -o FILE` uses, the fits `messcap fit` prints), so the page's files and
// fits are messcap's, byte for byte. No line protocol is involved: the machine is not asked.
//
//   {"export":"csv"|"xyz"|"dmi"|"hits","id":N,"hits":[{"seq":17,"x":…,"y":…,"z":…,"i":…,"j":…,"k":…,"r":…},…]}
//     -> {"type":"Export","id":N,"format":"csv","name":"points.csv","text":"hit,x,y,z,scan\n17,…"}
//   {"fit":"plane"|"circle"|"sphere"|"cylinder"|… ,"id":N,"hits":[…]}
//     -> {"type":"Fit","id":N,"kind":"circle","n":8,"result":{…},"text":"{…}"} (`messcap fit`'s line)
//   a refusal or a failed fit -> the same type with "error": what was wrong and what is accepted.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "imess/metrology/point_file.hpp"

namespace imess::webpoints {

inline constexpr std::size_t kMaxHits = 100000;  // one request's points

// One of the page's points: a hit with its journal number; approach and tip radius when the
// Hit line had them (a MeasPt-only messd gives none: approach zero).
struct PageHit {
  std::uint64_t seq = 0;
  metrology::ProbedPoint hit;
};

struct PointsRequest {
  enum class Kind { Export, Fit } kind = Kind::Export;
  std::string what;  // the format ("csv") or the fit's kind ("circle"), as sent
  std::int64_t id = 0;
  std::vector<PageHit> hits;
};

// What the request parser says: not a points request (no "export"/"fit" key: a MESSD command
// for webjson), a request, or a refusal (the reply to send).
struct NotPoints {};
struct Refused {
  std::string reply;
};

// The page's message read strictly (jsontext): a points request or why not.
std::variant<NotPoints, PointsRequest, Refused> parse_points_request(std::string_view message);

// The reply (one JSON text message) to a request.
std::string points_reply(const PointsRequest& request);

// Both: the reply for a points message, nothing for any other message.
std::optional<std::string> answer_points_message(std::string_view message);

}  // namespace imess::webpoints
