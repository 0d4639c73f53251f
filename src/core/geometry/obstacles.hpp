#pragma once
// Workspace obstacles: disks, simple polygons and thin walls (segments), all closed sets.
#include <string>
#include <variant>
#include <vector>

#include "core/geometry/geometry.hpp"

namespace csl {

/// Walls have no thickness; a robot closer than this (scene units) to one is in collision, so
/// that crossing a wall is a collision and not a measure-zero event no sample ever hits.
inline constexpr double kWallTolerance = 1e-6;

struct Disk {
  Vec2 center{0.0, 0.0};
  double radius = 0.0;
};

struct PolygonObstacle {
  Polygon vertices;
};

struct Wall {
  Vec2 a{0.0, 0.0};
  Vec2 b{0.0, 0.0};
};

using Obstacle = std::variant<Disk, PolygonObstacle, Wall>;

/// "disk", "polygon" or "segment" (the JSON type names).
const char* obstacle_type_name(const Obstacle& o);

/// Clearance of a point from the obstacle: distance (minus kWallTolerance for walls); <= 0 is
/// a collision.
double point_clearance(const Obstacle& o, const Vec2& p);
/// Clearance of a segment ab from the obstacle, as point_clearance.
double segment_clearance(const Obstacle& o, const Vec2& a, const Vec2& b);
/// Clearance of a closed polygon from the obstacle, as point_clearance.
double polygon_clearance(const Obstacle& o, const Polygon& poly);

/// Axis-aligned bounds of the obstacle.
Box obstacle_bounds(const Obstacle& o);
/// Moves the whole obstacle by `by` (a disk's centre, every vertex, both ends of a wall).
void translate(Obstacle& o, const Vec2& by);

}  // namespace csl
