// The live measurement of an inspection plan over messd's protocol: one command at a time
// (MoveTo / Probe, each waited for until its Done), Hit lines collected by Probe id.
#include "inspect_session.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include "imess/client/connect_error.hpp"
#include "imess/client/connection.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::messcap {
namespace {

using Eigen::Vector3d;
using metrology::Frame;
using metrology::InspectionPlan;
using metrology::PlanFeature;

constexpr auto kReplyTimeout = std::chrono::seconds{10};
constexpr auto kMoveTimeout = std::chrono::seconds{120};

std::string xyz_words(const Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "X%.4f Y%.4f Z%.4f", p.x(), p.y(), p.z());
  return buf;
}

class Session {
 public:
  Session(const InspectionPlan& plan, const LiveOptions& options, std::ostream& log)
      : plan_(plan), options_(options), log_(log), frame_(plan.placement) {
    try {
      link_ = std::make_unique<client::Connection>(client::Connection::open(options.endpoint));
    } catch (const client::ConnectError& e) {
      throw InspectSessionError(e.what());
    }
  }

  std::vector<metrology::MeasuredPoint> run() {
    request("Hello messcap-inspect");
    request("Take");
    if (plan_.probing.tip_radius) request("Set TipRadius " + std::to_string(*plan_.probing.tip_radius));
    if (plan_.probing.search) request("Set SearchDist " + std::to_string(*plan_.probing.search));
    tip_radius_ = plan_.probing.tip_radius ? *plan_.probing.tip_radius : status_tip_radius();
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
  // --- the wire ---
  void send(const std::string& line) {
    if (!link_->send_line(line)) throw InspectSessionError("messd went away (" + link_->close_reason() + ")");
  }

  // Reads lines until `done` holds, handling every event on the way.
  template <class Pred>
  void read_until(Pred done, std::chrono::seconds timeout, const std::string& waiting_for) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
      if (std::chrono::steady_clock::now() > deadline)
        throw InspectSessionError("no answer from messd within " + std::to_string(timeout.count()) + " s while waiting for " + waiting_for);
      const auto status = link_->poll_lines(std::chrono::milliseconds{200}, [this](std::string_view l) { on_line(l); });
      if (status == client::ReadStatus::Closed)
        throw InspectSessionError("messd closed the connection (" + link_->close_reason() + ") while waiting for " + waiting_for);
    }
  }

  // One command, one reply line: Ok (returned) or Err (thrown, naming the command).
  std::string request(const std::string& line) {
    reply_.reset();
    send(line);
    read_until([this] { return reply_.has_value(); }, kReplyTimeout, "the reply to '" + line + "'");
    if (reply_->rfind("Err ", 0) == 0) throw InspectSessionError("messd refused '" + line + "': " + *reply_);
    return *reply_;
  }

  void on_line(std::string_view line) {
    if (line.rfind("Ok ", 0) == 0 || line == "Ok" || line.rfind("Err ", 0) == 0) {
      reply_ = std::string(line);
      return;
    }
    if (line.rfind("Done ", 0) == 0 || line.rfind("Failed ", 0) == 0) {
      std::istringstream words{std::string(line)};
      std::string verb;
      std::uint64_t id = 0;
      if (words >> verb >> id) ended_[id] = std::string(line);
      return;
    }
    if (line.rfind("Fault ", 0) == 0) fault_ = std::string(line);
    auto message = protocol::parse_message(line);
    if (auto* hit = std::get_if<protocol::HitMsg>(&message); hit && hit->id != 0) hits_[hit->id].push_back(*hit);
  }

  // A queued command (MoveTo, Probe): Ok, then its Done; a Failed ends the measurement.
  void queued(const std::string& verb, const std::string& words) {
    const std::uint64_t id = next_id_++;
    const std::string line = verb + " " + std::to_string(id) + " " + words;
    request(line);
    read_until([&] { return ended_.count(id) > 0; }, kMoveTimeout, "the end of '" + line + "'");
    const std::string end = ended_[id];
    if (end.rfind("Done ", 0) != 0)
      throw InspectSessionError("'" + line + "' ended with '" + end + "'" + (fault_.empty() ? "" : " (" + fault_ + ")"));
  }

  double status_tip_radius() {
    std::istringstream words(request("Status"));
    std::string w;
    while (words >> w)
      if (w == "TipRadius" && words >> w) return std::stod(w);
    return 0.0;
  }

  // --- moves ---
  std::string feed_word() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, " F%.1f", feed_);
    return buf;
  }
  void move_z(double z) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "Z%.4f", z);
    queued("MoveTo", buf + feed_word());
  }
  void move_to(const Vector3d& part) { queued("MoveTo", xyz_words(frame_.point_to_parent(part)) + feed_word()); }
  Vector3d above(const Vector3d& part) const { return {part.x(), part.y(), plan_.probing.safe_z}; }

  // Ball-centre positions of one probe point: the start (clearance off the surface) and the
  // target (touching the nominal surface), part coordinates.
  Vector3d start_of(const metrology::ProbeTarget& t) const {
    return t.point - (tip_radius_ + plan_.probing.clearance) * t.approach;
  }
  Vector3d target_of(const metrology::ProbeTarget& t) const { return t.point - tip_radius_ * t.approach; }

  void measure_feature(const PlanFeature& f) {
    if (f.probes.empty()) throw InspectSessionError("feature '" + f.name + "' has no probe points to measure");
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
    const std::uint64_t id = next_id_;
    queued("Probe", xyz_words(frame_.point_to_parent(target_of(t))) + feed_word());
    const auto it = hits_.find(id);
    if (it == hits_.end() || it->second.size() != 1)
      throw InspectSessionError("Probe " + std::to_string(id) + " of '" + f.name + "' ended with " +
                                std::to_string(it == hits_.end() ? 0 : it->second.size()) + " hits (expected 1)");
    const auto& h = it->second.front();
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
      reply_.reset();
      send(buf);
      read_until([this] { return reply_.has_value(); }, kReplyTimeout, "the reply to SetFrame");
      if (reply_->rfind("Err ", 0) == 0) log_ << "messcap: messd keeps no part frames (" << *reply_ << "); the frame is in the report\n";
    }
    request("Release");
    link_->finish();
  }

  const InspectionPlan& plan_;
  const LiveOptions& options_;
  std::ostream& log_;
  std::unique_ptr<client::Connection> link_;
  Frame frame_;
  double tip_radius_ = 0, feed_ = 0;
  std::uint64_t next_id_ = 1;
  std::optional<std::string> reply_;
  std::map<std::uint64_t, std::string> ended_;
  std::map<std::uint64_t, std::vector<protocol::HitMsg>> hits_;
  std::string fault_;
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

}  // namespace imess::messcap
