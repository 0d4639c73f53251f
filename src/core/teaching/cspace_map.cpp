#include "core/teaching/cspace_map.hpp"

// Derivation. Both links are the same problem: a segment S(phi) = {p + s u(phi), 0 <= s <= L}
// of length L from a fixed pivot p at the absolute angle phi, u(phi) = (cos phi, sin phi)
// (link 1: p = base, L = l1, phi = theta1; link 2: p = elbow(theta1), L = l2,
// phi = theta1 + theta2). Which phi make S(phi) meet a closed set K?
//
// (1) If p is in K, every phi. Otherwise S(phi) meets K exactly when some point k of K with
//     |k - p| <= L lies in the direction phi from p (that point is p + |k - p| u(phi), on
//     S(phi)). So the forbidden directions are the directions, seen from p, of the points of
//     K n B(p, L), B(p, L) the closed disk of radius L about p.
// (2) For K convex, K n B(p, L) is convex and misses p, so its directions form one arc of
//     width <= pi (exactly pi only if p is on K's boundary, which (1) already caught); its
//     end directions are those of extreme points of K n B(p, L).
//
// Disk K = B(c, r), d = |c - p| > r, alpha the direction of c - p. By symmetry the arc is
// alpha +- w. The distance from c to S(phi) grows with |phi - alpha| on [0, pi] (every point
// of the segment moves away from c as it turns away from c), so w is where it reaches r:
//   - d - r > L: even pointing at c the tip stays outside: no arc.
//   - tangent length t = sqrt(d^2 - r^2) <= L: the tangent from p touches the circle within
//     the segment, at |phi - alpha| = asin(r / d) = atan2(r, t); beyond it the segment's line
//     misses the disk. w = atan2(r, t).
//   - t > L >= d - r: the tangent point is out of reach, the boundary is where the tip
//     p + L u crosses the circle: |tip - c|^2 = d^2 + L^2 - 2 d L cos w = r^2, so
//     w = acos((d^2 + L^2 - r^2) / (2 d L)) (in [0, pi/2) here: the argument is in (L/d, 1]).
//
// Segment K = [a, b] (an edge of a polygon or of a wall's rectangle, below). K n B(p, L) is
// the chord [a + t0 (b - a), a + t1 (b - a)] of the segment inside the disk: with f = a - p,
// g = b - a, |f + t g|^2 = L^2 is A t^2 + 2 B t + C = 0, A = g.g, B = f.g, C = f.f - L^2,
// whose roots t = (-B -+ sqrt(B^2 - A C)) / A (no real root: the line misses the disk) are
// clipped to [0, 1] (taken in the stable form q = -(B + sign(B) sqrt(.)), roots q/A and C/q).
// The forbidden arc runs between the directions of the chord's two ends, the short way
// (width < pi since p is not on the segment). An end inside the disk is the vertex itself,
// whose direction is shared by both edges meeting there (computed once per pivot).
//
// Polygon K: for p outside K, S(phi) meets the closed polygon iff it meets its boundary (a
// segment from outside to a point of K crosses the boundary), so the union of its edges' arcs;
// p inside (point_in_polygon, as the collision checks decide): every phi. Concave polygons
// need nothing more.
//
// Wall: is_free calls a link in collision when its distance to the wall [a, b] is
// <= kWallTolerance = rho, i.e. when it meets the capsule [a, b] + B(0, rho), the union of the
// end disks B(a, rho), B(b, rho) and the rectangle with corners a +- rho n, b +- rho n
// (n the unit normal). The rectangle is a convex polygon (its short edges lie inside the end
// disks and add nothing, but cost little), so the wall's arcs are those of two disks and one
// four-edge polygon; p inside the capsule (distance to [a, b] <= rho): every phi.
//
// Link 2's arcs in phi become theta2 = phi - theta1 by a shift and a wrap; an arc passing pi
// is split in two. Where link 1 collides, the whole column is forbidden.

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/base/overloaded.hpp"

namespace csl {
namespace {

// Pruning by squared distances must never drop a piece that touches: compare against bounds
// inflated by far more than the rounding of the squares (as collision.cpp).
constexpr double kSafe = 1.0 + 1e-12;

// The arc of absolute directions [start, start + width] (0 <= width <= pi), shifted by -offset
// into the chart, as one or two closed intervals in [-pi, pi].
void push_arc(double start, double width, double offset, std::vector<AngleInterval>& out) {
  const double lo = wrap_angle(start - offset);
  const double hi = lo + width;
  if (hi < kPi) {
    out.push_back({lo, hi});
    return;
  }
  out.push_back({lo, kPi});
  out.push_back({-kPi, hi - kTwoPi});
}

// The short arc between directions a1 and a2 (the directions of a chord's ends seen from a
// pivot not on it).
void push_between(double a1, double a2, double offset, std::vector<AngleInterval>& out) {
  const double delta = angle_difference(a1, a2);
  if (delta >= 0.0)
    push_arc(a1, delta, offset, out);
  else
    push_arc(a2, -delta, offset, out);
}

// Sorts by lo and merges overlapping or touching intervals (closed sets), in place.
void sort_and_merge(std::vector<AngleInterval>& v) {
  std::sort(v.begin(), v.end(), [](const AngleInterval& x, const AngleInterval& y) { return x.lo < y.lo; });
  std::size_t m = 0;
  for (const AngleInterval& iv : v) {
    if (m > 0 && iv.lo <= v[m - 1].hi) {
      if (iv.hi > v[m - 1].hi) v[m - 1].hi = iv.hi;
    } else {
      v[m++] = iv;
    }
  }
  v.resize(m);
}

// The first pixel index j in [0, n] whose centre angle is >= a (strict: > a).
int first_row(double a, int n, bool strict) {
  const double x = (a + kPi) * (static_cast<double>(n) / kTwoPi) - 0.5;
  int j = x <= 0.0 ? 0 : (x >= n ? n : static_cast<int>(std::ceil(x)));
  // The estimate can be off by one through rounding; the comparisons decide.
  auto below = [&](int k) {
    const double t = cspace_pixel_angle(k, n);
    return strict ? t <= a : t < a;
  };
  while (j > 0 && !below(j - 1)) --j;
  while (j < n && below(j)) ++j;
  return j;
}

bool contains(const std::vector<AngleInterval>& v, double t) {
  for (const AngleInterval& iv : v)
    if (iv.lo <= t && t <= iv.hi) return true;
  return false;
}

}  // namespace

// Per pivot: each vertex relative to the pivot, |v - p|^2 - L^2, and its direction once known.
struct ArmCSpaceMap::Scratch {
  struct Vertex {
    double fx, fy, d;
    double angle;
    bool has_angle;
  };
  std::vector<Vertex> v;
  explicit Scratch(std::size_t n) : v(n) {}
};

void cspace_pixel_span(double lo, double hi, int resolution, int& j0, int& j1) {
  j0 = first_row(lo, resolution, false);
  j1 = first_row(hi, resolution, true);
}

double cspace_pixel_angle(int index, int resolution) {
  return -kPi + (static_cast<double>(index) + 0.5) * (kTwoPi / static_cast<double>(resolution));
}

ArmCSpaceMap::ArmCSpaceMap(const ArmRobot& arm, const std::vector<Obstacle>& obstacles) : arm_(arm) {
  if (arm.links() != 2) throw std::invalid_argument("the exact C-space map is of the 2-link arm (T^2)");
  auto add_chain = [&](int first, Chain::Containment containment, int shape) {
    const int count = static_cast<int>(vertices_.size()) - first;
    Box box{vertices_[static_cast<std::size_t>(first)], vertices_[static_cast<std::size_t>(first)]};
    for (int k = first; k < first + count; ++k) {
      box.min = box.min.cwiseMin(vertices_[static_cast<std::size_t>(k)]);
      box.max = box.max.cwiseMax(vertices_[static_cast<std::size_t>(k)]);
    }
    const Vec2 center = 0.5 * (box.min + box.max);
    double r2 = 0.0;
    for (int k = first; k < first + count; ++k) r2 = std::max(r2, squared_length(vertices_[static_cast<std::size_t>(k)] - center));
    chains_.push_back({first, count, containment, shape, center, std::sqrt(r2) * kSafe});
  };
  for (const Obstacle& o : obstacles)
    std::visit(Overloaded{[&](const Disk& d) { disks_.push_back({d.center.x(), d.center.y(), d.radius}); },
                          [&](const PolygonObstacle& g) {
                            const int first = static_cast<int>(vertices_.size());
                            vertices_.insert(vertices_.end(), g.vertices.begin(), g.vertices.end());
                            polygons_.push_back(g.vertices);
                            add_chain(first, Chain::Containment::InPolygon, static_cast<int>(polygons_.size()) - 1);
                          },
                          [&](const Wall& w) {
                            walls_.push_back(w);
                            disks_.push_back({w.a.x(), w.a.y(), kWallTolerance});
                            const double gx = w.b.x() - w.a.x(), gy = w.b.y() - w.a.y();
                            const double len = std::sqrt(gx * gx + gy * gy);
                            if (!(len > 0.0)) return;  // a point: the capsule is the one disk
                            disks_.push_back({w.b.x(), w.b.y(), kWallTolerance});
                            const Vec2 n(-gy / len * kWallTolerance, gx / len * kWallTolerance);
                            const int first = static_cast<int>(vertices_.size());
                            vertices_.insert(vertices_.end(), {w.a + n, w.b + n, w.b - n, w.a - n});
                            add_chain(first, Chain::Containment::InCapsule, static_cast<int>(walls_.size()) - 1);
                          }},
               o);
  Scratch scratch(vertices_.size());
  if (pivot_arcs(arm_.base, arm_.length(0), 0.0, scratch, link1_))
    link1_.assign(1, {-kPi, kPi});
  else
    sort_and_merge(link1_);
}

bool ArmCSpaceMap::pivot_arcs(const Vec2& pivot, double length, double offset, Scratch& scratch,
                              std::vector<AngleInterval>& out) const {
  const double px = pivot.x(), py = pivot.y();
  const double l2 = length * length;
  for (const DiskPiece& k : disks_) {
    const double fx = k.x - px, fy = k.y - py;
    const double d2 = fx * fx + fy * fy;
    const double reach = length + k.r;
    if (d2 > reach * reach * kSafe) continue;  // surely d - r > L
    const double d = std::sqrt(d2);
    if (d - k.r <= 0.0) return true;  // the pivot in the disk (is_free's test: sqrt(d2) - r <= 0)
    if (d - k.r > length) continue;
    const double alpha = det::atan2(fy, fx);
    const double tangent2 = (d - k.r) * (d + k.r);
    const double w = tangent2 <= l2 ? det::atan2(k.r, std::sqrt(tangent2))
                                    : det::acos((d2 + l2 - k.r * k.r) / (2.0 * d * length));
    push_arc(alpha - w, 2.0 * w, offset, out);
  }
  for (const Chain& c : chains_) {
    const double cx = c.center.x() - px, cy = c.center.y() - py;
    const double reach = length + c.radius;
    if (cx * cx + cy * cy > reach * reach * kSafe) continue;
    if (c.containment == Chain::Containment::InPolygon) {
      if (point_in_polygon(pivot, polygons_[static_cast<std::size_t>(c.shape)])) return true;
    } else {
      const Wall& w = walls_[static_cast<std::size_t>(c.shape)];
      if (std::sqrt(point_segment_squared_distance(pivot, w.a, w.b)) - kWallTolerance <= 0.0) return true;
    }
    for (int k = c.first; k < c.first + c.count; ++k) {
      const Vec2& v = vertices_[static_cast<std::size_t>(k)];
      Scratch::Vertex& s = scratch.v[static_cast<std::size_t>(k)];
      s.fx = v.x() - px;
      s.fy = v.y() - py;
      s.d = s.fx * s.fx + s.fy * s.fy - l2;
      s.has_angle = false;
    }
    auto angle_of = [&](int k) {
      Scratch::Vertex& s = scratch.v[static_cast<std::size_t>(k)];
      if (!s.has_angle) {
        s.angle = det::atan2(s.fy, s.fx);
        s.has_angle = true;
      }
      return s.angle;
    };
    for (int e = 0; e < c.count; ++e) {
      const int ia = c.first + e, ib = c.first + (e + 1 == c.count ? 0 : e + 1);
      const Scratch::Vertex& a = scratch.v[static_cast<std::size_t>(ia)];
      const Scratch::Vertex& b = scratch.v[static_cast<std::size_t>(ib)];
      const bool a_in = a.d <= 0.0, b_in = b.d <= 0.0;
      if (a_in && b_in) {
        push_between(angle_of(ia), angle_of(ib), offset, out);
        continue;
      }
      const double gx = b.fx - a.fx, gy = b.fy - a.fy;
      const double qa = gx * gx + gy * gy, qb = a.fx * gx + a.fy * gy, qc = a.d;
      const double disc = qb * qb - qa * qc;
      if (disc < 0.0 || !(qa > 0.0)) continue;  // the line misses the disk
      const double root = std::sqrt(disc);
      const double q = -(qb + (qb >= 0.0 ? root : -root));
      double t0 = 0.0, t1 = 0.0;
      if (q != 0.0) {
        t0 = q / qa;
        t1 = qc / q;
        if (t0 > t1) std::swap(t0, t1);
      }
      if (a_in) {
        const double t = std::min(std::max(t1, 0.0), 1.0);
        push_between(angle_of(ia), det::atan2(a.fy + t * gy, a.fx + t * gx), offset, out);
      } else if (b_in) {
        const double t = std::min(std::max(t0, 0.0), 1.0);
        push_between(det::atan2(a.fy + t * gy, a.fx + t * gx), angle_of(ib), offset, out);
      } else {
        // Both ends outside the convex disk: the chord lies inside (0, 1) or misses [0, 1].
        if (t1 < 0.0 || t0 > 1.0) continue;
        const double s0 = std::max(t0, 0.0), s1 = std::min(t1, 1.0);
        push_between(det::atan2(a.fy + s0 * gy, a.fx + s0 * gx), det::atan2(a.fy + s1 * gy, a.fx + s1 * gx), offset,
                     out);
      }
    }
  }
  return false;
}

void ArmCSpaceMap::link2_intervals(double theta1, Scratch& scratch, std::vector<AngleInterval>& out) const {
  out.clear();
  double s1, c1;
  det::sincos(theta1, s1, c1);
  // The elbow exactly as arm_pose computes it.
  const Vec2 elbow(arm_.base.x() + arm_.length(0) * c1, arm_.base.y() + arm_.length(0) * s1);
  if (pivot_arcs(elbow, arm_.length(1), theta1, scratch, out)) {
    out.assign(1, {-kPi, kPi});
    return;
  }
  sort_and_merge(out);
}

bool ArmCSpaceMap::link1_blocked_at(double theta1) const { return contains(link1_, wrap_angle(theta1)); }

void ArmCSpaceMap::blocked_theta2(double theta1, std::vector<AngleInterval>& out) const {
  const double t1 = wrap_angle(theta1);
  if (contains(link1_, t1)) {
    out.assign(1, {-kPi, kPi});
    return;
  }
  Scratch scratch(vertices_.size());
  link2_intervals(t1, scratch, out);
}

bool ArmCSpaceMap::blocked(double theta1, double theta2) const {
  std::vector<AngleInterval> v;
  blocked_theta2(theta1, v);
  return contains(v, wrap_angle(theta2));
}

double ArmCSpaceMap::rasterize(int resolution, std::vector<std::uint8_t>& pixels) const {
  const int n = resolution;
  const auto stride = static_cast<std::size_t>(n);
  pixels.assign(stride * stride, 255);
  Scratch scratch(vertices_.size());
  std::vector<AngleInterval> intervals;
  intervals.reserve(64);
  long long blocked = 0;
  std::size_t next1 = 0;  // link 1's intervals are sorted, like the columns
  for (int i = 0; i < n; ++i) {
    const double theta1 = cspace_pixel_angle(i, n);
    while (next1 < link1_.size() && link1_[next1].hi < theta1) ++next1;
    std::uint8_t* column = pixels.data() + i;
    if (next1 < link1_.size() && link1_[next1].lo <= theta1) {
      for (std::size_t j = 0; j < stride; ++j) column[j * stride] = 0;
      blocked += n;
      continue;
    }
    link2_intervals(theta1, scratch, intervals);
    for (const AngleInterval& iv : intervals) {
      const int j0 = first_row(iv.lo, n, false), j1 = first_row(iv.hi, n, true);
      for (int j = j0; j < j1; ++j) column[static_cast<std::size_t>(j) * stride] = 0;
      if (j1 > j0) blocked += j1 - j0;
    }
  }
  const double total = static_cast<double>(stride) * static_cast<double>(stride);
  return (total - static_cast<double>(blocked)) / total;
}

}  // namespace csl
