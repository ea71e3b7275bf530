// Part frames on the wire: Frames, Frame, PartPos, UseFrame, SetFrame, Align, DelFrame
// (docs/protocol.md, "Part frames"). The store is FrameService's; alignments fit journaled
// hits with the metrology library.
#include <algorithm>
#include <cctype>
#include <cmath>

#include <Eigen/Geometry>

#include "imess/metrology/alignment.hpp"
#include "imess/metrology/fit.hpp"
#include "imess/metrology/probe_compensation.hpp"
#include "imess/net/frame_verbs.hpp"

#include <spdlog/spdlog.h>
#include "imess/protocol/hit_set.hpp"
#include "imess/protocol/numbers.hpp"

namespace imess::net {
namespace {

using protocol::ErrorCode;
using protocol::format_err;
using protocol::format_ok;
using Vec = Eigen::Vector3d;

void append_vector(std::string& out, std::string_view label, const Vec& v, int decimals) {
  out += ' ';
  out += label;
  for (int c = 0; c < 3; ++c) {
    out += ' ';
    protocol::append_fixed(out, v[c], decimals);
  }
}

// "Origin x y z XAxis i j k YAxis i j k ZAxis i j k": the frame's origin and axes in machine
// coordinates (the columns of its rotation).
std::string frame_text(const metrology::Frame& f) {
  std::string out;
  append_vector(out, "Origin", f.translation(), 4);
  append_vector(out, "XAxis", f.rotation().col(0), 9);
  append_vector(out, "YAxis", f.rotation().col(1), 9);
  append_vector(out, "ZAxis", f.rotation().col(2), 9);
  return out.substr(1);
}

// " machine a b": the names, each after a blank; `from` 1 leaves machine out (the stored ones).
std::string names_text(const PartFrames& frames, std::size_t from = 0) {
  std::string out;
  const auto names = frames.names();
  for (std::size_t i = from; i < names.size(); ++i) out += ' ' + names[i];
  return out;
}

// The journaled hits of one set: surface points, approach directions, tip radii.
struct HitGroup {
  std::vector<Vec> surface, centre, approach;
  double radius = 0;
};

}  // namespace

bool FrameVerbs::frames_usable(Session& s, std::uint32_t slot, std::string_view verb) {
  if (layout().cartesian_axis(0) >= 0 && layout().cartesian_axis(1) >= 0 && layout().cartesian_axis(2) >= 0) return true;
  reply(s, slot, format_err(ErrorCode::BadValue, std::string(verb) + ": part frames need linear X Y Z axes; this machine has " + layout().names()));
  return false;
}

// The frame of `name` (empty: the active one), or an Err 105 naming the frames there are.
const metrology::Frame* FrameVerbs::frame_named(Session& s, std::uint32_t slot, std::string_view verb, std::string& name) {
  if (name.empty()) name = frames_.active();
  if (const auto* f = frames_.frames().find(name)) return f;
  reply(s, slot, format_err(ErrorCode::BadValue, std::string(verb) + ": no frame '" + name.substr(0, 40) + "'; the frames are" + names_text(frames_.frames())));
  return nullptr;
}

void FrameVerbs::list_frames(Session& s, std::uint32_t slot) {
  reply(s, slot, format_ok("Frames", "Active " + frames_.active() + " Names" + names_text(frames_.frames())));
}

void FrameVerbs::show_frame(Session& s, std::uint32_t slot, std::string name) {
  if (const auto* f = frame_named(s, slot, "Frame", name)) reply(s, slot, format_ok("Frame", name + ' ' + frame_text(*f)));
}

void FrameVerbs::part_pos(Session& s, std::uint32_t slot, std::string name) {
  if (!frames_usable(s, slot, "PartPos")) return;
  const auto* f = frame_named(s, slot, "PartPos", name);
  if (!f) return;
  const Vec p = f->point_from_parent(layout().cartesian(gateway_.snapshot().position));
  std::string data = name;
  for (int c = 0; c < 3; ++c) {
    data += ' ';
    protocol::append_mm(data, p[c]);
  }
  reply(s, slot, format_ok("PartPos", data));
}

void FrameVerbs::use_frame(Session& s, std::uint32_t slot, std::string name) {
  if (!frames_usable(s, slot, "UseFrame") || !frame_named(s, slot, "UseFrame", name)) return;
  frames_.use(name);
  reply(s, slot, format_ok("UseFrame", name));
  frames_.changed();
}

// Stores `frame` under `name`, makes it active, answers `verb` with the frame and announces it.
void FrameVerbs::store_frame(Session& s, std::uint32_t slot, std::string_view verb, const std::string& name,
                         const metrology::Frame& frame, std::string_view extra) {
  const std::string save_error = frames_.keep(name, frame);
  std::string data = name + ' ' + frame_text(frame);
  if (!extra.empty()) data += ' ' + std::string(extra);
  if (!save_error.empty()) data += " Stored no";
  reply(s, slot, format_ok(verb, data));
  frames_.changed();
}

void FrameVerbs::set_frame(Session& s, std::uint32_t slot, const protocol::SetFrame& c) {
  if (!frames_usable(s, slot, "SetFrame")) return;
  if (auto why = PartFrames::refuse_name(c.name); !why.empty()) {
    reply(s, slot, format_err(ErrorCode::BadValue, "SetFrame " + c.name.substr(0, 40) + ": accepted " + why));
    return;
  }
  const Vec origin = c.origin ? Vec((*c.origin)[0], (*c.origin)[1], (*c.origin)[2])
                              : Vec(layout().cartesian(gateway_.snapshot().position));
  if (!(origin.cwiseAbs().maxCoeff() <= kMaxFrameOrigin)) {
    reply(s, slot, format_err(ErrorCode::BadValue, "SetFrame " + c.name + ": the origin's coordinates go from -1000000 to 1000000 mm"));
    return;
  }
  if (c.x_axis.has_value() != c.z_axis.has_value()) {
    reply(s, slot, format_err(ErrorCode::BadValue, "SetFrame " + c.name + ": give both X and Z (the axes' directions) or neither (the machine's axes)"));
    return;
  }
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  if (c.x_axis) {
    Vec x((*c.x_axis)[0], (*c.x_axis)[1], (*c.x_axis)[2]), z((*c.z_axis)[0], (*c.z_axis)[1], (*c.z_axis)[2]);
    if (!(x.norm() > 1e-9) || !(z.norm() > 1e-9)) {
      reply(s, slot, format_err(ErrorCode::BadValue, "SetFrame " + c.name + ": the X and Z directions must not be zero"));
      return;
    }
    x.normalize();
    z.normalize();
    if (std::abs(x.dot(z)) > 1e-3) {
      reply(s, slot, format_err(ErrorCode::BadValue, "SetFrame " + c.name + ": X and Z must be perpendicular (within 1e-3 rad), their cosine is " + std::to_string(x.dot(z))));
      return;
    }
    r.col(0) = x;
    r.col(1) = z.cross(x).normalized();
    r.col(2) = z;
  }
  try {
    store_frame(s, slot, "SetFrame", c.name, metrology::Frame::orthonormalised(r, origin), {});
  } catch (const metrology::FrameError& e) {
    reply(s, slot, format_err(ErrorCode::BadValue, "SetFrame " + c.name + ": " + e.what()));
  }
}

// Align's hit sets: three given, or the one word `last` (the newest 6 hits, for holes 9), which
// become their numbers in `sets` and `used` ("7-9 10,11 12"). False: refused (answered).
bool FrameVerbs::last_hits(Session& s, std::uint32_t slot, const protocol::Align& c, const std::string& head,
                           std::array<std::string, 3>& sets, std::string& used) {
  const bool last = c.hits[0].size() == 4 && std::equal(c.hits[0].begin(), c.hits[0].end(), "last", [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) == b;
                    });
  const std::string usage = "; usage: Align name 321|holes plane-hits hits hits, or Align name 321|holes last";
  if (last && (!c.hits[1].empty() || !c.hits[2].empty())) {
    reply(s, slot, format_err(ErrorCode::BadArguments, head + "'last' takes the newest hits and stands alone" + usage));
    return false;
  }
  if (!last && (c.hits[1].empty() || c.hits[2].empty())) {
    reply(s, slot, format_err(ErrorCode::BadArguments, head + "needs three hit sets (" + (c.holes ? "plane, hole, hole" : "plane, line, point") +
                                                          ") or the word 'last'" + usage));
    return false;
  }
  if (!last) return true;
  const std::uint64_t n = c.holes ? 9 : 6, newest = journal_.newest();
  if (newest < n || journal_.oldest() > newest - n + 1) {
    reply(s, slot, format_err(ErrorCode::BadValue, head + "'last' takes the newest " + std::to_string(n) + " hits; the journal holds " +
                                                       (newest == 0 ? std::string("none") : "hits " + std::to_string(journal_.oldest()) + " to " + std::to_string(newest))));
    return false;
  }
  const std::uint64_t first = newest - n + 1;
  auto range = [](std::uint64_t a, std::uint64_t b) { return std::to_string(a) + "-" + std::to_string(b); };
  if (c.holes) {
    sets = {range(first, first + 2), range(first + 3, first + 5), range(first + 6, first + 8)};
  } else {
    sets = {range(first, first + 2), std::to_string(first + 3) + "," + std::to_string(first + 4), std::to_string(first + 5)};
  }
  used = sets[0] + " " + sets[1] + " " + sets[2];
  return true;
}

// Align name 321|holes plane line|hole point|hole: fits the journaled hits and builds the frame.
void FrameVerbs::align(Session& s, std::uint32_t slot, const protocol::Align& c) {
  if (!frames_usable(s, slot, "Align")) return;
  const std::string head = "Align " + c.name.substr(0, 40) + ": ";
  if (auto why = PartFrames::refuse_name(c.name); !why.empty()) {
    reply(s, slot, format_err(ErrorCode::BadValue, head + "accepted " + why));
    return;
  }
  static constexpr const char* kRoles321[3] = {"plane", "line", "point"};
  static constexpr const char* kRolesHoles[3] = {"plane", "first hole", "second hole"};
  static constexpr std::size_t kMinimum321[3] = {3, 2, 1};
  static constexpr std::size_t kMinimumHoles[3] = {3, 3, 3};
  // The hit sets as given, or `last`: the journal's newest hits, taken in order (321: three for
  // the plane, two for the line, one for the point; holes: three each), named in the reply.
  std::array<std::string, 3> sets = c.hits;
  std::string hits_used;
  if (!last_hits(s, slot, c, head, sets, hits_used)) return;
  HitGroup groups[3];
  for (int g = 0; g < 3; ++g) {
    const char* role = c.holes ? kRolesHoles[g] : kRoles321[g];
    std::string why;
    const auto seqs = protocol::parse_hit_set(sets[static_cast<std::size_t>(g)], why);
    if (seqs.empty()) {
      reply(s, slot, format_err(ErrorCode::BadValue, head + role + ": " + why));
      return;
    }
    const std::size_t minimum = c.holes ? kMinimumHoles[g] : kMinimum321[g];
    if (seqs.size() < minimum) {
      reply(s, slot, format_err(ErrorCode::BadValue, head + "the " + role + " needs at least " + std::to_string(minimum) + " hits, got " + std::to_string(seqs.size())));
      return;
    }
    auto& grp = groups[g];
    for (std::size_t i = 0; i < seqs.size(); ++i) {
      std::optional<protocol::HitMsg> hit;
      bool lost = false;  // journaled, but its record is damaged or missing
      try {
        const auto got = journal_.read(seqs[i], 1);
        lost = !got.lost.empty() && got.lost.front().first <= seqs[i];
        if (!got.lines.empty()) {
          auto m = protocol::parse_message(std::string_view(got.lines[0]).substr(0, got.lines[0].size() - 1));
          if (auto* h = std::get_if<protocol::HitMsg>(&m); h && h->seq == seqs[i]) hit = *h;
        }
      } catch (const journal::JournalError& e) {
        log_limited(log_, spdlog::level::err, "journal", e.what());
      }
      if (!hit && lost) {
        reply(s, slot, format_err(ErrorCode::BadValue, head + "hit " + std::to_string(seqs[i]) + " of the " + role +
                                                          " is lost: its record in the journal is damaged or missing; "
                                                          "measure the point again and use its new number"));
        return;
      }
      if (!hit) {
        reply(s, slot, format_err(ErrorCode::BadValue, head + "hit " + std::to_string(seqs[i]) + " of the " + role +
                                                          " is not in the journal (hits " + std::to_string(journal_.oldest()) + " to " +
                                                          std::to_string(journal_.newest()) + " are)"));
        return;
      }
      const Vec p(hit->p.x, hit->p.y, hit->p.z), d(hit->dir.x, hit->dir.y, hit->dir.z);
      if (i == 0) grp.radius = hit->radius;
      if (std::abs(hit->radius - grp.radius) > 1e-9) {
        reply(s, slot, format_err(ErrorCode::BadValue, head + "the hits of the " + role + " were taken with different tip radii; measure them again with one"));
        return;
      }
      grp.surface.push_back(p);
      grp.approach.push_back(d);
      grp.centre.push_back(p - hit->radius * d);
    }
  }
  // The plane: fitted to the ball centres, moved by the tip radius, its normal out of the material.
  const auto plane = metrology::fit_plane_probed(groups[0].centre, groups[0].approach, groups[0].radius);
  if (!plane.ok()) {
    reply(s, slot, format_err(ErrorCode::BadValue, head + "the plane: " + plane.error().message));
    return;
  }
  std::string extra;
  auto form = [&](std::string_view label, double value) {
    extra += (extra.empty() ? "" : " ") + std::string(label) + ' ';
    protocol::append_fixed(extra, value, 4);
  };
  form("PlaneForm", plane->stats.form());
  try {
    metrology::Frame frame;
    if (!c.holes) {
      // The line: the surface points of its hits (compensated along their approach); X points
      // from its first hit toward its last, as the operator probed them.
      const auto line = metrology::fit_line3d(groups[1].surface);
      if (!line.ok()) {
        reply(s, slot, format_err(ErrorCode::BadValue, head + "the line: " + line.error().message));
        return;
      }
      metrology::Line3 l = *line;
      if (l.direction.dot(groups[1].surface.back() - groups[1].surface.front()) < 0) l.direction = -l.direction;
      Vec origin = Vec::Zero();
      for (const auto& p : groups[2].surface) origin += p;
      origin /= static_cast<double>(groups[2].surface.size());
      frame = metrology::align_321(*plane, l, origin);
      form("LineForm", l.stats.form());
    } else {
      Vec centres[2];
      for (int h = 0; h < 2; ++h) {
        const auto& grp = groups[1 + h];
        const auto hole = metrology::fit_circle3d_probed(grp.centre, grp.approach, grp.radius);
        if (!hole.ok()) {
          reply(s, slot, format_err(ErrorCode::BadValue, head + (h == 0 ? "the first hole: " : "the second hole: ") + hole.error().message));
          return;
        }
        centres[h] = hole->center;
        form(h == 0 ? "Hole1Dia" : "Hole2Dia", hole->diameter);
      }
      frame = metrology::align_plane_two_holes(*plane, centres[0], centres[1]);
    }
    if (!(frame.translation().cwiseAbs().maxCoeff() <= kMaxFrameOrigin)) {  // as SetFrame's bound
      reply(s, slot, format_err(ErrorCode::BadValue, head + "the frame's origin lies beyond -1000000 to 1000000 mm; probe other features"));
      return;
    }
    if (!hits_used.empty()) extra += " Hits " + hits_used;
    store_frame(s, slot, "Align", c.name, frame, extra);
  } catch (const std::exception& e) {  // AlignmentError, FrameError
    reply(s, slot, format_err(ErrorCode::BadValue, head + e.what()));
  }
}

void FrameVerbs::del_frame(Session& s, std::uint32_t slot, const std::string& name) {
  const bool was_active = frames_.active() == name;
  std::string save_error;
  if (!frames_.remove(name, save_error)) {  // a file not written is logged there
    reply(s, slot, format_err(ErrorCode::BadValue, "DelFrame: no stored frame '" + name.substr(0, 40) + "'; the stored frames are" + names_text(frames_.frames(), 1)));
    return;
  }
  reply(s, slot, format_ok("DelFrame", name));
  if (was_active) frames_.changed();
}

}  // namespace imess::net
