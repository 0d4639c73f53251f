// Potential fields (homework P13): every force against minus the central finite-difference
// gradient of its potential, rho and grad rho against brute force, the J^T mapping against finite
// differences in configuration space, the conventions at the non-differentiable points, and
// P13's scene with values computed by hand. Runs natively and in wasm.
//
// Finite differences: central, h = 1e-6 (workspace and C-space alike), at fixed-seed random points
// kept away from the kinks (medial axes, obstacle boundaries). The truncation error is about
// h^2 |U'''| / 6 and the rounding error about ulp(U) / h; both are far below the tolerance
// (relative 1e-6 of max(|F|, 1)); the largest errors seen are printed with -s.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/base/angles.hpp"
#include "core/base/rng.hpp"
#include "core/fields/potential.hpp"

using csl::config;
using csl::Config;
using csl::Vec2;

namespace {

constexpr double kH = 1e-6;
constexpr double kRelTol = 1e-6;

// Relative error of a force against a finite-difference force, scaled by max(|F|, 1).
double rel_error(const Vec2& f, const Vec2& fd) { return csl::length(f - fd) / std::max(1.0, csl::length(f)); }

// -grad U at x by central differences.
template <class U>
Vec2 fd_force(const U& u, const Vec2& x) {
  const Vec2 dx(kH, 0.0), dy(0.0, kH);
  return {-(u(x + dx) - u(x - dx)) / (2 * kH), -(u(x + dy) - u(x - dy)) / (2 * kH)};
}

// Distance from x to each edge of a polygon.
std::vector<double> edge_distances(const csl::Polygon& poly, const Vec2& x) {
  std::vector<double> d;
  for (std::size_t i = 0; i < poly.size(); ++i)
    d.push_back(csl::point_segment_distance(x, poly[i], poly[(i + 1) % poly.size()]));
  return d;
}

// Whether x is within `margin` of the polygon's medial axis outside it: a second edge whose
// nearest point is elsewhere (not the shared vertex) is almost as near as the nearest one.
bool near_medial_axis(const csl::Polygon& poly, const Vec2& x, double margin) {
  const auto d = edge_distances(poly, x);
  const auto best = static_cast<std::size_t>(std::min_element(d.begin(), d.end()) - d.begin());
  const Vec2 b = csl::closest_point_on_segment(x, poly[best], poly[(best + 1) % poly.size()]);
  for (std::size_t i = 0; i < poly.size(); ++i) {
    if (i == best) continue;
    const Vec2 c = csl::closest_point_on_segment(x, poly[i], poly[(i + 1) % poly.size()]);
    if (csl::length(c - b) > 1e-9 && d[i] - d[best] < margin) return true;
  }
  return false;
}

// Whether x is a safe place for finite differences of obstacle o's repulsion.
bool smooth_at(const csl::Obstacle& o, const Vec2& x, double rho0) {
  const double rho = csl::obstacle_distance(o, x).rho;
  if (rho < 0.01 || std::fabs(rho - rho0) < 1e-4) return false;
  if (const auto* g = std::get_if<csl::PolygonObstacle>(&o)) return !near_medial_axis(g->vertices, x, 1e-4);
  return true;
}

// A U-shaped (concave) polygon, opening downward: the classic trap.
const csl::Polygon kCup{{0.3, 0.4}, {0.4, 0.4}, {0.4, 0.6}, {0.6, 0.6}, {0.6, 0.4},
                        {0.7, 0.4}, {0.7, 0.7}, {0.3, 0.7}};

std::vector<csl::Obstacle> mixed_obstacles() {
  return {csl::Disk{{0.25, 0.25}, 0.1}, csl::PolygonObstacle{{{0.6, 0.15}, {0.85, 0.2}, {0.75, 0.35}}},
          csl::PolygonObstacle{kCup}, csl::Wall{{0.1, 0.8}, {0.35, 0.95}}};
}

// x before y (separate statements: the order of a call's arguments is unspecified, and GCC and
// Clang differ, which would give the native and wasm builds different points).
Vec2 random_point(csl::Rng& rng, double lo = -0.1, double hi = 1.1) {
  const double x = rng.uniform(lo, hi);
  return {x, rng.uniform(lo, hi)};
}

}  // namespace

TEST_CASE("attractive: quadratic within d, conic beyond, continuous at d, F = -grad U") {
  const Vec2 goal(0.4, 0.6);
  const double zeta = 1.7, d = 0.2;
  // Hand values: |e| = 0.1 (quadratic) and |e| = 0.5 (conic).
  auto in = csl::attractive_field({0.5, 0.6}, goal, zeta, d);
  CHECK(in.U == doctest::Approx(0.5 * zeta * 0.01));
  CHECK(in.F.x() == doctest::Approx(-zeta * 0.1));
  auto out = csl::attractive_field({0.4, 0.1}, goal, zeta, d);
  CHECK(out.U == doctest::Approx(d * zeta * 0.5 - 0.5 * zeta * d * d));
  CHECK(out.F.y() == doctest::Approx(d * zeta));  // length d zeta, toward the goal
  CHECK(out.F.x() == 0.0);
  // Continuity of U and F across |e| = d.
  const auto below = csl::attractive_field({0.4 + d * (1 - 1e-12), 0.6}, goal, zeta, d);
  const auto above = csl::attractive_field({0.4 + d * (1 + 1e-12), 0.6}, goal, zeta, d);
  CHECK(std::fabs(below.U - above.U) < 1e-12);
  CHECK(csl::length(below.F - above.F) < 1e-11);
  // At the goal: no force.
  CHECK(csl::attractive_field(goal, goal, zeta, d).F == Vec2(0, 0));

  csl::Rng rng(11);
  double worst[2] = {0, 0};
  int count[2] = {0, 0};
  for (int i = 0; i < 4000; ++i) {
    const Vec2 x = random_point(rng);
    const double e = csl::length(x - goal);
    if (std::fabs(e - d) < 1e-4 || e < 1e-4) continue;
    const auto u = [&](const Vec2& p) { return csl::attractive_field(p, goal, zeta, d).U; };
    const double err = rel_error(csl::attractive_field(x, goal, zeta, d).F, fd_force(u, x));
    const int regime = e <= d ? 0 : 1;
    worst[regime] = std::max(worst[regime], err);
    ++count[regime];
  }
  MESSAGE("attractive: max rel FD error quadratic " << worst[0] << " (" << count[0] << " points), conic "
                                                    << worst[1] << " (" << count[1] << ")");
  CHECK(count[0] > 50);
  CHECK(count[1] > 1000);
  CHECK(worst[0] < kRelTol);
  CHECK(worst[1] < kRelTol);
}

namespace {
// Points along an obstacle's boundary no more than `spacing` apart (the brute force's input).
std::vector<Vec2> boundary_samples(const csl::Obstacle& o, double& spacing) {
  std::vector<Vec2> out;
  const auto along = [&](const Vec2& a, const Vec2& b, int n) {
    for (int k = 0; k < n; ++k) out.push_back(a + (static_cast<double>(k) / n) * (b - a));
    spacing = std::max(spacing, csl::length(b - a) / n);
  };
  spacing = 0;
  if (const auto* d = std::get_if<csl::Disk>(&o)) {
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * csl::kPi * k / n;
      out.push_back(d->center + d->radius * Vec2(csl::det::cos(a), csl::det::sin(a)));
    }
    spacing = 2 * csl::kPi * d->radius / n;
  } else if (const auto* g = std::get_if<csl::PolygonObstacle>(&o)) {
    for (std::size_t i = 0; i < g->vertices.size(); ++i)
      along(g->vertices[i], g->vertices[(i + 1) % g->vertices.size()], 3000);
  } else {
    const auto& w = std::get<csl::Wall>(o);
    along(w.a, w.b, 3000);
    out.push_back(w.b);
  }
  return out;
}
}  // namespace

TEST_CASE("rho and grad rho against brute force, for every obstacle kind") {
  const auto obstacles = mixed_obstacles();
  csl::Rng rng(5);
  double worst_rho = 0, worst_grad = 0;
  int outside = 0, inside = 0;
  for (const csl::Obstacle& o : obstacles) {
    double spacing = 0;
    const std::vector<Vec2> samples = boundary_samples(o, spacing);
    const csl::Box box = csl::obstacle_bounds(o);
    for (int i = 0; i < 80; ++i) {
      // Half anywhere, half in the obstacle's bounding box (to get points inside it too).
      const Vec2 x = i % 2 ? random_point(rng)
                           : box.min + (random_point(rng, 0, 1).array() * (box.max - box.min).array()).matrix();
      const csl::ObstacleDistance r = csl::obstacle_distance(o, x);
      Vec2 b = samples[0];
      for (const Vec2& s : samples)
        if (csl::length(x - s) < csl::length(x - b)) b = s;
      const double brute = csl::length(x - b);
      CHECK(std::fabs(csl::length(r.grad) - 1.0) < 1e-15);
      const bool in = std::holds_alternative<csl::Wall>(o) ? false : csl::point_clearance(o, x) <= 0;
      CHECK(r.inside == in);
      // Within a sample spacing of the true boundary distance (a chord's sag is far less).
      CHECK(std::fabs(csl::length(x - r.nearest) - brute) <= spacing);
      if (in) {
        ++inside;
        CHECK(r.rho == 0.0);
        // The way out: toward the nearest boundary point.
        CHECK(csl::length(r.grad - (b - x) / brute) <= 2 * spacing / brute);
        continue;
      }
      ++outside;
      worst_rho = std::max(worst_rho, std::fabs(r.rho - brute));
      CHECK(std::fabs(r.rho - brute) <= spacing);
      if (const auto* g = std::get_if<csl::PolygonObstacle>(&o); g && near_medial_axis(g->vertices, x, 1e-3)) continue;
      const double grad_error = csl::length(r.grad - (x - b) / brute);
      if (brute > 0.05) worst_grad = std::max(worst_grad, grad_error);  // where samples resolve it
      CHECK(grad_error <= 2 * spacing / brute);
    }
  }
  MESSAGE("rho vs brute force: " << outside << " outside, " << inside << " inside; max |rho - brute| " << worst_rho
                                 << ", max |grad - brute| (rho > 0.05) " << worst_grad);
  CHECK(outside > 200);
  CHECK(inside > 40);
}

TEST_CASE("grad rho is the finite-difference gradient of rho off the kinks") {
  const auto obstacles = mixed_obstacles();
  csl::Rng rng(8);
  double worst = 0;
  int n = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec2 x = random_point(rng);
    for (const auto& o : obstacles) {
      if (!smooth_at(o, x, 1e9)) continue;
      const auto rho = [&](const Vec2& p) { return csl::obstacle_distance(o, p).rho; };
      const Vec2 g = -fd_force(rho, x);
      worst = std::max(worst, csl::length(csl::obstacle_distance(o, x).grad - g));
      ++n;
    }
  }
  MESSAGE("grad rho vs FD: max error " << worst << " over " << n << " points");
  CHECK(n > 8000);
  CHECK(worst < 1e-6);
}

TEST_CASE("the conventions where rho has no gradient") {
  // The disk's centre: +x. Inside: the way out, toward the nearest boundary point.
  const csl::Disk disk{{0.5, 0.5}, 0.2};
  CHECK(csl::disk_distance(disk, {0.5, 0.5}).grad == Vec2(1, 0));
  CHECK(csl::disk_distance(disk, {0.5, 0.5}).rho == 0.0);
  CHECK(csl::disk_distance(disk, {0.5, 0.45}).grad == Vec2(0, -1));
  CHECK(csl::disk_distance(disk, {0.5, 0.45}).nearest.y() == doctest::Approx(0.3));
  // A polygon (clockwise here): on an edge, the outward normal; inside, the nearest way out.
  const csl::Polygon square_cw{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  auto r = csl::polygon_distance(square_cw, {0.5, 1.0});
  CHECK(r.inside);
  CHECK(r.rho == 0.0);
  CHECK(r.grad == Vec2(0, 1));
  r = csl::polygon_distance(square_cw, {0.0, 0.3});
  CHECK(r.grad == Vec2(-1, 0));
  r = csl::polygon_distance(square_cw, {0.9, 0.5});
  CHECK(r.grad == Vec2(1, 0));
  CHECK(r.nearest == Vec2(1.0, 0.5));
  // At a vertex on the boundary: the outward normal of the lower-index edge through it. Vertex
  // (1, 1) joins edge 1 ((0,1) -> (1,1), normal +y) and edge 2 ((1,1) -> (1,0), normal +x).
  CHECK(csl::polygon_distance(square_cw, {1.0, 1.0}).grad == Vec2(0, 1));
  // Inside, equidistant from all four edges (the centre): edge 0 wins, way out -x.
  CHECK(csl::polygon_distance(square_cw, {0.5, 0.5}).grad == Vec2(-1, 0));
  // Outside a concave polygon, on the medial axis: in the cup's mouth, x = 0.5 is equidistant
  // from the inner faces of both arms (edges 1: x = 0.4 and 3: x = 0.6); the lower index wins.
  r = csl::polygon_distance(kCup, {0.5, 0.5});
  CHECK_FALSE(r.inside);
  CHECK(r.rho == doctest::Approx(0.1));
  CHECK(r.grad == Vec2(1, 0));  // away from edge 1 (x = 0.4)
  CHECK(r.nearest.x() == doctest::Approx(0.4));
  // A wall: on it, its left normal; a degenerate wall, +x; elsewhere away from the nearest point.
  CHECK(csl::segment_distance({0, 0}, {1, 0}, {0.5, 0}).grad == Vec2(0, 1));
  CHECK(csl::segment_distance({1, 0}, {0, 0}, {0.5, 0}).grad == Vec2(0, -1));
  CHECK(csl::segment_distance({0.2, 0.2}, {0.2, 0.2}, {0.2, 0.2}).grad == Vec2(1, 0));
  CHECK(csl::segment_distance({0, 0}, {1, 0}, {1.3, 0.4}).rho == doctest::Approx(0.5));
  CHECK(csl::segment_distance({0, 0}, {1, 0}, {1.3, 0.4}).grad.x() == doctest::Approx(0.6));
  // The repulsion on contact: U = +inf, an infinite push along grad rho, zero across it.
  const auto contact = csl::repulsive_field(csl::disk_distance(disk, {0.5, 0.45}), 1e-3, 0.1);
  CHECK(std::isinf(contact.U));
  CHECK(contact.F.x() == 0.0);
  CHECK(contact.F.y() == -std::numeric_limits<double>::infinity());
}

TEST_CASE("repulsive: F = -grad U for each obstacle kind, zero beyond rho0") {
  const auto obstacles = mixed_obstacles();
  const double eta = 1e-3, rho0 = 0.15;
  const char* const names[] = {"disk", "triangle (convex)", "cup (concave)", "wall"};
  csl::Rng rng(21);
  for (std::size_t j = 0; j < obstacles.size(); ++j) {
    const csl::Obstacle& o = obstacles[j];
    double worst = 0;
    int n = 0, zero = 0;
    for (int i = 0; i < 20000 && n < 500; ++i) {
      const Vec2 x = random_point(rng);
      const csl::ObstacleDistance r = csl::obstacle_distance(o, x);
      const csl::FieldValue f = csl::repulsive_field(r, eta, rho0);
      if (r.rho > rho0) {
        CHECK(f.U == 0.0);
        CHECK(f.F == Vec2(0, 0));
        ++zero;
        continue;
      }
      if (!smooth_at(o, x, rho0)) continue;
      const auto u = [&](const Vec2& p) { return csl::repulsive_field(csl::obstacle_distance(o, p), eta, rho0).U; };
      worst = std::max(worst, rel_error(f.F, fd_force(u, x)));
      // (5.5) and (5.6) literally.
      CHECK(f.U == doctest::Approx(0.5 * eta * (1 / r.rho - 1 / rho0) * (1 / r.rho - 1 / rho0)));
      ++n;
    }
    MESSAGE("repulsive, " << std::string(names[j]) << ": max rel FD error " << worst << " over " << n << " points");
    CHECK(n >= 100);
    CHECK(zero > 0);
    CHECK(worst < kRelTol);
  }
}

TEST_CASE("the total workspace force of a point robot is -grad U (every obstacle, both regimes)") {
  const csl::CollisionWorld world(csl::PointRobot{}, mixed_obstacles(), {0, 0}, {1, 1});
  csl::PotentialParams params;
  params.eta = 1e-3;
  params.rho0 = 0.15;
  const csl::PotentialField field(world, config({0.9, 0.9}), params);
  csl::Rng rng(3);
  double worst = 0;
  int n = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec2 x = random_point(rng, 0, 1);
    const bool smooth = std::all_of(world.obstacles().begin(), world.obstacles().end(), [&](const csl::Obstacle& o) {
      const double rho = csl::obstacle_distance(o, x).rho;
      return rho > params.rho0 + 1e-4 || smooth_at(o, x, params.rho0);
    });
    if (!smooth) continue;
    const Config q = config({x.x(), x.y()});
    const auto u = [&](const Vec2& p) { return field.potential(config({p.x(), p.y()})); };
    const auto g = field.gradient(q);
    worst = std::max(worst, rel_error(Vec2(g.tau[0], g.tau[1]), fd_force(u, x)));
    // The report's totals are the same numbers, bit for bit.
    const auto report = field.evaluate(q);
    REQUIRE(report.U == g.U);
    REQUIRE(report.tau == g.tau);
    REQUIRE(report.F.x() == g.tau[0]);
    ++n;
  }
  MESSAGE("point robot total: max rel FD error " << worst << " over " << n << " points");
  CHECK(n > 2000);
  CHECK(worst < kRelTol);
}

namespace {
// Max relative error of tau(q) against -grad_q U by central differences, over free random q
// whose control points are all away from kinks.
double cspace_fd_error(const csl::PotentialField& field, int samples, std::uint64_t seed, int& used) {
  const csl::CollisionWorld& world = field.world();
  csl::Rng rng(seed);
  double worst = 0;
  used = 0;
  for (int i = 0; i < samples; ++i) {
    const Config q = world.space().sample(rng);
    if (!world.is_free(q)) continue;
    bool smooth = true;
    for (const auto& c : csl::control_points(world.robot(), q))
      for (const auto& o : world.obstacles()) {
        const double rho = csl::obstacle_distance(o, c.position).rho;
        smooth = smooth && (rho > field.params().rho0 + 1e-4 || smooth_at(o, c.position, field.params().rho0));
      }
    if (!smooth) continue;
    const Config tau = field.gradient(q).tau;
    Config fd(q.size());
    for (Eigen::Index k = 0; k < q.size(); ++k) {
      Config a = q, b = q;
      a[k] += kH;
      b[k] -= kH;
      fd[k] = -(field.potential(a) - field.potential(b)) / (2 * kH);
    }
    double diff = 0, norm = 0;
    for (Eigen::Index k = 0; k < q.size(); ++k) {
      diff += (tau[k] - fd[k]) * (tau[k] - fd[k]);
      norm += tau[k] * tau[k];
    }
    worst = std::max(worst, std::sqrt(diff) / std::max(1.0, std::sqrt(norm)));
    ++used;
  }
  return worst;
}
}  // namespace

TEST_CASE("SE(2): tau = sum J^T F is -grad_q U (forces and torque)") {
  const auto robot = csl::make_polygon_robot({{-0.06, -0.03}, {0.06, -0.03}, {0.08, 0.02}, {-0.04, 0.04}});
  const csl::CollisionWorld world(robot, mixed_obstacles(), {0, 0}, {1, 1});
  csl::PotentialParams params;
  params.eta = 1e-3;
  params.rho0 = 0.15;
  const csl::PotentialField field(world, config({0.85, 0.9, 2.0}), params);
  int used = 0;
  const double worst = cspace_fd_error(field, 3000, 17, used);
  MESSAGE("SE(2): max rel FD error of (Fx, Fy, torque) " << worst << " over " << used << " configurations");
  CHECK(used > 1000);
  CHECK(worst < kRelTol);
  // The Jacobian itself: columns are d o / dx, d o / dy, d o / dtheta by differences.
  const Config q = config({0.3, 0.6, 0.7});
  const auto cps = csl::control_points(world.robot(), q);
  for (std::size_t i = 0; i < cps.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      Config a = q, b = q;
      a[k] += kH;
      b[k] -= kH;
      const Vec2 d = (csl::control_points(world.robot(), a)[i].position - csl::control_points(world.robot(), b)[i].position) / (2 * kH);
      CHECK(csl::length(d - cps[i].jacobian.col(k)) < 1e-9);
    }
}

TEST_CASE("arm: tau = J_elbow^T F_elbow + J_tip^T F_tip is -grad_q U (joint torques)") {
  const csl::CollisionWorld world(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.25}, mixed_obstacles(), {0, 0}, {1, 1});
  csl::PotentialParams params;
  params.eta = 1e-3;
  params.rho0 = 0.15;
  const csl::PotentialField field(world, config({1.2, -0.8}), params);
  int used = 0;
  const double worst = cspace_fd_error(field, 6000, 19, used);
  MESSAGE("arm: max rel FD error of the joint torques " << worst << " over " << used << " configurations");
  CHECK(used > 400);
  CHECK(worst < kRelTol);
  // The textbook Jacobians at a hand-checkable pose: theta1 = 0, theta2 = pi/2.
  const auto cps = csl::control_points(world.robot(), config({0.0, csl::kPi / 2}));
  CHECK(cps[0].position.x() == doctest::Approx(0.8));
  CHECK(cps[0].jacobian(1, 0) == doctest::Approx(0.3));   // l1 c1
  CHECK(cps[0].jacobian(0, 1) == 0.0);                    // the elbow ignores theta2
  CHECK(cps[1].position.y() == doctest::Approx(0.75));
  CHECK(cps[1].jacobian(0, 0) == doctest::Approx(-0.25));  // -l1 s1 - l2 s12
  CHECK(cps[1].jacobian(1, 0) == doctest::Approx(0.3));    // l1 c1 + l2 c12
  CHECK(cps[1].jacobian(0, 1) == doctest::Approx(-0.25));  // -l2 s12
  CHECK(std::fabs(cps[1].jacobian(1, 1)) < 1e-16);         // l2 c12
}

TEST_CASE("P13: a rectangle robot, two polygon obstacles, forces at the four vertices") {
  // Regions of influence rho0 = 0.15 do not overlap: the obstacles are 0.32 apart (the square's
  // corner (0.65, 0.55) to the triangle's vertex (0.4, 0.75)), more than 2 rho0.
  const auto robot = csl::make_polygon_robot({{-0.1, -0.05}, {0.1, -0.05}, {0.1, 0.05}, {-0.1, 0.05}});
  const csl::Polygon square{{0.65, 0.35}, {0.85, 0.35}, {0.85, 0.55}, {0.65, 0.55}};
  const csl::Polygon triangle{{0.15, 0.75}, {0.4, 0.75}, {0.25, 0.95}};
  CHECK(csl::polygon_polygon_distance(square, triangle) > 0.3);
  const csl::CollisionWorld world(robot, {csl::PolygonObstacle{square}, csl::PolygonObstacle{triangle}}, {0, 0}, {1, 1});
  csl::PotentialParams params;
  params.eta = 1e-3;
  params.rho0 = 0.15;
  const csl::PotentialField field(world, config({0.2, 0.25, 0.0}), params);
  // At q = (0.5, 0.56, 0) the vertices are a1 = (0.4, 0.51), a2 = (0.6, 0.51), a3 = (0.6, 0.61),
  // a4 = (0.4, 0.61). By hand:
  //   a1: 0.25 from the square, 0.24 from the triangle: outside both regions, no force.
  //   a2: nearest (0.65, 0.51) on the square's left edge: rho = 0.05, grad rho = (-1, 0),
  //       F = 1e-3 (20 - 6.667) / 0.0025 (-1, 0) = (-5.3333, 0), U = 0.5e-3 (13.333)^2 = 0.088889.
  //   a3: nearest the square's corner (0.65, 0.55): rho = sqrt(0.05^2 + 0.06^2) = 0.078102,
  //       grad rho = (-0.05, 0.06) / rho = (-0.64018, 0.76822),
  //       |F| = 1e-3 (12.8037 - 6.6667) / 0.0061 = 1.00607, F = (-0.64407, 0.77288), U = 0.018832.
  //   a4: nearest the triangle's vertex (0.4, 0.75): rho = 0.14, grad rho = (0, -1),
  //       F = 1e-3 (7.1429 - 6.6667) / 0.0196 (0, -1) = (0, -0.024295), U = 0.00011338.
  //   Net workspace force (-5.97740, 0.74859). Torque about (x, y), R v = v at theta = 0:
  //   sum v_x F_y - v_y F_x = -0.266667 + 0.109492 + 0.002430 = -0.154745.
  const auto r = field.evaluate(config({0.5, 0.56, 0.0}));
  REQUIRE(r.points.size() == 4);
  CHECK(r.points[0].terms.empty());
  CHECK(r.points[0].repulsive.F == Vec2(0, 0));
  CHECK(r.points[1].nearest_obstacle == 0);
  CHECK(r.points[1].nearest.rho == doctest::Approx(0.05));
  CHECK(r.points[1].nearest.grad.x() == doctest::Approx(-1.0));
  CHECK(r.points[1].repulsive.F.x() == doctest::Approx(-5.333333333));
  CHECK(r.points[1].repulsive.U == doctest::Approx(0.0888888889));
  CHECK(r.points[2].nearest_obstacle == 0);
  CHECK(r.points[2].nearest.rho == doctest::Approx(0.0781024968));
  CHECK(r.points[2].nearest.grad.x() == doctest::Approx(-0.6401843997));
  CHECK(r.points[2].nearest.grad.y() == doctest::Approx(0.7682212796));
  CHECK(r.points[2].repulsive.F.x() == doctest::Approx(-0.6440697236));
  CHECK(r.points[2].repulsive.F.y() == doctest::Approx(0.7728836683));
  CHECK(r.points[2].repulsive.U == doctest::Approx(0.0188315154));
  CHECK(r.points[3].nearest_obstacle == 1);
  CHECK(r.points[3].nearest.rho == doctest::Approx(0.14));
  CHECK(r.points[3].repulsive.F.y() == doctest::Approx(-0.0242954325));
  CHECK(r.points[3].repulsive.U == doctest::Approx(0.0001133787));
  for (const auto& p : r.points) CHECK(p.terms.size() <= 1);  // regions of influence apart
  CHECK(r.F_rep.x() == doctest::Approx(-5.97740305689));
  CHECK(r.F_rep.y() == doctest::Approx(0.748588235813));
  CHECK(r.tau_rep[0] == doctest::Approx(-5.97740305689));
  CHECK(r.tau_rep[1] == doctest::Approx(0.748588235813));
  CHECK(r.tau_rep[2] == doctest::Approx(-0.154745270416));
  CHECK(r.U_rep == doctest::Approx(0.107833782955));
  CHECK_FALSE(r.contact);
}
