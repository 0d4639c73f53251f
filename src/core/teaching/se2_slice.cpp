#include "core/teaching/se2_slice.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/base/overloaded.hpp"

namespace csl {
namespace {

// Two pieces (vertex indices, both in the polygon's orientation) that share an edge, merged
// into one if the union is convex (Hertel and Mehlhorn 1983); empty otherwise.
std::vector<int> merged_if_convex(const Polygon& poly, const std::vector<int>& p, const std::vector<int>& q) {
  const std::size_t n = p.size(), m = q.size();
  for (std::size_t a = 0; a < n; ++a) {
    const int u = p[a], v = p[(a + 1) % n];
    for (std::size_t b = 0; b < m; ++b) {
      if (q[b] != v || q[(b + 1) % m] != u) continue;
      // p from v round to u, then q from u round to v without its two ends.
      std::vector<int> out;
      for (std::size_t k = 0; k < n; ++k) out.push_back(p[(a + 1 + k) % n]);
      for (std::size_t k = 2; k < m; ++k) out.push_back(q[(b + k) % m]);
      Polygon shape;
      for (int i : out) shape.push_back(poly[static_cast<std::size_t>(i)]);
      if (polygon_is_convex(shape)) return out;
      return {};
    }
  }
  return {};
}

// The convex pieces of a simple polygon: itself when convex, else its ear-clipping triangles
// merged across diagonals while the union stays convex (fewer pieces: every slice sums each
// body piece with each obstacle piece). Merging costs O(n^3) at worst: polygons of more than
// 64 vertices keep their triangles.
std::vector<Polygon> convex_pieces(const Polygon& poly) {
  if (polygon_is_convex(poly)) return {poly};
  std::vector<std::vector<int>> pieces;
  for (const Triangle& t : triangulate(poly)) pieces.push_back({t[0], t[1], t[2]});
  for (bool merged = poly.size() <= 64; merged;) {
    merged = false;
    for (std::size_t i = 0; i < pieces.size() && !merged; ++i)
      for (std::size_t j = i + 1; j < pieces.size() && !merged; ++j) {
        std::vector<int> both = merged_if_convex(poly, pieces[i], pieces[j]);
        if (both.empty()) continue;
        pieces[i] = std::move(both);
        pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(j));
        merged = true;
      }
  }
  std::vector<Polygon> out;
  for (const std::vector<int>& piece : pieces) {
    Polygon shape;
    for (int k : piece) shape.push_back(poly[static_cast<std::size_t>(k)]);
    out.push_back(std::move(shape));
  }
  return out;
}

// Widens [lo, hi] to hold x.
void include(double x, double& lo, double& hi) {
  lo = std::min(lo, x);
  hi = std::max(hi, x);
}

// The x where the line at height y crosses the closed convex polygon (any orientation, or a
// point or segment), widened into [lo, hi].
void convex_row(const Vec2* v, std::size_t n, double y, double& lo, double& hi) {
  if (n == 1) {
    if (v[0].y() == y) include(v[0].x(), lo, hi);
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& p = v[k];
    const Vec2& q = v[k + 1 == n ? 0 : k + 1];
    if ((p.y() - y) * (q.y() - y) > 0.0) continue;  // the edge lies wholly above or below
    if (p.y() == q.y()) {
      include(p.x(), lo, hi);
      include(q.x(), lo, hi);
    } else {
      include(p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y()), lo, hi);
    }
  }
}

}  // namespace

Polygon convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() <= 2) return points;
  Polygon hull(2 * points.size());
  std::size_t k = 0;
  for (const Vec2& p : points) {  // lower chain
    while (k >= 2 && orient(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && orient(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point is the first again
  return hull;
}

bool rounded_polygon_contains(const RoundedPolygon& piece, const Vec2& q) {
  const Polygon& h = piece.hull;
  const std::size_t n = h.size();
  if (n >= 3) {
    bool inside = true;
    for (std::size_t k = 0; k < n && inside; ++k) inside = orient(h[k], h[k + 1 == n ? 0 : k + 1], q) >= 0.0;
    if (inside) return true;
  }
  double d2;
  if (n == 1) {
    d2 = squared_length(q - h[0]);
  } else {
    d2 = point_segment_squared_distance(q, h[0], h[1]);
    for (std::size_t k = 1; k < n && n >= 3; ++k)
      d2 = std::min(d2, point_segment_squared_distance(q, h[k], h[k + 1 == n ? 0 : k + 1]));
  }
  return std::sqrt(d2) - piece.radius <= 0.0;
}

RoundedPolygonRows::RoundedPolygonRows(const RoundedPolygon& piece) : piece_(piece) {
  // The set within r of a convex polygon is the polygon, each edge's band (the rectangle the
  // edge sweeps moved r along its normal both ways) and each vertex's disk: a point's nearest
  // point of the polygon is inside it, inside an edge or a vertex.
  const Polygon& h = piece.hull;
  const std::size_t n = h.size();
  const double r = piece.radius;
  if (!(r > 0.0) || n < 2) return;
  for (std::size_t k = 0; k < (n == 2 ? 1 : n); ++k) {
    const Vec2& a = h[k];
    const Vec2& b = h[k + 1 == n ? 0 : k + 1];
    const double len = length(b - a);
    if (!(len > 0.0)) continue;
    const Vec2 m(-(b.y() - a.y()) / len * r, (b.x() - a.x()) / len * r);
    bands_.insert(bands_.end(), {a + m, b + m, b - m, a - m});
  }
}

bool RoundedPolygonRows::row(double y, double& lo, double& hi) const {
  lo = HUGE_VAL;
  hi = -HUGE_VAL;
  const Polygon& h = piece_.hull;
  convex_row(h.data(), h.size(), y, lo, hi);
  const double r = piece_.radius;
  if (r > 0.0) {
    for (const Vec2& v : h) {
      const double dy = y - v.y();
      if (std::fabs(dy) <= r) {
        const double w = std::sqrt((r - dy) * (r + dy));
        include(v.x() - w, lo, hi);
        include(v.x() + w, lo, hi);
      }
    }
    for (std::size_t k = 0; k < bands_.size(); k += 4) convex_row(bands_.data() + k, 4, y, lo, hi);
  }
  return lo <= hi;
}

bool rounded_polygon_row(const RoundedPolygon& piece, double y, double& lo, double& hi) {
  return RoundedPolygonRows(piece).row(y, lo, hi);
}

Polygon rounded_polygon_outline(const RoundedPolygon& piece, double max_step) {
  const Polygon& h = piece.hull;
  const double r = piece.radius;
  if (!(r > 0.0)) return h;
  const std::size_t n = h.size();
  Polygon out;
  if (n == 1) {  // a disk
    const int steps = std::max(3, static_cast<int>(std::ceil(kTwoPi / max_step)));
    for (int s = 0; s < steps; ++s) {
      double sn, cs;
      det::sincos(kTwoPi * s / steps, sn, cs);
      out.push_back(h[0] + r * Vec2(cs, sn));
    }
    return out;
  }
  // Counter-clockwise: each edge's outward normal is its direction turned clockwise; at each
  // vertex, the arc from the incoming edge's normal to the outgoing one's (a segment: a half
  // turn at each end).
  auto normal_angle = [&](std::size_t k) {
    const Vec2& a = h[k];
    const Vec2& b = h[(k + 1) % n];
    return det::atan2(-(b.x() - a.x()), b.y() - a.y());
  };
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t prev = (k + n - 1) % n;
    const double from = normal_angle(prev);
    double sweep = angle_difference(from, normal_angle(k));
    if (sweep < 0.0) sweep += kTwoPi;  // convex and counter-clockwise: the arcs turn left
    if (n == 2) sweep = kPi;
    const int steps = std::max(1, static_cast<int>(std::ceil(sweep / max_step)));
    for (int s = 0; s <= steps; ++s) {
      double sn, cs;
      det::sincos(from + sweep * s / steps, sn, cs);
      out.push_back(h[k] + r * Vec2(cs, sn));
    }
  }
  return out;
}

Se2CObstacles::Se2CObstacles(const PolygonRobot& robot, const std::vector<Obstacle>& obstacles)
    : body_(convex_pieces(robot.body)) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const int index = static_cast<int>(i);
    std::visit(Overloaded{[&](const Disk& d) { obstacles_.push_back({{d.center}, d.radius, index}); },
                          [&](const PolygonObstacle& g) {
                            for (Polygon& p : convex_pieces(g.vertices)) obstacles_.push_back({std::move(p), 0.0, index});
                          },
                          [&](const Wall& w) { obstacles_.push_back({{w.a, w.b}, kWallTolerance, index}); }},
               obstacles[i]);
  }
}

double Se2CObstacles::sums_per_slice() const {
  double body = 0.0, obstacles = 0.0;
  for (const Polygon& piece : body_) body += static_cast<double>(piece.size());
  for (const ObstaclePiece& o : obstacles_) obstacles += static_cast<double>(o.points.size());
  return body * obstacles;  // the sum over pairs of |b| |o| factors
}

void Se2CObstacles::slice(double theta, std::vector<RoundedPolygon>& out) const {
  out.clear();
  double s, c;
  det::sincos(theta, s, c);  // as polygon_pose turns the body
  std::vector<Vec2> turned, sums;
  for (const Polygon& piece : body_) {
    turned.clear();
    for (const Vec2& v : piece) turned.emplace_back(-(c * v.x() - s * v.y()), -(s * v.x() + c * v.y()));
    for (const ObstaclePiece& o : obstacles_) {
      sums.clear();
      for (const Vec2& p : o.points)
        for (const Vec2& t : turned) sums.push_back(p + t);
      out.push_back({convex_hull(sums), o.radius, o.obstacle});
    }
  }
}

bool se2_slice_blocked(const std::vector<RoundedPolygon>& pieces, const Vec2& q) {
  for (const RoundedPolygon& p : pieces)
    if (rounded_polygon_contains(p, q)) return true;
  return false;
}

}  // namespace csl
