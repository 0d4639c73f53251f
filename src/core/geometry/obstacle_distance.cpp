#include "core/geometry/obstacle_distance.hpp"

#include <cmath>

#include "core/base/overloaded.hpp"

namespace csl {
namespace {

// The unit vector along v; `fallback` when v is the zero vector.
Vec2 unit_or(const Vec2& v, const Vec2& fallback) {
  const double len = length(v);
  return len > 0.0 ? Vec2(v.x() / len, v.y() / len) : fallback;
}

// The left normal of a -> b, (-dy, dx)/|ab|; (1, 0) for a degenerate segment.
Vec2 left_normal(const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  return unit_or(Vec2(-d.y(), d.x()), Vec2(1.0, 0.0));
}

}  // namespace

ObstacleDistance disk_distance(const Disk& d, const Vec2& x) {
  ObstacleDistance r;
  const Vec2 v = x - d.center;
  const double len = length(v);
  r.grad = unit_or(v, Vec2(1.0, 0.0));  // the centre: every direction is as good; take +x
  r.nearest = Vec2(d.center.x() + d.radius * r.grad.x(), d.center.y() + d.radius * r.grad.y());
  r.rho = len - d.radius;
  if (r.rho <= 0.0) {
    r.rho = 0.0;
    r.inside = true;
  }
  return r;
}

ObstacleDistance polygon_distance(const Polygon& poly, const Vec2& x) {
  // The nearest edge: strictly smaller squared distance wins, so ties keep the lowest index.
  std::size_t best = 0;
  double best_d2 = point_segment_squared_distance(x, poly[0], poly[1 % poly.size()]);
  for (std::size_t i = 1, n = poly.size(); i < n; ++i) {
    const double d2 = point_segment_squared_distance(x, poly[i], poly[(i + 1) % n]);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  const Vec2& a = poly[best];
  const Vec2& b = poly[(best + 1) % poly.size()];
  ObstacleDistance r;
  r.nearest = closest_point_on_segment(x, a, b);
  // The edge's outward normal: the left normal points inward on a counter-clockwise polygon.
  const Vec2 left = left_normal(a, b);
  const Vec2 outward = polygon_twice_signed_area(poly) > 0.0 ? Vec2(-left) : left;
  if (point_in_polygon(x, poly)) {
    r.inside = true;
    r.rho = 0.0;
    r.grad = unit_or(r.nearest - x, outward);  // the signed distance's gradient: the way out
    return r;
  }
  r.rho = std::sqrt(best_d2);
  r.inside = r.rho == 0.0;                   // only through rounding at the boundary
  r.grad = unit_or(x - r.nearest, outward);
  return r;
}

ObstacleDistance segment_distance(const Vec2& a, const Vec2& b, const Vec2& x) {
  ObstacleDistance r;
  r.nearest = closest_point_on_segment(x, a, b);
  r.rho = point_segment_distance(x, a, b);
  r.grad = unit_or(x - r.nearest, left_normal(a, b));
  r.inside = r.rho == 0.0;
  return r;
}

ObstacleDistance obstacle_distance(const Obstacle& o, const Vec2& x) {
  return std::visit(Overloaded{[&](const Disk& d) { return disk_distance(d, x); },
                               [&](const PolygonObstacle& g) { return polygon_distance(g.vertices, x); },
                               [&](const Wall& w) { return segment_distance(w.a, w.b, x); }},
                    o);
}

}  // namespace csl
