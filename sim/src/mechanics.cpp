// Mechanics integration at the card's sub-tick; the probe edge is located on the travelled
// segment by bisection, so a latch is exact however fast the carriage moves.
#include "imess/sim/mechanics.hpp"

#include <algorithm>
#include <cmath>

namespace imess::sim {

Mechanics::Mechanics(MechanicsConfig config, Scene scene)
    : config_(std::move(config)),
      scene_(std::move(scene)),
      pos_(config_.start),
      analog_(config_.probe.analog, config_.probe.ball_radius) {
  contact_ = deflection() > config_.probe.pretravel;
  if (config_.probe.type == ProbeType::Analog) reading_ = analog_.read(scene_, ball_centre());
}

double Mechanics::deflection_at(const hal::AxisVec& p) const noexcept {
  return config_.probe.ball_radius - scene_.distance(config_.layout.cartesian(p));
}

double Mechanics::deflection() const noexcept { return deflection_at(pos_); }

bool Mechanics::limit_neg(int a) const noexcept {
  return pos_[a] < config_.axes[a].travel_min - config_.axes[a].limit_margin;
}
bool Mechanics::limit_pos(int a) const noexcept {
  return pos_[a] > config_.axes[a].travel_max + config_.axes[a].limit_margin;
}
bool Mechanics::home_switch(int a) const noexcept {
  const auto& ax = config_.axes[a];
  return ax.home_direction < 0 ? pos_[a] < ax.travel_min - ax.home_cam_margin
                               : pos_[a] > ax.travel_max + ax.home_cam_margin;
}
bool Mechanics::index_mark(int a) const noexcept {
  const auto& ax = config_.axes[a];
  double u = (pos_[a] - ax.travel_min) / ax.index_pitch;
  return std::abs(u - std::round(u)) * ax.index_pitch < ax.index_width / 2;
}

void Mechanics::push_by_hand(const Vec3& delta, double speed) noexcept {
  hand_target_ = pos_ + config_.layout.machine(delta);
  hand_speed_ = speed;
  hand_active_ = delta.norm() > 0 && speed > 0;
}

void Mechanics::step(double dt) noexcept {
  const hal::AxisVec before = pos_;
  const double alpha = 1.0 - std::exp(-dt / config_.motor_time_constant);
  bool any_free = false;
  for (int a = 0; a < config_.layout.count; ++a) {
    if (position_driven_[a])
      vel_[a] = dt > 0 ? (commanded_[a] - pos_[a]) / dt : 0.0;
    else if (driven_[a])
      vel_[a] += (demand_[a] - vel_[a]) * alpha;
    else
      any_free = true;
  }
  if (hand_active_ && any_free) {
    hal::AxisVec to_go = hand_target_ - pos_;
    double dist = to_go.norm(), reach = hand_speed_ * dt;
    hal::AxisVec v = dist <= reach ? hal::AxisVec(to_go / dt) : hal::AxisVec(to_go / dist * hand_speed_);
    for (int a = 0; a < config_.layout.count; ++a)
      if (!driven_[a] && !position_driven_[a]) vel_[a] = v[a];
    if (dist <= reach) hand_active_ = false;
  } else {
    for (int a = 0; a < config_.layout.count; ++a)
      if (!driven_[a] && !position_driven_[a]) vel_[a] = 0;
  }
  for (int a = 0; a < config_.layout.count; ++a) {
    pos_[a] = position_driven_[a] ? commanded_[a] : pos_[a] + vel_[a] * dt;
    const auto& ax = config_.axes[a];
    double lo = ax.travel_min - ax.hard_margin, hi = ax.travel_max + ax.hard_margin;
    if (pos_[a] < lo || pos_[a] > hi) {
      pos_[a] = std::clamp(pos_[a], lo, hi);
      vel_[a] = 0;
      ++hard_stop_hits_;
    }
  }
  edge_.valid = false;
  if (config_.probe.type == ProbeType::Analog) reading_ = analog_.read(scene_, ball_centre());
  double defl = deflection();
  const auto& pr = config_.probe;
  if (!contact_ && defl > pr.pretravel)
    find_edge(before, pos_, true);
  else if (contact_ && defl < pr.pretravel - pr.hysteresis)
    find_edge(before, pos_, false);
}

void Mechanics::find_edge(const hal::AxisVec& from, const hal::AxisVec& to, bool to_contact) noexcept {
  const auto& pr = config_.probe;
  double threshold = to_contact ? pr.pretravel : pr.pretravel - pr.hysteresis;
  auto beyond = [&](double s) {
    double d = deflection_at(from + s * (to - from));
    return to_contact ? d > threshold : d < threshold;
  };
  double lo = 0, hi = 1;
  for (int i = 0; i < 48 && hi - lo > 1e-12; ++i) {  // lo before the edge, hi beyond it
    double mid = 0.5 * (lo + hi);
    (beyond(mid) ? hi : lo) = mid;
  }
  contact_ = to_contact;
  edge_ = {true, to_contact, from + hi * (to - from)};
}

}  // namespace imess::sim
