// The live measurement of an inspection plan over messd's protocol (MachineLink: one command
// at a time, MoveTo / Probe each waited for until its Done, Hit lines collected by Probe id).
#include "inspect_session.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Geometry>

namespace imess::messcap {
namespace {

using Eigen::Vector3d;
using metrology::Frame;
using metrology::InspectionPlan;
using metrology::PlanFeature;

class Session {
 public:
  Session(const InspectionPlan& plan, const LiveOptions& options, std::ostream& log)
      : plan_(plan), options_(options), log_(log), frame_(plan.placement), link_(options.endpoint) {}

  std::vector<metrology::MeasuredPoint> run() {
    link_.request("Hello messcap-inspect");
    link_.request("Take");
    if (plan_.probing.tip_radius) link_.request("Set TipRadius " + std::to_string(*plan_.probing.tip_radius));
    if (plan_.probing.search) link_.request("Set SearchDist " + std::to_string(*plan_.probing.search));
    tip_radius_ = plan_.probing.tip_radius ? *plan_.probing.tip_radius : link_.status_number("TipRadius");
    feed_ = options_.feed.value_or(plan_.probing.feed);
    log_ << "messcap: measuring " << plan_.part << " on " << options_.endpoint.to_string() << " (tip radius "
         << tip_radius_ << " mm, feed " << feed_ << " mm/s)\n";

    // Up to the safe height where the machine stands, before anything moves sideways.
    move_z(frame_.point_to_parent(Vector3d(0, 0, plan_.probing.safe_z)).z());
    const auto order = measuring_order(plan_);
    for (std::size_t k = 0; k < order.size(); ++k) {
      measure_feature(*order[k]);
      if (plan_.alignment && k == 2) align();
    }
    release();
    return points_;
  }

 private:
  // --- moves ---
  std::string feed_word() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, " F%.1f", feed_);
    return buf;
  }
  void move_z(double z) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "Z%.4f", z);
    link_.queued("MoveTo", buf + feed_word());
  }
  void move_to(const Vector3d& part) { link_.queued("MoveTo", xyz_words(frame_.point_to_parent(part)) + feed_word()); }
  Vector3d above(const Vector3d& part) const { return {part.x(), part.y(), plan_.probing.safe_z}; }

  // Ball-centre positions of one probe point: the start (clearance off the surface) and the
  // target (touching the nominal surface), part coordinates.
  Vector3d start_of(const metrology::ProbeTarget& t) const {
    return t.point - (tip_radius_ + plan_.probing.clearance) * t.approach;
  }
  Vector3d target_of(const metrology::ProbeTarget& t) const { return t.point - tip_radius_ * t.approach; }

  void measure_feature(const PlanFeature& f) {
    if (f.probes.empty()) throw MachineError("feature '" + f.name + "' has no probe points to measure");
    for (std::size_t i = 0; i < f.probes.size(); ++i) {
      const Vector3d start = start_of(f.probes[i]);
      if (i == 0 || f.lift_between) {
        move_to(above(start));
        move_to(start);
      } else {
        move_to(start);
      }
      probe(f, f.probes[i]);
      move_to(start);
      if (f.lift_between || i + 1 == f.probes.size()) move_to(above(start));
    }
    log_ << "messcap: " << f.name << ": " << f.probes.size() << (f.probes.size() == 1 ? " point\n" : " points\n");
  }

  void probe(const PlanFeature& f, const metrology::ProbeTarget& t) {
    protocol::HitMsg h;
    try {
      h = link_.probe(xyz_words(frame_.point_to_parent(target_of(t))) + feed_word());
    } catch (const MachineError& e) {
      throw MachineError("feature '" + f.name + "': " + e.what());
    }
    metrology::MeasuredPoint p;
    p.feature = f.name;
    p.point = {h.p.x, h.p.y, h.p.z};
    const Vector3d dir(h.dir.x, h.dir.y, h.dir.z);
    if (dir.norm() > 0) {
      p.approach = dir.normalized();
      p.radius = h.radius;
    }
    points_.push_back(p);
  }

  // The part frame from the alignment features measured so far: the rest is probed in it.
  void align() {
    frame_ = metrology::align_part(plan_, points_);
    const Vector3d o = frame_.translation();
    const double turn = std::atan2(frame_.rotation()(1, 0), frame_.rotation()(0, 0)) * 180 / M_PI;
    char buf[160];
    std::snprintf(buf, sizeof buf, "messcap: part frame from %s, %s, %s: origin %.4f %.4f %.4f, x axis turned %.4f deg about z\n",
                  plan_.alignment->primary.c_str(), plan_.alignment->secondary.c_str(), plan_.alignment->tertiary.c_str(),
                  o.x(), o.y(), o.z(), turn);
    log_ << buf;
  }

  // Tells messd the part frame (a messd with part frames keeps it for other clients; an older
  // one answers Err, which is only noted), then gives up control.
  void release() {
    if (plan_.alignment) {
      const Vector3d o = frame_.translation(), x = frame_.rotation().col(0), z = frame_.rotation().col(2);
      char buf[256];
      std::snprintf(buf, sizeof buf, "SetFrame %s O %.6f %.6f %.6f X %.9f %.9f %.9f Z %.9f %.9f %.9f", plan_.part.c_str(), o.x(),
                    o.y(), o.z(), x.x(), x.y(), x.z(), z.x(), z.y(), z.z());
      const std::string reply = link_.try_request(buf);
      if (reply.rfind("Err ", 0) == 0) log_ << "messcap: messd keeps no part frames (" << reply << "); the frame is in the report\n";
    }
    link_.request("Release");
    link_.finish();
  }

  const InspectionPlan& plan_;
  const LiveOptions& options_;
  std::ostream& log_;
  Frame frame_;
  MachineLink link_;
  double tip_radius_ = 0, feed_ = 0;
  std::vector<metrology::MeasuredPoint> points_;
};

}  // namespace

std::vector<const PlanFeature*> measuring_order(const InspectionPlan& plan) {
  std::vector<const PlanFeature*> order;
  if (plan.alignment)
    for (const auto* name : {&plan.alignment->primary, &plan.alignment->secondary, &plan.alignment->tertiary})
      order.push_back(&plan.feature(*name));
  for (const auto& f : plan.features)
    if (std::find(order.begin(), order.end(), &f) == order.end()) order.push_back(&f);
  return order;
}

std::vector<metrology::MeasuredPoint> measure_live(const InspectionPlan& plan, const LiveOptions& options, std::ostream& log) {
  return Session(plan, options, log).run();
}

void announce_result(const InspectionPlan& plan, const metrology::InspectionResult& result, const LiveOptions& options,
                     std::ostream& log) {
  const std::size_t open = result.out_of_tolerance() + result.not_evaluated();
  std::string part = plan.part;
  for (char& c : part)
    if (c == ' ' || c == '\t') c = '_';  // one word on the wire
  const std::string line = "Verdict " + part + " " + std::to_string(result.characteristics.size() - open) + " " +
                           std::to_string(open) + (open == 0 ? " pass" : " fail");
  MachineLink link(options.endpoint);
  link.try_request("Hello messcap-inspect");
  const std::string reply = link.try_request(line);
  if (reply.rfind("Err ", 0) == 0) log << "messcap: messd did not take the result (" << reply << ")\n";
  link.finish();
}

}  // namespace imess::messcap
