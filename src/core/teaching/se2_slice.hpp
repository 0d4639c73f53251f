#pragma once
// The exact C-obstacles of a polygon robot (SE(2)) at a fixed angle theta: the (x, y) of the
// reference point where the robot, turned by theta, touches an obstacle.
//
// The robot's body B (robot frame) and each obstacle are cut into convex pieces (a convex
// polygon stays whole; a concave one is triangulated by ear clipping). The body at
// q = (x, y, theta) is q + R(theta) B, so a body piece T meets a convex closed set S exactly when
// (x, y) lies in S (+) -R(theta) T, the Minkowski sum of S and the piece turned and reflected
// through the reference point. Every obstacle is a convex point set S grown by a radius r:
//   - a polygon piece: its vertices, r = 0;
//   - a disk: its centre, r = its radius;
//   - a wall: its two ends, r = kWallTolerance (the checker calls a body within that of a wall
//     a collision: the wall is the capsule [a, b] (+) B(0, r)).
// So each C-obstacle piece is conv(S (+) -R(theta) T) (+) B(0, r): a convex polygon with a radius
// ("rounded"), and the C-obstacle at theta is the union of all of them (body pieces x obstacle
// pieces). Decisions are CollisionWorld::is_free's (closed sets, touching collides) up to the
// rounding of the sums.
//
// The workspace box: CollisionWorld does not confine a polygon robot's reference point (nor its
// body) to the workspace; the box is only the range of x and y in SE(2). The slices here do the
// same: the box adds no C-obstacle, it bounds the (x, y) domain of a slice or a volume.
#include <vector>

#include "core/geometry/obstacles.hpp"
#include "core/robots/polygon_robot.hpp"

namespace csl {

/// A convex polygon grown by a radius: the points within `radius` of conv(hull). `hull` is
/// counter-clockwise without collinear vertices; it may be a single point or a segment (a disk
/// or a wall against a flat piece). `obstacle` is the scene index of the obstacle it comes from.
struct RoundedPolygon {
  Polygon hull;
  double radius = 0.0;
  int obstacle = -1;
};

/// Whether q lies in the closed rounded polygon (distance to conv(hull) minus radius <= 0, the
/// checker's test).
bool rounded_polygon_contains(const RoundedPolygon& piece, const Vec2& q);

/// The x where the horizontal line at height y crosses the rounded polygon: [lo, hi], false
/// when it misses. Exact up to rounding (the set is convex: its hull, each edge's band of
/// width 2 radius and each vertex's disk, combined).
bool rounded_polygon_row(const RoundedPolygon& piece, double y, double& lo, double& hi);

/// rounded_polygon_row for many rows of one piece: the edges' bands computed once.
class RoundedPolygonRows {
 public:
  explicit RoundedPolygonRows(const RoundedPolygon& piece);
  bool row(double y, double& lo, double& hi) const;

 private:
  const RoundedPolygon& piece_;
  std::vector<Vec2> bands_;  // four corners per edge
};

/// A closed polyline around the rounded polygon for drawing: its hull where radius is 0; else
/// each edge moved out by the radius and each corner's arc in steps of at most `max_step`
/// radians (> 0). Its vertices lie on the exact boundary.
Polygon rounded_polygon_outline(const RoundedPolygon& piece, double max_step);

/// The convex hull of points, counter-clockwise, collinear points dropped (Andrew's monotone
/// chain); one point, or the two ends, for degenerate input.
Polygon convex_hull(std::vector<Vec2> points);

/// The robot's and the obstacles' convex pieces, cut once; slices at any theta from them.
class Se2CObstacles {
 public:
  Se2CObstacles(const PolygonRobot& robot, const std::vector<Obstacle>& obstacles);

  /// The C-obstacle at theta as rounded convex pieces (their union), written into `out`.
  void slice(double theta, std::vector<RoundedPolygon>& out) const;

  /// How many pieces every slice has (body pieces x obstacle pieces).
  std::size_t pieces_per_slice() const { return body_.size() * obstacles_.size(); }
  /// How many vertex sums every slice forms (each piece is the hull of |body piece| x
  /// |obstacle piece| sums): what prices a slice beside its pieces, since one convex 256-gon
  /// against another is one piece but 65536 sums.
  double sums_per_slice() const;

 private:
  struct ObstaclePiece {
    std::vector<Vec2> points;
    double radius;
    int obstacle;
  };
  std::vector<Polygon> body_;  // convex pieces of the body, robot frame
  std::vector<ObstaclePiece> obstacles_;
};

/// Whether (x, y) is in the C-obstacle given by `pieces` (one slice).
bool se2_slice_blocked(const std::vector<RoundedPolygon>& pieces, const Vec2& q);

}  // namespace csl
