#pragma once
// The homework's two distance derivations worked out number by number, for the "Distances"
// lesson: P10 (two angles on S^1, by the modulus and by rotation matrices) and P11 (a segment
// and a closed disk, by projecting the centre onto the segment). Each report holds every
// intermediate quantity the derivation names and which special case holds; the values the lab
// itself plans with come from angles.hpp and geometry.hpp, and the reports carry those too, so
// a student can see that the worked formula and the lab's function agree.
#include "core/base/vec2.hpp"

namespace csl {

// ---------------------------------------------------------------- P10: angles on S^1

/// Which case of P10 a pair of angles is in.
enum class S1Case {
  Equal,      ///< the same direction: d = 0, no arc at all
  Antipodal,  ///< opposite directions: d = pi, both arcs are equally short
  General,    ///< one arc is strictly shorter
};

/// Angles whose distance is within this of 0 (or of pi) count as equal (or antipodal). Typed
/// angles of the lab are at most 1000 rad, where a double's own spacing is 1.1e-13: 1e-9 is far
/// above rounding and far below anything a student types or drags on purpose.
inline constexpr double kS1CaseTolerance = 1e-9;

struct S1DistanceReport {
  double q1 = 0.0, q2 = 0.0;              ///< the angles as given (any finite numbers)
  double wrapped1 = 0.0, wrapped2 = 0.0;  ///< the same directions in [0, 2pi)
  // (a) the modulus: d = min(|q1 - q2| mod 2pi, 2pi - (|q1 - q2| mod 2pi)).
  double raw_difference = 0.0;    ///< |q1 - q2|
  double modulus = 0.0;           ///< |q1 - q2| mod 2pi, in [0, 2pi)
  double other_way = 0.0;         ///< 2pi - modulus: the arc the other way round
  double modular_distance = 0.0;  ///< min(modulus, other_way)
  // (b) rotations: R(q) = [cos q, -sin q; sin q, cos q]; trace(R1^T R2) / 2 is the dot product of
  // their first columns, the unit vectors (cos q, sin q), and equals cos d.
  double cos1 = 1.0, sin1 = 0.0, cos2 = 1.0, sin2 = 0.0;
  double dot = 1.0;              ///< cos q1 cos q2 + sin q1 sin q2 = trace(R1^T R2) / 2
  double cross = 0.0;            ///< cos q1 sin q2 - sin q1 cos q2: the sine of the turn q1 -> q2
  double arccos_distance = 0.0;  ///< arccos(dot), the dot clamped to [-1, 1] against rounding
  // What the lab computes.
  double distance = 0.0;           ///< s1_distance(q1, q2) = |wrap(q2 - q1)|: the value shown
  double rotation_distance = 0.0;  ///< s1_distance_rotation(q1, q2) (atan2, accurate near 0 and pi)
  double signed_turn = 0.0;        ///< the shorter turn from q1 to q2 in [-pi, pi) (+: counter-clockwise)
  bool wraps_around = false;       ///< the shorter arc passes through the angle 0 (= 2pi)
  S1Case kind = S1Case::Equal;
};

/// The whole of P10 for q1 and q2 (finite; the lab keeps them within +-1000).
S1DistanceReport s1_distance_report(double q1, double q2);
/// "equal", "antipodal" or "general".
const char* s1_case_name(S1Case c);

// ---------------------------------------------------------------- P11: segment to disk

/// Where on the segment p1p2 the point nearest the disk's centre q lies.
enum class SegmentDiskCase {
  Interior,    ///< 0 < t* < 1: the foot of the perpendicular from q
  AtP1,        ///< t* <= 0: the projection falls before p1, so p1 is nearest
  AtP2,        ///< t* >= 1: it falls beyond p2, so p2 is nearest
  Degenerate,  ///< p1 == p2: no direction to project on; the segment is the point p1
};

struct SegmentDiskReport {
  Vec2 p1{0, 0}, p2{0, 0}, q{0, 0};
  double r = 0.0;
  Vec2 direction{0, 0};         ///< p2 - p1
  double length_squared = 0.0;  ///< |p2 - p1|^2 (exactly 0: degenerate)
  double dot = 0.0;             ///< (q - p1) . (p2 - p1)
  double t_raw = 0.0;           ///< t* = dot / length_squared; NaN when degenerate
  double t = 0.0;               ///< t* clamped to [0, 1] (0 when degenerate)
  Vec2 foot{0, 0};              ///< p1 + t* (p2 - p1): q projected on the whole line (p1 when degenerate)
  Vec2 closest{0, 0};  ///< c = p1 + t (p2 - p1), the segment's point nearest q (an endpoint exactly when clamped)
  double centre_distance = 0.0;  ///< |q - c|
  double distance = 0.0;         ///< max(0, |q - c| - r): P11's distance between the two sets
  double signed_distance = 0.0;  ///< |q - c| - r: negative when the disk reaches past the segment, by that much
  /// segment_disk_signed_distance(p1, p2, q, r): what the collision checker computes for a link
  /// against a disk (eta); the same as signed_distance up to rounding.
  double lab_clearance = 0.0;
  bool meets = false;  ///< |q - c| <= r: the segment touches or enters the closed disk (distance 0)
  SegmentDiskCase where = SegmentDiskCase::Degenerate;
};

/// The whole of P11 for the segment p1p2 and the closed disk B_r(q), r >= 0.
SegmentDiskReport segment_disk_report(const Vec2& p1, const Vec2& p2, const Vec2& q, double r);
/// "interior", "p1", "p2" or "degenerate".
const char* segment_disk_case_name(SegmentDiskCase c);

}  // namespace csl
