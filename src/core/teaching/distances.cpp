#include "core/teaching/distances.hpp"

#include <cmath>
#include <limits>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/geometry/geometry.hpp"

namespace csl {
namespace {

// The direction of angle a in [0, 2pi), the range the handout's modulus works in.
double wrap_positive(double a) {
  double w = wrap_angle(a);  // [-pi, pi)
  if (w < 0.0) w += kTwoPi;
  return w < kTwoPi ? w : 0.0;  // -1e-17 + 2pi rounds to 2pi, which is the direction 0
}

S1Case classify(double distance) {
  if (distance <= kS1CaseTolerance) return S1Case::Equal;
  if (distance >= kPi - kS1CaseTolerance) return S1Case::Antipodal;
  return S1Case::General;
}

}  // namespace

S1DistanceReport s1_distance_report(double q1, double q2) {
  S1DistanceReport r;
  r.q1 = q1;
  r.q2 = q2;
  r.wrapped1 = wrap_positive(q1);
  r.wrapped2 = wrap_positive(q2);
  // (a) As the handout writes it, on the angles as given: the modulus takes away whole turns.
  r.raw_difference = std::fabs(q1 - q2);
  r.modulus = std::fmod(r.raw_difference, kTwoPi);  // exact remainder, in [0, 2pi)
  r.other_way = kTwoPi - r.modulus;
  r.modular_distance = r.modulus < r.other_way ? r.modulus : r.other_way;
  // (b) The unit vectors (first columns of the rotations) and their dot product.
  det::sincos(q1, r.sin1, r.cos1);
  det::sincos(q2, r.sin2, r.cos2);
  r.dot = r.cos1 * r.cos2 + r.sin1 * r.sin2;
  r.cross = r.cos1 * r.sin2 - r.sin1 * r.cos2;
  r.arccos_distance = det::acos(r.dot);  // clamps a dot rounded past +-1
  // The lab's own functions: the shown value, and the direction its straight lines take.
  r.distance = s1_distance(q1, q2);
  r.rotation_distance = s1_distance_rotation(q1, q2);
  r.signed_turn = angle_difference(q1, q2);
  r.kind = classify(r.distance);
  // Whether the arc the lab takes (q1 turning by signed_turn) passes the angle 0: then the
  // plain difference |q1 - q2| of the wrapped angles is the long way, and the min() matters.
  const double end = r.wrapped1 + r.signed_turn;
  r.wraps_around = r.kind != S1Case::Equal && (end < 0.0 || end >= kTwoPi);
  return r;
}

const char* s1_case_name(S1Case c) {
  switch (c) {
    case S1Case::Equal: return "equal";
    case S1Case::Antipodal: return "antipodal";
    case S1Case::General: return "general";
  }
  return "general";
}

SegmentDiskReport segment_disk_report(const Vec2& p1, const Vec2& p2, const Vec2& q, double r) {
  SegmentDiskReport s;
  s.p1 = p1;
  s.p2 = p2;
  s.q = q;
  s.r = r;
  const double dx = p2.x() - p1.x(), dy = p2.y() - p1.y();
  s.direction = Vec2(dx, dy);
  s.length_squared = dx * dx + dy * dy;
  s.dot = (q.x() - p1.x()) * dx + (q.y() - p1.y()) * dy;
  if (s.length_squared == 0.0) {
    // One point: there is no line to project on, and every t gives p1.
    s.where = SegmentDiskCase::Degenerate;
    s.t_raw = std::numeric_limits<double>::quiet_NaN();
    s.t = 0.0;
    s.foot = p1;
    s.closest = p1;
  } else {
    s.t_raw = s.dot / s.length_squared;
    s.foot = Vec2(p1.x() + s.t_raw * dx, p1.y() + s.t_raw * dy);
    if (s.t_raw <= 0.0) {
      s.where = SegmentDiskCase::AtP1;
      s.t = 0.0;
      s.closest = p1;  // the endpoint itself, not p1 + 0 * d: no rounding
    } else if (s.t_raw >= 1.0) {
      s.where = SegmentDiskCase::AtP2;
      s.t = 1.0;
      s.closest = p2;  // not p1 + 1 * d, which rounds
    } else {
      s.where = SegmentDiskCase::Interior;
      s.t = s.t_raw;
      s.closest = Vec2(p1.x() + s.t * dx, p1.y() + s.t * dy);
    }
  }
  const double cx = q.x() - s.closest.x(), cy = q.y() - s.closest.y();
  s.centre_distance = std::sqrt(cx * cx + cy * cy);
  s.signed_distance = s.centre_distance - r;
  s.distance = s.signed_distance > 0.0 ? s.signed_distance : 0.0;
  s.meets = s.centre_distance <= r;
  s.lab_clearance = segment_disk_signed_distance(p1, p2, q, r);
  return s;
}

const char* segment_disk_case_name(SegmentDiskCase c) {
  switch (c) {
    case SegmentDiskCase::Interior: return "interior";
    case SegmentDiskCase::AtP1: return "p1";
    case SegmentDiskCase::AtP2: return "p2";
    case SegmentDiskCase::Degenerate: return "degenerate";
  }
  return "degenerate";
}

}  // namespace csl
