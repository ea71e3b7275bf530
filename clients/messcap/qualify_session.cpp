// The touches of a probe qualification over messd's protocol (qualify_session.hpp).
#include "qualify_session.hpp"

#include <algorithm>
#include <cstdio>

namespace imess::messcap {
namespace {

using Eigen::Vector3d;

std::string feed_word(double feed) {
  char buf[32];
  std::snprintf(buf, sizeof buf, " F%.1f", feed);
  return buf;
}

std::string sphere_words(const ReferenceSphere& s) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.3f,%.3f,%.3f (diameter %.4f mm)", s.centre.x(), s.centre.y(), s.centre.z(), s.diameter);
  return buf;
}

}  // namespace

QualifySession::QualifySession(const client::Endpoint& endpoint, std::ostream& log) : link_(endpoint), log_(log) {
  link_.on_event = [this](std::string_view line) {
    if (line.rfind("Qualified ", 0) == 0) qualified_ = std::string(line);
  };
  link_.request("Hello messcap-qualify");
  link_.request("Take");
}

void QualifySession::move(const Vector3d& ball, double feed) { link_.queued("MoveTo", xyz_words(ball - offset_) + feed_word(feed)); }

Touches QualifySession::touch(const ReferenceSphere& sphere, const TouchPattern& pattern, double feed) {
  Touches out;
  offset_ = {link_.get_number("ProbeOffX"), link_.get_number("ProbeOffY"), link_.get_number("ProbeOffZ")};
  out.offset = offset_;
  out.tip_radius = link_.status_number("TipRadius");
  const TouchPlan plan = plan_touches(sphere, out.tip_radius, pattern);
  const std::size_t count = plan.touches.size();
  log_ << "messcap: qualifying on the sphere at " << sphere_words(sphere) << ": " << count - 1
       << " touches on a ring, then the pole (tip radius in use " << out.tip_radius << " mm)\n";

  // Up where the machine stands (never down), then over the sphere at the safe height.
  const Vector3d here = link_.status_position() + offset_;
  const double first_z = std::max(here.z(), plan.safe_z);
  char z_words[32];
  std::snprintf(z_words, sizeof z_words, "Z%.4f", first_z - offset_.z());
  link_.queued("MoveTo", z_words + feed_word(feed));
  for (std::size_t k = 0; k < count; ++k) {
    const Touch& t = plan.touches[k];
    const Vector3d above(t.start.x(), t.start.y(), k == 0 ? first_z : plan.safe_z);
    try {
      move(above, feed);
      if (k == 0 && first_z != plan.safe_z) move({t.start.x(), t.start.y(), plan.safe_z}, feed);
      move(t.start, feed);
      const auto hit = link_.probe(xyz_words(t.target - offset_) + feed_word(feed));
      metrology::ProbedPoint p;
      p.surface = {hit.p.x, hit.p.y, hit.p.z};
      p.approach = {hit.dir.x, hit.dir.y, hit.dir.z};
      p.radius = hit.radius;
      if (p.has_approach()) p.approach.normalize();
      out.hits.push_back(p);
      move(t.start, feed);
      move({t.start.x(), t.start.y(), plan.safe_z}, feed);
    } catch (const MoveFailed& e) {
      const std::string which = "touch " + std::to_string(k + 1) + " of " + std::to_string(count);
      if (e.reason() == "PartNotFound")
        throw MachineError(which + " found no surface within SearchDist of where the ball should meet the sphere: "
                           "the sphere is not at " + sphere_words(sphere) + " (--sphere, --diameter), or it is off by more "
                           "than SearchDist (" + e.what() + ")");
      if (e.reason() == "UnexpectedHit")
        throw MachineError(which + ": the probe touched something on its way to the sphere: is the sphere at " +
                           sphere_words(sphere) + " (--sphere), with nothing else within " +
                           std::to_string(static_cast<int>(pattern.safe_height)) + " mm above it? (" + e.what() + ")");
      throw MachineError(which + ": " + e.what());
    }
  }
  return out;
}

void QualifySession::qualify(const Qualification& q) {
  char line[160];
  std::snprintf(line, sizeof line, "Qualify %.6f %.6f %.6f %.6f %.6f", q.tip_radius, q.form, q.offset.x(), q.offset.y(),
                q.offset.z());
  link_.request(line);
}

std::optional<std::string> QualifySession::release() {
  link_.request("Release");
  link_.finish();
  return qualified_;
}

}  // namespace imess::messcap
