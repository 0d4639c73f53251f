#include "core/geometry/obstacles.hpp"

#include "core/base/overloaded.hpp"

namespace csl {

const char* obstacle_type_name(const Obstacle& o) {
  return std::visit(Overloaded{[](const Disk&) { return "disk"; },
                               [](const PolygonObstacle&) { return "polygon"; },
                               [](const Wall&) { return "segment"; }},
                    o);
}

double point_clearance(const Obstacle& o, const Vec2& p) {
  return std::visit(
      Overloaded{[&](const Disk& d) { return length(p - d.center) - d.radius; },
                 [&](const PolygonObstacle& g) { return point_polygon_signed_distance(p, g.vertices); },
                 [&](const Wall& w) { return point_segment_distance(p, w.a, w.b) - kWallTolerance; }},
      o);
}

double segment_clearance(const Obstacle& o, const Vec2& a, const Vec2& b) {
  return std::visit(
      Overloaded{[&](const Disk& d) { return segment_disk_signed_distance(a, b, d.center, d.radius); },
                 [&](const PolygonObstacle& g) { return segment_polygon_distance(a, b, g.vertices); },
                 [&](const Wall& w) { return segment_segment_distance(a, b, w.a, w.b) - kWallTolerance; }},
      o);
}

double polygon_clearance(const Obstacle& o, const Polygon& poly) {
  return std::visit(
      Overloaded{[&](const Disk& d) { return polygon_disk_distance(poly, d.center, d.radius); },
                 [&](const PolygonObstacle& g) { return polygon_polygon_distance(poly, g.vertices); },
                 [&](const Wall& w) { return segment_polygon_distance(w.a, w.b, poly) - kWallTolerance; }},
      o);
}

Box obstacle_bounds(const Obstacle& o) {
  return std::visit(
      Overloaded{[](const Disk& d) {
                   const Vec2 r(d.radius, d.radius);
                   return Box{d.center - r, d.center + r};
                 },
                 [](const PolygonObstacle& g) { return bounding_box(g.vertices); },
                 [](const Wall& w) { return Box{w.a.cwiseMin(w.b), w.a.cwiseMax(w.b)}; }},
      o);
}

void translate(Obstacle& o, const Vec2& by) {
  std::visit(Overloaded{[&](Disk& d) { d.center += by; },
                        [&](PolygonObstacle& g) {
                          for (Vec2& v : g.vertices) v += by;
                        },
                        [&](Wall& w) {
                          w.a += by;
                          w.b += by;
                        }},
             o);
}

}  // namespace csl
