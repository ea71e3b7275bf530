// relate(): each feature reduced to a centre, an axis or a plane for the distance and to an
// axis or a plane for the angle; then one small rule per pair of those.
#include "feature_relation.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include <nlohmann/json.hpp>

#include "imess/metrology/compare.hpp"

namespace imess::messcap {
namespace {

using Eigen::Vector3d;
using exchange::FitKind;
using exchange::FitReport;

enum class Place { Point, Axis, Plane };

struct Element {
  Place place;
  Vector3d at;   // the centre, the axis' point, the plane's point
  Vector3d dir;  // unit: the axis or the normal (unused for a point)
};

// What a feature is when distances are measured: circles and spheres by their centre.
Element distance_element(const FitReport& f) {
  switch (f.kind) {
    case FitKind::Sphere:
    case FitKind::Circle:
    case FitKind::Circle2d: return {Place::Point, *f.center, Vector3d::Zero()};
    case FitKind::Plane: return {Place::Plane, *f.point, *f.normal};
    case FitKind::Line:
    case FitKind::Line2d: return {Place::Axis, *f.point, *f.direction};
    case FitKind::Cylinder:
    case FitKind::Cone: return {Place::Axis, *f.point, *f.axis};
  }
  return {Place::Point, Vector3d::Zero(), Vector3d::Zero()};
}

// What a feature is when angles are measured: a circle by its axis (its normal); a sphere has
// no direction.
std::optional<Element> angle_element(const FitReport& f) {
  if (f.kind == FitKind::Sphere) return std::nullopt;
  if (f.kind == FitKind::Circle || f.kind == FitKind::Circle2d) return Element{Place::Axis, *f.center, *f.normal};
  return distance_element(f);
}

const char* place_name(Place p) { return p == Place::Point ? "point" : p == Place::Axis ? "axis" : "plane"; }

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

// Angle of two directions folded into 0 … 90 degrees (fitted directions have no meaningful sign).
double line_angle_deg(const Vector3d& u, const Vector3d& v) { return degrees(metrology::direction_angle(u, v)); }

// 0 … 90: two axes, two plane normals, or an axis against a plane (the complement of the angle
// to its normal: 0 = the axis lies parallel to the plane, 90 = square to it).
double element_angle_deg(const Element& a, const Element& b) {
  const double between = line_angle_deg(a.dir, b.dir);
  const bool one_plane = (a.place == Place::Plane) != (b.place == Place::Plane);
  return one_plane ? 90.0 - between : between;
}

Vector3d foot_on_plane(const Vector3d& p, const Element& plane) {
  return p - plane.dir * plane.dir.dot(p - plane.at);
}

Vector3d foot_on_axis(const Vector3d& p, const Element& axis) {
  return axis.at + axis.dir * axis.dir.dot(p - axis.at);
}

Vector3d foot_on(const Vector3d& p, const Element& e) {
  return e.place == Place::Plane ? foot_on_plane(p, e) : e.place == Place::Axis ? foot_on_axis(p, e) : e.at;
}

struct Span {
  Vector3d from, to;  // from on the first element, to on the second
};

// Closest points of two non-parallel lines (the common perpendicular).
Span skew_span(const Element& a, const Element& b) {
  const Vector3d w = a.at - b.at;
  const double c = a.dir.dot(b.dir), d = a.dir.dot(w), e = b.dir.dot(w);
  const double denom = 1.0 - c * c;  // > 0: the caller checked they are not parallel
  const double s = (c * e - d) / denom, t = (e - c * d) / denom;
  return {a.at + s * a.dir, b.at + t * b.dir};
}

std::string angle_text(double deg) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", deg);
  return buf;
}

void set_distance(Relation& r, const Element& a, const Element& b) {
  const Place pa = a.place, pb = b.place;
  std::string rule = std::string(place_name(pa)) + "-" + place_name(pb);
  Span span;
  if (pa == Place::Point || pb == Place::Point) {
    // A centre against anything: the perpendicular from the centre (or between the centres).
    span = pa == Place::Point ? Span{a.at, foot_on(a.at, b)} : Span{foot_on(b.at, a), b.at};
  } else {
    const double angle = element_angle_deg(a, b);
    const bool parallel = angle <= kParallelDeg;  // for an axis and a plane: the axis lies along it
    if (pa == Place::Axis && pb == Place::Axis && !parallel) {
      span = skew_span(a, b);
      rule += " skew";
    } else if (!parallel) {
      r.notes.push_back(rule + ": not parallel (" + angle_text(angle) + " deg > " + angle_text(kParallelDeg) +
                        " deg), so they intersect and have no distance");
      return;
    } else if (pa == Place::Axis && pb == Place::Plane) {
      span = {a.at, foot_on_plane(a.at, b)};  // the axis' point to the plane
      rule += " parallel";
    } else {
      span = {foot_on(b.at, a), b.at};  // B's point to A
      rule += " parallel";
    }
  }
  r.distance = (span.to - span.from).norm();
  r.from = span.from;
  r.to = span.to;
  r.distance_rule = std::move(rule);
}

nlohmann::ordered_json array(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

Relation relate(const FitReport& a, const FitReport& b) {
  Relation r;
  r.a = a.kind;
  r.b = b.kind;
  set_distance(r, distance_element(a), distance_element(b));
  const auto ea = angle_element(a), eb = angle_element(b);
  if (ea && eb) {
    r.angle_deg = element_angle_deg(*ea, *eb);
    r.angle_rule = std::string(place_name(ea->place)) + "-" + place_name(eb->place);
  } else {
    r.notes.push_back("a sphere has no direction, so there is no angle");
  }
  return r;
}

std::string to_json(const Relation& r) {
  nlohmann::ordered_json j;
  j["a"] = std::string(exchange::to_string(r.a));
  j["b"] = std::string(exchange::to_string(r.b));
  if (r.distance) {
    j["distance"] = *r.distance;
    j["distance_rule"] = r.distance_rule;
    j["from"] = array(*r.from);
    j["to"] = array(*r.to);
  }
  if (r.angle_deg) {
    j["angle_deg"] = *r.angle_deg;
    j["angle_rule"] = r.angle_rule;
  }
  if (!r.notes.empty()) j["notes"] = r.notes;
  return j.dump();
}

}  // namespace imess::messcap
