#include "core/geometry/geometry.hpp"

#include <limits>
#include <algorithm>

namespace csl {
namespace {

int sign(double v) { return (v > 0.0) - (v < 0.0); }

// For collinear a, b, p: whether p lies within the bounding box of ab.
bool on_collinear_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

}  // namespace

bool segments_intersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  // Disjoint bounding boxes: apart. Exact, and needed: for nearly collinear points the signs
  // of orient below are rounding noise and would join segments lying one after the other on
  // their common line, however far apart (e.g. (2.6,0.2)-(2.2,0.5) and (1.8,0.8)-(1.4,1.1)).
  if (std::max(a.x(), b.x()) < std::min(c.x(), d.x()) || std::max(c.x(), d.x()) < std::min(a.x(), b.x()) ||
      std::max(a.y(), b.y()) < std::min(c.y(), d.y()) || std::max(c.y(), d.y()) < std::min(a.y(), b.y()))
    return false;
  const int o1 = sign(orient(a, b, c)), o2 = sign(orient(a, b, d));
  const int o3 = sign(orient(c, d, a)), o4 = sign(orient(c, d, b));
  // Each segment's endpoints on different sides of (or one on) the other's line: they meet.
  // (If c is on line ab and a, b straddle line cd, the meeting point is c itself.)
  if (o1 != o2 && o3 != o4) return true;
  // Collinear cases: an endpoint lying on the other segment.
  if (o1 == 0 && on_collinear_segment(a, b, c)) return true;
  if (o2 == 0 && on_collinear_segment(a, b, d)) return true;
  if (o3 == 0 && on_collinear_segment(c, d, a)) return true;
  if (o4 == 0 && on_collinear_segment(c, d, b)) return true;
  return false;
}

double segment_segment_distance(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  if (segments_intersect(a, b, c, d)) return 0.0;
  // Disjoint segments: the closest pair always involves an endpoint of one of them.
  const double d2 = std::min(std::min(point_segment_squared_distance(a, c, d), point_segment_squared_distance(b, c, d)),
                             std::min(point_segment_squared_distance(c, a, b), point_segment_squared_distance(d, a, b)));
  return std::sqrt(d2);
}

double polygon_twice_signed_area(const Polygon& poly) {
  double s = 0.0;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % n];
    s += p.x() * q.y() - q.x() * p.y();
  }
  return s;
}

double point_polygon_boundary_distance(const Vec2& p, const Polygon& poly) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = poly.size(); i < n; ++i)
    best = std::min(best, point_segment_squared_distance(p, poly[i], poly[(i + 1) % n]));
  return std::sqrt(best);
}

bool point_in_polygon(const Vec2& p, const Polygon& poly) {
  bool inside = false;
  for (std::size_t i = 0, n = poly.size(), j = n - 1; i < n; j = i++) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[j];
    // On an edge: the boundary belongs to the closed polygon.
    if (orient(a, b, p) == 0.0 && on_collinear_segment(a, b, p)) return true;
    // Even-odd rule: count edges crossing the horizontal ray to the right of p.
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

double point_polygon_distance(const Vec2& p, const Polygon& poly) {
  return point_in_polygon(p, poly) ? 0.0 : point_polygon_boundary_distance(p, poly);
}

double point_polygon_signed_distance(const Vec2& p, const Polygon& poly) {
  const double d = point_polygon_boundary_distance(p, poly);
  return point_in_polygon(p, poly) ? -d : d;
}

double segment_polygon_distance(const Vec2& a, const Vec2& b, const Polygon& poly) {
  if (point_in_polygon(a, poly) || point_in_polygon(b, poly)) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    best = std::min(best, segment_segment_distance(a, b, poly[i], poly[(i + 1) % n]));
    if (best == 0.0) return 0.0;
  }
  return best;
}

double polygon_polygon_distance(const Polygon& p, const Polygon& q) {
  // Containment: a vertex of one inside the other (if neither holds and no edges cross,
  // the polygons are disjoint and the distance is between boundaries).
  if (point_in_polygon(p.front(), q) || point_in_polygon(q.front(), p)) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = p.size(); i < n; ++i)
    for (std::size_t j = 0, m = q.size(); j < m; ++j) {
      best = std::min(best, segment_segment_distance(p[i], p[(i + 1) % n], q[j], q[(j + 1) % m]));
      if (best == 0.0) return 0.0;
    }
  return best;
}

double polygon_disk_distance(const Polygon& poly, const Vec2& c, double r) {
  const double d = point_polygon_distance(c, poly) - r;
  return d > 0.0 ? d : 0.0;
}

const char* polygon_problem(const Polygon& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return "a polygon needs at least 3 vertices";
  for (const Vec2& v : poly)
    if (!std::isfinite(v.x()) || !std::isfinite(v.y())) return "vertices must be finite numbers";
  for (std::size_t i = 0; i < n; ++i)
    if (poly[i] == poly[(i + 1) % n]) return "two consecutive vertices coincide";
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2& c = poly[j];
      const Vec2& d = poly[(j + 1) % n];
      const bool next = j == i + 1, wrap = (i == 0 && j == n - 1);
      if (next || wrap) {
        // Neighbours share one vertex; they must not fold back onto each other.
        const Vec2& shared = next ? b : a;
        const Vec2& other_ab = next ? a : b;
        const Vec2& other_cd = next ? d : c;
        if (orient(shared, other_ab, other_cd) == 0.0 &&
            (other_ab - shared).dot(other_cd - shared) > 0.0)
          return "the polygon's edges overlap (it folds back on itself)";
        continue;
      }
      if (segments_intersect(a, b, c, d)) return "the polygon's edges cross (it is self-intersecting)";
    }
  }
  // After the crossing tests, so that a symmetric bow-tie is called self-intersecting.
  if (polygon_twice_signed_area(poly) == 0.0) return "the polygon has zero area";
  return "";
}

bool polygon_is_convex(const Polygon& poly) {
  int turn = 0;
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const int s = sign(orient(poly[i], poly[(i + 1) % n], poly[(i + 2) % n]));
    if (s == 0) continue;
    if (turn == 0) turn = s;
    else if (s != turn) return false;
  }
  return true;
}

std::vector<Triangle> triangulate(const Polygon& poly) {
  // Ear clipping (Meisters 1975): repeatedly cut off a convex vertex whose triangle holds no
  // other remaining vertex. O(n^2) per ear in the worst case; fine for the lab's polygons.
  std::vector<int> idx(poly.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  const double orientation = polygon_twice_signed_area(poly) > 0.0 ? 1.0 : -1.0;
  std::vector<Triangle> out;
  auto at = [&](int k) -> const Vec2& { return poly[static_cast<std::size_t>(k)]; };
  while (idx.size() > 3) {
    const std::size_t n = idx.size();
    bool cut = false;
    for (std::size_t i = 0; i < n && !cut; ++i) {
      const int a = idx[(i + n - 1) % n], b = idx[i], c = idx[(i + 1) % n];
      if (orientation * orient(at(a), at(b), at(c)) <= 0.0) continue;  // reflex or flat
      bool empty = true;
      for (int k : idx) {
        if (k == a || k == b || k == c) continue;
        const Vec2& p = at(k);
        if (orientation * orient(at(a), at(b), p) >= 0.0 && orientation * orient(at(b), at(c), p) >= 0.0 &&
            orientation * orient(at(c), at(a), p) >= 0.0) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
      cut = true;
    }
    if (!cut) {
      // No ear: rounding made (nearly) collinear vertices look flat, reflex or inside, and what
      // is left is a sliver of rounding-sized area. Cut its most convex vertex all the same,
      // so that there are still n - 2 triangles (dropping a vertex would leave n - 3).
      auto turn = [&](std::size_t i) {
        return orientation * orient(at(idx[(i + n - 1) % n]), at(idx[i]), at(idx[(i + 1) % n]));
      };
      std::size_t best = 0;
      for (std::size_t i = 1; i < n; ++i)
        if (turn(i) > turn(best)) best = i;
      out.push_back({idx[(best + n - 1) % n], idx[best], idx[(best + 1) % n]});
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(best));
    }
  }
  if (idx.size() == 3) out.push_back({idx[0], idx[1], idx[2]});
  return out;
}

Box bounding_box(const Polygon& poly) {
  Box box{poly.front(), poly.front()};
  for (const Vec2& v : poly) {
    box.min = box.min.cwiseMin(v);
    box.max = box.max.cwiseMax(v);
  }
  return box;
}

}  // namespace csl
