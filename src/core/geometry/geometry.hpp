#pragma once
// Planar distances between points, segments, disks and simple polygons.
//
// Conventions, the same in every function here:
// - obstacles are closed sets: touching is intersecting;
// - `*_distance` is the Euclidean distance between the two sets: >= 0, exactly 0 when they
//   touch or overlap (a shape inside another counts as overlapping);
// - `*_signed_distance` is negative inside, by how deep (only where it is cheap and exact).
// Only + - * / and sqrt are used, so results are bit-identical natively and in wasm.
#include <array>
#include <cmath>
#include <vector>

#include "core/base/vec2.hpp"

namespace csl {

/// A simple polygon: >= 3 vertices in order (either orientation), not closed by a repeat.
using Polygon = std::vector<Vec2>;

/// z-component of (b - a) x (c - a): > 0 when a, b, c turn left.
inline double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

inline double squared_length(const Vec2& v) { return v.x() * v.x() + v.y() * v.y(); }
inline double length(const Vec2& v) { return std::sqrt(squared_length(v)); }

/// Parameter s in [0,1] of the point of segment ab closest to p (0 when a == b).
inline double closest_parameter(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double len2 = dx * dx + dy * dy;
  if (len2 == 0.0) return 0.0;  // degenerate segment: a single point
  const double s = ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2;
  return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);  // projection outside -> nearest endpoint
}

/// Squared distance from p to segment ab (P11): the dot product decides whether the nearest
/// point is an endpoint (then it is that endpoint itself, not a + 1 * (b - a), which rounds) or
/// inside, where the distance to the line is |(b - a) x (p - a)|^2 / |b - a|^2: exactly 0 when
/// orient(a, b, p) is, as segments_intersect and point_in_polygon decide, and rounded relative
/// to |p - a| instead of to the size of the coordinates.
inline double point_segment_squared_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double s = closest_parameter(p, a, b);
  if (s == 0.0) return squared_length(p - a);
  if (s == 1.0) return squared_length(p - b);
  const double c = orient(a, b, p);
  return c * c / squared_length(b - a);
}

/// Distance from point p to segment ab; a == b is allowed.
inline double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  return std::sqrt(point_segment_squared_distance(p, a, b));
}

/// The point of segment ab closest to p (an endpoint exactly when it is one).
inline Vec2 closest_point_on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double s = closest_parameter(p, a, b);
  if (s == 1.0) return b;
  return {a.x() + s * (b.x() - a.x()), a.y() + s * (b.y() - a.y())};
}

/// Distance from segment ab to the centre c minus r: negative when they overlap (by how much
/// the disk reaches past the segment). Homework P11: dist(segment, B_r(c)) = max(0, this).
inline double segment_disk_signed_distance(const Vec2& a, const Vec2& b, const Vec2& c, double r) {
  return point_segment_distance(c, a, b) - r;
}

/// Distance between segment ab and the closed disk B_r(c), r >= 0 (P11); 0 if they meet.
/// Covers a == b (point), projections outside the segment, endpoints inside the disk, r = 0.
inline double segment_disk_distance(const Vec2& a, const Vec2& b, const Vec2& c, double r) {
  const double d = segment_disk_signed_distance(a, b, c, r);
  return d > 0.0 ? d : 0.0;
}

/// Whether closed segments ab and cd share a point (touching and collinear overlap count).
bool segments_intersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// Distance between segments ab and cd; 0 if they intersect.
double segment_segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// Twice the signed area (> 0 for counter-clockwise vertex order).
double polygon_twice_signed_area(const Polygon& poly);

/// Whether p lies in the closed polygon (boundary included); even-odd rule.
bool point_in_polygon(const Vec2& p, const Polygon& poly);

/// Distance from p to the polygon's boundary.
double point_polygon_boundary_distance(const Vec2& p, const Polygon& poly);

/// Distance from p to the closed polygon: 0 inside or on the boundary.
double point_polygon_distance(const Vec2& p, const Polygon& poly);

/// Signed distance: minus the distance to the boundary inside, plus outside.
double point_polygon_signed_distance(const Vec2& p, const Polygon& poly);

/// Distance from segment ab to the closed polygon: 0 if the segment touches or enters it.
double segment_polygon_distance(const Vec2& a, const Vec2& b, const Polygon& poly);

/// Distance between two closed polygons: 0 if they touch, overlap or one contains the other.
double polygon_polygon_distance(const Polygon& p, const Polygon& q);

/// Distance between a closed polygon and the closed disk B_r(c): 0 if they meet.
double polygon_disk_distance(const Polygon& poly, const Vec2& c, double r);

/// Why a polygon is not simple, or an empty string if it is: >= 3 finite vertices, non-zero
/// area, no repeated consecutive vertex, edges meeting only at shared endpoints of neighbours.
const char* polygon_problem(const Polygon& poly);

/// Whether the polygon is convex (all turns one way; collinear vertices allowed).
bool polygon_is_convex(const Polygon& poly);

/// Indices of three polygon vertices.
using Triangle = std::array<int, 3>;
/// Triangles covering a simple polygon exactly (ear clipping; n - 2 of them).
std::vector<Triangle> triangulate(const Polygon& poly);

/// Axis-aligned bounds of a set of points.
struct Box {
  Vec2 min{0, 0}, max{0, 0};
  /// Distance from p to the box (0 inside).
  double distance(const Vec2& p) const {
    const double dx = std::fmax(std::fmax(min.x() - p.x(), 0.0), p.x() - max.x());
    const double dy = std::fmax(std::fmax(min.y() - p.y(), 0.0), p.y() - max.y());
    return std::sqrt(dx * dx + dy * dy);
  }
};
Box bounding_box(const Polygon& poly);

}  // namespace csl
