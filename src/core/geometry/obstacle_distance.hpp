#pragma once
// rho(x), the distance from a workspace point x to one obstacle, and its gradient grad rho(x):
// what the repulsive potential of Spong, Hutchinson and Vidyasagar, "Robot Modeling and
// Control" (2006), section 5.2, eqs (5.5) and (5.6), is made of. Where rho is differentiable
// (outside the obstacle, off the medial axis), grad rho = (x - b) / |x - b|, the unit vector
// away from the nearest obstacle point b.
//
// Where it is not, we return one definite unit vector (documented per case) instead of failing,
// so that callers always get a direction:
// - rho = 0 (x on or inside the obstacle): grad is the gradient of the *signed* distance, i.e.
//   the unit vector from x toward the nearest boundary point: the quickest way out. On the
//   boundary itself (x == b) it is the outward normal: disk (x - c)/r; polygon edge: the edge's
//   outward normal; a wall (no inside) the left normal of a -> b; a degenerate wall (a == b),
//   or the centre of a disk (every boundary point is nearest), (1, 0).
// - x outside a concave polygon and equidistant from two or more of its edges (the medial axis):
//   rho has a kink there (it is the least of the edges' distances). We take the nearest point
//   on the edge of lowest index among the tied ones (edges i = (v_i, v_{i+1}) in vertex order),
//   i.e. one of the one-sided gradients, an element of Clarke's generalized gradient (their
//   convex hull). Ties are exact comparisons of the squared distances, so both builds agree.
// Walls are measured as bare segments here (no kWallTolerance: that only makes touching a wall
// count as a collision).
// Only + - * / and sqrt: the results are bit-identical natively and in wasm.
#include "core/geometry/obstacles.hpp"

namespace csl {

/// rho(x) to one obstacle, its gradient and the nearest obstacle point.
struct ObstacleDistance {
  double rho = 0.0;        ///< distance from x to the closed obstacle: >= 0, 0 on or inside it
  Vec2 grad{1.0, 0.0};     ///< a unit vector: grad rho (see the file comment where rho has none)
  Vec2 nearest{0.0, 0.0};  ///< b: the point of the obstacle's boundary nearest to x
  bool inside = false;     ///< x lies on or inside the obstacle (rho = 0)
};

/// Disk B_r(c): rho = max(0, |x - c| - r), grad = (x - c)/|x - c| (inside too; (1, 0) at c).
ObstacleDistance disk_distance(const Disk& d, const Vec2& x);
/// Simple polygon (convex or not, either orientation): the nearest point over its edges.
ObstacleDistance polygon_distance(const Polygon& poly, const Vec2& x);
/// Segment (wall) ab: rho = |x - b|, b the nearest point of the segment.
ObstacleDistance segment_distance(const Vec2& a, const Vec2& b, const Vec2& x);
/// Whichever of the above the obstacle is.
ObstacleDistance obstacle_distance(const Obstacle& o, const Vec2& x);

}  // namespace csl
