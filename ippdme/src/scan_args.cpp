// The scanning methods' arguments: positional numbers (points, directions, angles, counts) read
// into the typed commands of scan_commands.hpp with the spec's checks, and written back.
#include "scan_args.hpp"

#include <climits>
#include <cmath>
#include <initializer_list>
#include <string_view>

namespace imess::ippdme {
namespace scan_args_impl {
namespace {

using Fault = std::optional<ErrorCode>;

// How far from orthogonal a circle's start direction and its normal, or a line and its surface
// normal, may be (the cosine of their angle): about 0.6 degrees, room for the rounding of the
// numbers a client writes; the server projects onto the exact geometry.
constexpr double kOrthogonalCosine = 0.01;

// Positional numbers, taken in order.
class Numbers {
 public:
  explicit Numbers(const std::vector<Value>& args) : args_(args) {}
  double next() { return args_[at_++].number; }
  Point3 point() {
    const double x = next(), y = next(), z = next();
    return {x, y, z};
  }
  Vector3 vector() {
    const double i = next(), j = next(), k = next();
    return {i, j, k};
  }

 private:
  const std::vector<Value>& args_;
  std::size_t at_ = 0;
};

// The call holds only numbers, as many as one of `counts`: that count, else 0.
std::size_t number_count(const Value& call, std::initializer_list<std::size_t> counts) {
  for (const auto& a : call.args)
    if (a.kind != ValueKind::Number) return 0;
  for (std::size_t n : counts)
    if (call.args.size() == n) return n;
  return 0;
}

double length(const Vector3& v) { return std::hypot(v.i, v.j, v.k); }
bool without_norm(const Vector3& v) {
  const double n = length(v);
  return !(n > 0) || !std::isfinite(n);
}
Vector3 from_to(const Point3& a, const Point3& b) { return {b[0] - a[0], b[1] - a[1], b[2] - a[2]}; }
double dot(const Vector3& a, const Vector3& b) { return a.i * b.i + a.j * b.j + a.k * b.k; }
Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a.j * b.k - a.k * b.j, a.k * b.i - a.i * b.k, a.i * b.j - a.j * b.i};
}
// Orthogonal within kOrthogonalCosine; both have a norm.
bool orthogonal(const Vector3& a, const Vector3& b) {
  const double c = dot(a, b) / length(a) / length(b);
  return std::abs(c) <= kOrthogonalCosine;
}
// The distance of p from the line through `at` along `axis` (axis with a norm) is not zero.
bool off_axis(const Point3& p, const Point3& at, const Vector3& axis) { return !without_norm(cross(from_to(at, p), axis)); }

// The first given direction (null: not given) without norm: 1010.
Fault first_without_norm(std::initializer_list<const Vector3*> vectors) {
  for (const Vector3* v : vectors)
    if (v && without_norm(*v)) return ErrorCode::VectorHasNoNorm;
  return std::nullopt;
}

// n: the n-th meeting of the stop body: a whole number from 1 (an int).
bool read_count(double n, int& out) {
  if (!(n >= 1) || n > INT_MAX || std::floor(n) != n) return false;
  out = static_cast<int>(n);
  return true;
}

// ---- hints ----------------------------------------------------------------------------------

Fault read_two_hints(const Value& call, double& a, double& b) {
  if (!number_count(call, {2})) return ErrorCode::IncorrectArguments;
  a = call.args[0].number;
  b = call.args[1].number;
  if (a < 0 || b < 0) return ErrorCode::BadArgument;
  return std::nullopt;
}

Fault read_circle_hint(const Value& call, Checked& out) {
  ScanOnCircleHint c;
  if (auto f = read_two_hints(call, c.displacement, c.form)) return f;
  out.built = c;
  return std::nullopt;
}

Fault read_line_hint(const Value& call, Checked& out) {
  ScanOnLineHint c;
  if (auto f = read_two_hints(call, c.angle, c.form)) return f;
  out.built = c;
  return std::nullopt;
}

Fault read_unknown_hint(const Value& call, Checked& out) {
  if (!number_count(call, {1})) return ErrorCode::IncorrectArguments;
  const double r = call.args[0].number;
  if (!(r > 0)) return ErrorCode::BadArgument;
  out.built = ScanUnknownHint{r};
  return std::nullopt;
}

// ScanUnknownDensity(Dis(d), Angle(a), AngleBaseLength(l)): each at most once, in any order.
Fault read_unknown_density(const Value& call, Checked& out) {
  ScanUnknownDensity c;
  if (call.args.empty()) return ErrorCode::IncorrectArguments;
  for (const auto& a : call.args) {
    if (a.kind != ValueKind::Call) return ErrorCode::IncorrectArguments;
    std::optional<double>* slot = a.text == "Dis"               ? &c.dis
                                  : a.text == "Angle"           ? &c.angle
                                  : a.text == "AngleBaseLength" ? &c.angle_base_length
                                                                : nullptr;
    if (!slot) return ErrorCode::ArgumentNotRecognized;
    if (a.args.size() != 1 || a.args[0].kind != ValueKind::Number || slot->has_value()) return ErrorCode::IncorrectArguments;
    *slot = a.args[0].number;
  }
  for (const auto* v : {&c.dis, &c.angle, &c.angle_base_length})
    if (*v && !(**v > 0)) return ErrorCode::BadArgument;
  out.built = c;
  return std::nullopt;
}

// ---- known contours -------------------------------------------------------------------------

// A circle's start lies in its plane (the start direction orthogonal to the normal); a helix's
// anywhere off its axis (the centre is a point of the axis).
template <class T>
Fault read_circle_like(const Value& call, T& c, std::size_t count, bool in_plane) {
  if (!number_count(call, {count})) return ErrorCode::IncorrectArguments;
  Numbers n(call.args);
  c.center = n.point();
  c.start = n.point();
  c.normal = n.vector();
  c.delta = n.next();
  c.sfa = n.next();
  c.step = n.next();
  if (auto f = first_without_norm({&c.normal})) return f;
  const Vector3 radius = from_to(c.center, c.start);
  if (in_plane ? without_norm(radius) || !orthogonal(radius, c.normal) : !off_axis(c.start, c.center, c.normal))
    return ErrorCode::BadArgument;
  if (c.delta == 0 || c.step == 0) return ErrorCode::BadArgument;
  return std::nullopt;
}

Fault read_circle(const Value& call, Checked& out) {
  ScanOnCircle c;
  if (auto f = read_circle_like(call, c, 12, true)) return f;
  out.built = c;
  return std::nullopt;
}

Fault read_helix(const Value& call, Checked& out) {
  ScanOnHelix c;
  if (auto f = read_circle_like(call, c, 13, false)) return f;
  c.pitch = call.args[12].number;
  // A surface angle of 90 or 270: a plane face, on which no helix runs.
  const double along = std::remainder(c.sfa, 180.0);
  if (std::abs(std::abs(along) - 90.0) < 1e-9) return ErrorCode::BadArgument;
  out.built = c;
  return std::nullopt;
}

Fault read_line(const Value& call, Checked& out) {
  if (!number_count(call, {10})) return ErrorCode::IncorrectArguments;
  Numbers n(call.args);
  ScanOnLine c;
  c.start = n.point();
  c.end = n.point();
  c.normal = n.vector();
  c.step = n.next();
  if (auto f = first_without_norm({&c.normal})) return f;
  const Vector3 way = from_to(c.start, c.end);
  if (without_norm(way) || !orthogonal(way, c.normal) || !(c.step > 0)) return ErrorCode::BadArgument;
  out.built = c;
  return std::nullopt;
}

// ---- unknown contours -----------------------------------------------------------------------

// The checks every unknown-contour scan shares: the start differs from the direction point, the
// step is not negative, n is a whole number from 1.
Fault unknown_contour_domain(const Point3& start, const Point3& direction, double step, double count, int& out_count) {
  if (without_norm(from_to(start, direction)) || !(step >= 0) || !read_count(count, out_count)) return ErrorCode::BadArgument;
  return std::nullopt;
}

// The plane scans: S, SIJK, [N (1.4.3)], D, StepW, then the stop body, [n], EIJK.
template <class T>
void read_plane_start(Numbers& n, T& c, bool with_plane) {
  c.start = n.point();
  c.start_normal = n.vector();
  if (with_plane) c.plane_normal = n.vector();
  c.direction = n.point();
  c.step = n.next();
}
template <class T>
const Vector3* given_plane(const T& c) {
  return c.plane_normal ? &*c.plane_normal : nullptr;
}

// The 1.4.0 form's plane (start_normal and the way to the direction point) must exist.
template <class T>
Fault check_plane(const T& c) {
  if (!c.plane_normal && without_norm(scan_plane_normal(c))) return ErrorCode::BadArgument;
  return std::nullopt;
}

Fault read_plane_end_sphere(const Value& call, Checked& out) {
  const std::size_t count = number_count(call, {17, 21});  // 1.4.0, 1.4.3
  if (!count) return ErrorCode::IncorrectArguments;
  const bool v143 = count == 21;
  Numbers n(call.args);
  ScanInPlaneEndIsSphere c;
  read_plane_start(n, c, v143);
  c.end_center = n.point();
  c.diameter = n.next();
  const double times = v143 ? n.next() : 1;
  c.end_normal = n.vector();
  if (auto f = first_without_norm({&c.start_normal, given_plane(c), &c.end_normal})) return f;
  if (auto f = unknown_contour_domain(c.start, c.direction, c.step, times, c.count)) return f;
  if (!(c.diameter > 0)) return ErrorCode::BadArgument;
  if (auto f = check_plane(c)) return f;
  out.built = c;
  return std::nullopt;
}

Fault read_plane_end_plane(const Value& call, Checked& out) {
  const std::size_t count = number_count(call, {20, 23});
  if (!count) return ErrorCode::IncorrectArguments;
  const bool v143 = count == 23;
  Numbers n(call.args);
  ScanInPlaneEndIsPlane c;
  read_plane_start(n, c, v143);
  c.stop_point = n.point();
  c.stop_normal = n.vector();
  const double times = n.next();
  c.end_normal = n.vector();
  if (auto f = first_without_norm({&c.start_normal, given_plane(c), &c.stop_normal, &c.end_normal})) return f;
  if (auto f = unknown_contour_domain(c.start, c.direction, c.step, times, c.count)) return f;
  if (auto f = check_plane(c)) return f;
  out.built = c;
  return std::nullopt;
}

Fault read_plane_end_cyl(const Value& call, Checked& out) {
  const std::size_t count = number_count(call, {21, 24});
  if (!count) return ErrorCode::IncorrectArguments;
  const bool v143 = count == 24;
  Numbers n(call.args);
  ScanInPlaneEndIsCyl c;
  read_plane_start(n, c, v143);
  c.axis_point = n.point();
  c.axis = n.vector();
  c.diameter = n.next();
  const double times = n.next();
  c.end_normal = n.vector();
  if (auto f = first_without_norm({&c.start_normal, given_plane(c), &c.axis, &c.end_normal})) return f;
  if (auto f = unknown_contour_domain(c.start, c.direction, c.step, times, c.count)) return f;
  if (!(c.diameter > 0)) return ErrorCode::BadArgument;
  if (auto f = check_plane(c)) return f;
  out.built = c;
  return std::nullopt;
}

// The cylinder scans: C, CIJK, S, SIJK, D, StepW, then the stop body, n, EIJK.
template <class T>
void read_cyl_start(Numbers& n, T& c) {
  c.axis_point = n.point();
  c.axis = n.vector();
  c.start = n.point();
  c.start_normal = n.vector();
  c.direction = n.point();
  c.step = n.next();
}

Fault read_cyl_end_sphere(const Value& call, Checked& out) {
  const std::size_t count = number_count(call, {23, 24});  // 1.4.0 (no n), 1.4.3
  if (!count) return ErrorCode::IncorrectArguments;
  Numbers n(call.args);
  ScanInCylEndIsSphere c;
  read_cyl_start(n, c);
  c.end_center = n.point();
  c.diameter = n.next();
  const double times = count == 24 ? n.next() : 1;
  c.end_normal = n.vector();
  if (auto f = first_without_norm({&c.axis, &c.start_normal, &c.end_normal})) return f;
  if (auto f = unknown_contour_domain(c.start, c.direction, c.step, times, c.count)) return f;
  if (!(c.diameter > 0) || !off_axis(c.start, c.axis_point, c.axis)) return ErrorCode::BadArgument;
  out.built = c;
  return std::nullopt;
}

Fault read_cyl_end_plane(const Value& call, Checked& out) {
  if (!number_count(call, {26})) return ErrorCode::IncorrectArguments;
  Numbers n(call.args);
  ScanInCylEndIsPlane c;
  read_cyl_start(n, c);
  c.stop_point = n.point();
  c.stop_normal = n.vector();
  const double times = n.next();
  c.end_normal = n.vector();
  if (auto f = first_without_norm({&c.axis, &c.start_normal, &c.stop_normal, &c.end_normal})) return f;
  if (auto f = unknown_contour_domain(c.start, c.direction, c.step, times, c.count)) return f;
  if (!off_axis(c.start, c.axis_point, c.axis)) return ErrorCode::BadArgument;
  out.built = c;
  return std::nullopt;
}

struct Reader {
  std::string_view method;
  Fault (*read)(const Value&, Checked&);
};
constexpr Reader kReaders[] = {
    {"ScanOnCircleHint", read_circle_hint},
    {"ScanOnLineHint", read_line_hint},
    {"ScanUnknownHint", read_unknown_hint},
    {"ScanUnknownDensity", read_unknown_density},
    {"ScanOnCircle", read_circle},
    {"ScanOnHelix", read_helix},
    {"ScanOnLine", read_line},
    {"ScanInPlaneEndIsSphere", read_plane_end_sphere},
    {"ScanInPlaneEndIsPlane", read_plane_end_plane},
    {"ScanInPlaneEndIsCyl", read_plane_end_cyl},
    {"ScanInCylEndIsSphere", read_cyl_end_sphere},
    {"ScanInCylEndIsPlane", read_cyl_end_plane},
};

// ---- writing --------------------------------------------------------------------------------

class Writer {
 public:
  Writer& number(double v) {
    out_.push_back(Value::of_number(v));
    return *this;
  }
  Writer& point(const Point3& p) { return number(p[0]).number(p[1]).number(p[2]); }
  Writer& vector(const Vector3& v) { return number(v.i).number(v.j).number(v.k); }
  std::vector<Value> done() { return std::move(out_); }

 private:
  std::vector<Value> out_;
};

}  // namespace
}  // namespace scan_args_impl

// Named here, no using-directive: in a unity build that would reach the next file's helpers.
using ScanWriter = scan_args_impl::Writer;

std::optional<ErrorCode> read_scan_args(const Value& call, Checked& out) {
  for (const auto& r : scan_args_impl::kReaders)
    if (r.method == call.text) return r.read(call, out);
  return ErrorCode::IllegalCommand;  // unreachable: every ScanArgs declaration has a reader (test_ippdme)
}

std::vector<Value> scan_args(const OnScanReport& c) {
  std::vector<Value> out;
  for (Item i : c.items) out.push_back(Value::call(item_name(i)));
  return out;
}
std::vector<Value> scan_args(const ScanOnCircleHint& c) { return ScanWriter().number(c.displacement).number(c.form).done(); }
std::vector<Value> scan_args(const ScanOnLineHint& c) { return ScanWriter().number(c.angle).number(c.form).done(); }
std::vector<Value> scan_args(const ScanUnknownHint& c) { return ScanWriter().number(c.min_radius).done(); }
std::vector<Value> scan_args(const ScanUnknownDensity& c) {
  std::vector<Value> out;
  if (c.dis) out.push_back(Value::call("Dis", {Value::of_number(*c.dis)}));
  if (c.angle) out.push_back(Value::call("Angle", {Value::of_number(*c.angle)}));
  if (c.angle_base_length) out.push_back(Value::call("AngleBaseLength", {Value::of_number(*c.angle_base_length)}));
  return out;
}
std::vector<Value> scan_args(const ScanOnCircle& c) {
  return ScanWriter().point(c.center).point(c.start).vector(c.normal).number(c.delta).number(c.sfa).number(c.step).done();
}
std::vector<Value> scan_args(const ScanOnHelix& c) {
  return ScanWriter().point(c.center).point(c.start).vector(c.normal).number(c.delta).number(c.sfa).number(c.step)
      .number(c.pitch).done();
}
std::vector<Value> scan_args(const ScanOnLine& c) {
  return ScanWriter().point(c.start).point(c.end).vector(c.normal).number(c.step).done();
}
// A plane scan without plane normal is written in its 1.4.0 form (the sphere's without n).
std::vector<Value> scan_args(const ScanInPlaneEndIsSphere& c) {
  ScanWriter w;
  w.point(c.start).vector(c.start_normal);
  if (c.plane_normal) w.vector(*c.plane_normal);
  w.point(c.direction).number(c.step).point(c.end_center).number(c.diameter);
  if (c.plane_normal) w.number(c.count);
  return w.vector(c.end_normal).done();
}
std::vector<Value> scan_args(const ScanInPlaneEndIsPlane& c) {
  ScanWriter w;
  w.point(c.start).vector(c.start_normal);
  if (c.plane_normal) w.vector(*c.plane_normal);
  return w.point(c.direction).number(c.step).point(c.stop_point).vector(c.stop_normal).number(c.count)
      .vector(c.end_normal).done();
}
std::vector<Value> scan_args(const ScanInPlaneEndIsCyl& c) {
  ScanWriter w;
  w.point(c.start).vector(c.start_normal);
  if (c.plane_normal) w.vector(*c.plane_normal);
  return w.point(c.direction).number(c.step).point(c.axis_point).vector(c.axis).number(c.diameter).number(c.count)
      .vector(c.end_normal).done();
}
std::vector<Value> scan_args(const ScanInCylEndIsSphere& c) {
  return ScanWriter().point(c.axis_point).vector(c.axis).point(c.start).vector(c.start_normal).point(c.direction)
      .number(c.step).point(c.end_center).number(c.diameter).number(c.count).vector(c.end_normal).done();
}
std::vector<Value> scan_args(const ScanInCylEndIsPlane& c) {
  return ScanWriter().point(c.axis_point).vector(c.axis).point(c.start).vector(c.start_normal).point(c.direction)
      .number(c.step).point(c.stop_point).vector(c.stop_normal).number(c.count).vector(c.end_normal).done();
}

}  // namespace imess::ippdme
