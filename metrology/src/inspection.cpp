// evaluate_inspection: the part frame, one fit per feature in part coordinates, the per-point
// deviations and every characteristic.
#include "imess/metrology/inspection.hpp"

#include <algorithm>

#include <Eigen/Geometry>

#include "inspection_characteristics.hpp"
#include "inspection_fit.hpp"

namespace imess::metrology {
namespace {

std::string feature_names(const InspectionPlan& plan) {
  std::string s;
  for (const auto& f : plan.features) s += (s.empty() ? "" : ", ") + f.name;
  return s;
}

AlignmentResult alignment_of(const InspectionPlan& plan, std::span<const MeasuredPoint> points) {
  AlignmentResult a;
  a.part_to_machine = plan.placement;
  if (plan.alignment) {
    a.part_to_machine = align_part(plan, points);
    a.measured = true;
  }
  a.shift = a.part_to_machine.translation() - plan.placement.translation();
  // part_to_machine = placement * delta: delta turns the nominal part axes into the measured ones.
  const Eigen::Matrix3d delta = plan.placement.rotation().transpose() * a.part_to_machine.rotation();
  const Eigen::AngleAxisd aa(delta);
  a.rotation_deg = aa.angle() * 180.0 / M_PI * aa.axis();
  return a;
}

}  // namespace

std::size_t InspectionResult::out_of_tolerance() const {
  return static_cast<std::size_t>(std::count_if(characteristics.begin(), characteristics.end(),
                                                [](const auto& c) { return c.evaluated() && !c.in_tolerance; }));
}

std::size_t InspectionResult::not_evaluated() const {
  return static_cast<std::size_t>(
      std::count_if(characteristics.begin(), characteristics.end(), [](const auto& c) { return !c.evaluated(); }));
}

InspectionResult evaluate_inspection(const InspectionPlan& plan, std::span<const MeasuredPoint> points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!plan.find(points[i].feature))
      throw InspectionError("point " + std::to_string(i + 1) + " belongs to '" + points[i].feature +
                            "', which the plan does not have; its features: " + feature_names(plan));
  InspectionResult out;
  out.alignment = alignment_of(plan, points);
  const Frame& frame = out.alignment.part_to_machine;

  for (const auto& f : plan.features) {
    std::vector<detail::FitInput> inputs;
    std::vector<const MeasuredPoint*> mine;
    for (const auto& p : points) {
      if (p.feature != f.name) continue;
      mine.push_back(&p);
      std::optional<Eigen::Vector3d> approach;
      if (p.approach) approach = frame.direction_from_parent(*p.approach);
      inputs.push_back({frame.point_from_parent(p.point), approach, p.radius});
    }
    FeatureResult fr;
    fr.name = f.name;
    fr.point_count = inputs.size();
    auto fit = detail::fit_feature(f.name, f.nominal, inputs);
    if (fit) {
      fr.actual = fit->geometry;
      fr.stats = fit->stats;
      fr.compensated = fit->compensated;
      fr.axis_ends = fit->axis_ends;
      fr.surface = fit->surface;
    } else {
      fr.error = fit.error().message;
    }
    for (std::size_t i = 0; i < mine.size(); ++i) {
      PointResult pr;
      pr.feature = f.name;
      pr.measured = *mine[i];
      pr.part = fit ? fit->surface[i] : inputs[i].point;
      pr.deviation = signed_distance(f.nominal, pr.part);
      if (fit) pr.form = signed_distance(fit->geometry, pr.part);
      out.points.push_back(std::move(pr));
    }
    out.features.push_back(std::move(fr));
  }
  for (const auto& c : plan.characteristics)
    out.characteristics.push_back(detail::evaluate_characteristic(c, plan, out.features));
  return out;
}

}  // namespace imess::metrology
