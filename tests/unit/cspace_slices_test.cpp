// The exact 3-D C-space slices and volumes (se2_slice, arm3_slice, cspace_volume): against the
// project's collision checker (CollisionWorld::is_free) at dense random points on seeded random
// scenes (convex and concave polygons, disks, walls; robots convex and concave), every
// disagreement within a tiny epsilon of a boundary; the volumes against the exact membership
// at their cell centres; and the free volume converging as the resolution grows.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/base/angles.hpp"
#include "core/base/rng.hpp"
#include "core/checking/collision.hpp"
#include "core/teaching/cspace_volume.hpp"

#include "random_polygon.hpp"

using csl::config;
using csl::kPi;
using csl::Vec2;

namespace {

// A simple star-shaped polygon about c (random_polygon.hpp), kept only above 1e-3 * size² in
// twice its area.
csl::Polygon random_polygon(csl::Rng& rng, const Vec2& c, double size) {
  return csl::test::random_star_polygon_about(rng, c, size, 1e-3);
}

// 2 to 3 of each kind in [0, 1]^2: disks, polygons (convex or not), walls.
std::vector<csl::Obstacle> random_obstacles(csl::Rng& rng, double size) {
  std::vector<csl::Obstacle> out;
  const int count = 2 + static_cast<int>(rng.below(2));
  for (int k = 0; k < count; ++k) {
    const double x = rng.uniform01();
    const double y = rng.uniform01();
    const double r = rng.uniform(0.3, 1.0) * size;
    out.push_back(csl::Disk{{x, y}, r});
    const double px = rng.uniform01();
    const double py = rng.uniform01();
    out.push_back(csl::PolygonObstacle{random_polygon(rng, {px, py}, size * 1.5)});
    const double ax = rng.uniform01();
    const double ay = rng.uniform01();
    const double ang = rng.uniform(-kPi, kPi);
    const double len = rng.uniform(0.5, 2.0) * size;
    out.push_back(csl::Wall{{ax, ay}, {ax + len * csl::det::cos(ang), ay + len * csl::det::sin(ang)}});
  }
  return out;
}

// Whether the checker's verdict changes within eps of (x, y) (either axis): q is on a boundary.
template <class Free>
bool near_boundary(const Free& free, double x, double y, double eps) {
  const bool here = free(x, y);
  return free(x + eps, y) != here || free(x - eps, y) != here || free(x, y + eps) != here || free(x, y - eps) != here;
}

struct Agreement {
  long long points = 0, agree = 0, far_disagree = 0, blocked = 0;
  void report(const char* what) const {
    std::printf("%s: %lld points, %lld agree (%.4f%%), %lld blocked, %lld disagreements away from a boundary\n", what,
                points, agree, 100.0 * static_cast<double>(agree) / static_cast<double>(points), blocked, far_disagree);
  }
};

}  // namespace

TEST_CASE("se2 slice: the exact C-obstacle at theta agrees with the checker at dense points") {
  Agreement a;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    csl::Rng rng(seed * 7919);
    const csl::PolygonRobot robot = csl::make_polygon_robot(random_polygon(rng, {0.0, 0.0}, 0.12));
    const std::vector<csl::Obstacle> obstacles = random_obstacles(rng, 0.1);
    const csl::CollisionWorld world(robot, obstacles, {0, 0}, {1, 1});
    const csl::Se2CObstacles cobstacles(robot, obstacles);
    std::vector<csl::RoundedPolygon> pieces;
    for (int t = 0; t < 4; ++t) {
      const double theta = rng.uniform(-kPi, kPi);
      cobstacles.slice(theta, pieces);
      REQUIRE(pieces.size() == cobstacles.pieces_per_slice());
      const auto free = [&](double x, double y) { return world.is_free(config({x, y, theta})); };
      for (int p = 0; p < 3000; ++p) {
        const double x = rng.uniform(-0.1, 1.1);
        const double y = rng.uniform(-0.1, 1.1);
        const bool exact_blocked = csl::se2_slice_blocked(pieces, {x, y});
        ++a.points;
        a.blocked += exact_blocked;
        if (exact_blocked == !free(x, y)) {
          ++a.agree;
          continue;
        }
        if (!near_boundary(free, x, y, 1e-9)) {
          ++a.far_disagree;
          CHECK_MESSAGE(false, "seed " << seed << " theta " << theta << " at (" << x << ", " << y << "): exact says "
                                       << (exact_blocked ? "blocked" : "free"));
        }
      }
    }
  }
  a.report("se2 slices vs is_free");
  CHECK(a.far_disagree == 0);
  CHECK(static_cast<double>(a.agree) >= 0.999 * static_cast<double>(a.points));
  // Both sides are well represented: a test where everything is free (or blocked) says little.
  CHECK(a.blocked > a.points / 10);
  CHECK(a.blocked < a.points * 9 / 10);
}

TEST_CASE("se2 slice: hand-computed pieces of a square robot against a disk, a wall and a square") {
  // A unit-half square robot [0, 0.1]^2 (reference point at a corner): at theta = 0 its
  // reflection is [-0.1, 0]^2, so a square obstacle [0.5, 0.6]^2 gives [0.4, 0.6]^2.
  const csl::PolygonRobot robot = csl::make_polygon_robot({{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}});
  const std::vector<csl::Obstacle> obstacles = {csl::PolygonObstacle{{{0.5, 0.5}, {0.6, 0.5}, {0.6, 0.6}, {0.5, 0.6}}},
                                                csl::Disk{{0.2, 0.8}, 0.05}, csl::Wall{{0.8, 0.1}, {0.8, 0.3}}};
  const csl::Se2CObstacles cobstacles(robot, obstacles);
  std::vector<csl::RoundedPolygon> pieces;
  cobstacles.slice(0.0, pieces);
  REQUIRE(pieces.size() == 3);
  CHECK(pieces[0].radius == 0.0);
  REQUIRE(pieces[0].hull.size() == 4);
  double lo, hi;
  REQUIRE(csl::rounded_polygon_row(pieces[0], 0.5, lo, hi));
  CHECK(lo == doctest::Approx(0.4));
  CHECK(hi == doctest::Approx(0.6));
  CHECK(csl::se2_slice_blocked(pieces, {0.41, 0.59}));
  CHECK_FALSE(csl::se2_slice_blocked(pieces, {0.39, 0.5}));
  // The disk: the square [0.1, 0.2] x [0.7, 0.8] grown by 0.05; a corner's rounding.
  CHECK(pieces[1].radius == 0.05);
  CHECK(csl::se2_slice_blocked(pieces, {0.06, 0.75}));
  CHECK(csl::se2_slice_blocked(pieces, {0.1 - 0.035, 0.7 - 0.035}));  // 0.0495 from the corner
  CHECK_FALSE(csl::se2_slice_blocked(pieces, {0.1 - 0.036, 0.7 - 0.036}));  // 0.0509
  // The wall: [0.7, 0.8] x [0.0, 0.3] within 1e-6.
  CHECK(csl::se2_slice_blocked(pieces, {0.75, 0.05}));
  CHECK(csl::se2_slice_blocked(pieces, {0.8 + 0.5e-6, 0.2}));
  CHECK_FALSE(csl::se2_slice_blocked(pieces, {0.8 + 2e-6, 0.2}));
  // A quarter turn: the body is [-0.1, 0] x [0, 0.1], reflected [0, 0.1] x [-0.1, 0]: the
  // square obstacle's piece is [0.5, 0.7] x [0.4, 0.6].
  cobstacles.slice(kPi / 2, pieces);
  CHECK(csl::se2_slice_blocked(pieces, {0.69, 0.41}));
  CHECK_FALSE(csl::se2_slice_blocked(pieces, {0.45, 0.5}));
  // The outline of the rounded piece lies on its boundary: radius from the hull.
  cobstacles.slice(0.0, pieces);
  const csl::Polygon outline = csl::rounded_polygon_outline(pieces[1], 0.1);
  CHECK(outline.size() > 4 * 4);
  for (const Vec2& p : outline) {
    double d = HUGE_VAL;
    const csl::Polygon& h = pieces[1].hull;
    for (std::size_t k = 0; k < h.size(); ++k) d = std::min(d, csl::point_segment_distance(p, h[k], h[(k + 1) % h.size()]));
    CHECK(d == doctest::Approx(0.05).epsilon(1e-9));
  }
}

TEST_CASE("se2 volume: every cell is the exact membership at its centre, but within 1e-9 of a boundary") {
  csl::Rng rng(4242);
  const csl::PolygonRobot robot = csl::make_polygon_robot(random_polygon(rng, {0.0, 0.0}, 0.12));
  const std::vector<csl::Obstacle> obstacles = random_obstacles(rng, 0.1);
  const csl::Se2CObstacles cobstacles(robot, obstacles);
  const Vec2 lo(-0.2, 0.0), hi(1.0, 1.3);
  const int nx = 48, ny = 40, nz = 16;
  const csl::CSpaceVolume v = csl::se2_volume(cobstacles, lo, hi, nx, ny, nz);
  REQUIRE(v.cells.size() == static_cast<std::size_t>(nx * ny * nz));
  std::vector<csl::RoundedPolygon> pieces;
  long long differ = 0, free = 0;
  for (int k = 0; k < nz; ++k) {
    cobstacles.slice(csl::cspace_pixel_angle(k, nz), pieces);
    const auto blocked = [&](double x, double y) { return csl::se2_slice_blocked(pieces, {x, y}); };
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double x = csl::volume_cell_centre(lo.x(), hi.x(), i, nx), y = csl::volume_cell_centre(lo.y(), hi.y(), j, ny);
        const std::uint8_t cell = v.cells[static_cast<std::size_t>((k * ny + j) * nx + i)];
        REQUIRE((cell == 0 || cell == 255));
        free += cell == 255;
        if ((cell == 0) != blocked(x, y)) {
          ++differ;
          CHECK(near_boundary(blocked, x, y, 1e-9));
        }
      }
  }
  CHECK(differ <= 2);
  CHECK(v.free_fraction == static_cast<double>(free) / static_cast<double>(v.cells.size()));
  CHECK(v.free_fraction > 0.2);
  CHECK(v.free_fraction < 0.95);
}

TEST_CASE("arm3 slice: the exact (theta2, theta3) slice agrees with the checker at dense points") {
  Agreement a;
  long long whole_slices = 0;
  std::vector<csl::AngleInterval> intervals;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    csl::Rng rng(seed * 104729);
    const double bx = rng.uniform(0.3, 0.7);
    const double by = rng.uniform(0.3, 0.7);
    const double l1 = rng.uniform(0.1, 0.25);
    const double l2 = rng.uniform(0.1, 0.25);
    const double l3 = rng.uniform(0.05, 0.2);
    const csl::ArmRobot arm({bx, by}, std::vector<double>{l1, l2, l3});
    std::vector<csl::Obstacle> obstacles = random_obstacles(rng, 0.08);
    obstacles.push_back(csl::Disk{{bx + 0.8 * l1, by}, 0.02});  // on link 1 at theta1 = 0
    const csl::CollisionWorld world(arm, obstacles, {0, 0}, {1, 1});
    const csl::Arm3Slices slices(arm, obstacles);
    for (int t = 0; t < 5; ++t) {
      const double theta1 = t == 0 ? 0.0 : rng.uniform(-kPi, kPi);
      const csl::Arm3Slices::Slice s = slices.slice(theta1);
      whole_slices += s.all_blocked();
      if (t == 0) CHECK(s.all_blocked());
      const auto free = [&](double t2, double t3) { return world.is_free(config({theta1, t2, t3})); };
      for (int p = 0; p < 3000; ++p) {
        const double t2 = rng.uniform(-kPi, kPi);
        const double t3 = rng.uniform(-kPi, kPi);
        const bool exact_blocked = s.blocked(t2, t3);
        CHECK(exact_blocked == slices.blocked(theta1, t2, t3));
        s.blocked_theta3(t2, intervals);  // the intervals the volume and the CLI use
        CHECK(exact_blocked == std::any_of(intervals.begin(), intervals.end(), [&](const csl::AngleInterval& iv) {
                return iv.lo <= t3 && t3 <= iv.hi;
              }));
        ++a.points;
        a.blocked += exact_blocked;
        if (exact_blocked == !free(t2, t3)) {
          ++a.agree;
          continue;
        }
        if (!near_boundary(free, t2, t3, 1e-9)) {
          ++a.far_disagree;
          CHECK_MESSAGE(false, "seed " << seed << " theta1 " << theta1 << " at (" << t2 << ", " << t3 << ")");
        }
      }
    }
  }
  a.report("arm3 slices vs is_free");
  CHECK(whole_slices >= 8);
  CHECK(a.far_disagree == 0);
  CHECK(static_cast<double>(a.agree) >= 0.999 * static_cast<double>(a.points));
  CHECK(a.blocked > a.points / 10);
  CHECK(a.blocked < a.points * 9 / 10);
}

TEST_CASE("arm3 volume: every cell is the exact slice at its centre; whole slices where link 1 collides") {
  const csl::ArmRobot arm({0.5, 0.5}, std::vector<double>{0.2, 0.15, 0.12});
  csl::Rng rng(77);
  std::vector<csl::Obstacle> obstacles = random_obstacles(rng, 0.08);
  obstacles.push_back(csl::Disk{{0.66, 0.5}, 0.02});
  const csl::Arm3Slices slices(arm, obstacles);
  const int n = 40, nz = 24;
  const csl::CSpaceVolume v = csl::arm3_volume(slices, n, nz);
  REQUIRE(v.cells.size() == static_cast<std::size_t>(n * n * nz));
  long long differ = 0, whole = 0;
  for (int k = 0; k < nz; ++k) {
    const csl::Arm3Slices::Slice s = slices.slice(csl::cspace_pixel_angle(k, nz));
    whole += s.all_blocked();
    const auto blocked = [&](double t2, double t3) { return s.blocked(t2, t3); };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double t2 = csl::cspace_pixel_angle(i, n), t3 = csl::cspace_pixel_angle(j, n);
        const std::uint8_t cell = v.cells[static_cast<std::size_t>((k * n + j) * n + i)];
        if ((cell == 0) != blocked(t2, t3)) {
          ++differ;
          CHECK(near_boundary(blocked, t2, t3, 1e-9));
        }
      }
  }
  CHECK(whole >= 1);
  CHECK(whole < nz);
  CHECK(differ <= 2);
}

TEST_CASE("volumes: the free fraction converges as the resolution grows, to the checker's estimate") {
  csl::Rng rng(99);
  const csl::PolygonRobot robot = csl::make_polygon_robot(random_polygon(rng, {0.0, 0.0}, 0.12));
  const std::vector<csl::Obstacle> obstacles = random_obstacles(rng, 0.1);
  const csl::Se2CObstacles cobstacles(robot, obstacles);
  const csl::ArmRobot arm({0.5, 0.5}, std::vector<double>{0.2, 0.15, 0.12});
  const csl::Arm3Slices arm_slices(arm, obstacles);

  // The error against a fine reference (256 x 256 x 128 and 256^3) shrinks with the resolution:
  // one level to the next can be noisy (a boundary that happens to pass through cell centres),
  // so the coarse levels' worst is compared with the fine levels'.
  const double se2_ref = csl::se2_volume(cobstacles, {0, 0}, {1, 1}, 256, 256, 128).free_fraction;
  const double t3_ref = csl::arm3_volume(arm_slices, 256, 256).free_fraction;
  double se2_err[5], t3_err[5];
  for (int level = 0; level < 5; ++level) {
    const int r = 8 << level;  // 8 .. 128
    se2_err[level] = std::fabs(csl::se2_volume(cobstacles, {0, 0}, {1, 1}, r, r, r / 2).free_fraction - se2_ref);
    t3_err[level] = std::fabs(csl::arm3_volume(arm_slices, r, r).free_fraction - t3_ref);
  }
  std::printf("free fraction SE(2) ref %.5f, errors at 8..128: %.5f %.5f %.5f %.5f %.5f\n", se2_ref, se2_err[0],
              se2_err[1], se2_err[2], se2_err[3], se2_err[4]);
  std::printf("free fraction T^3 ref %.5f, errors at 8..128: %.5f %.5f %.5f %.5f %.5f\n", t3_ref, t3_err[0], t3_err[1],
              t3_err[2], t3_err[3], t3_err[4]);
  CHECK(std::max(se2_err[3], se2_err[4]) < std::max(se2_err[0], se2_err[1]));
  CHECK(std::max(t3_err[3], t3_err[4]) < std::max(t3_err[0], t3_err[1]));
  CHECK(se2_err[4] < 0.005);
  CHECK(t3_err[4] < 0.005);
  // And they converge to the free volume the checker sees at uniform random configurations
  // (20000 samples: a standard error under 0.0036).
  const csl::CollisionWorld world(robot, obstacles, {0, 0}, {1, 1});
  const csl::CollisionWorld arm_world(arm, obstacles, {0, 0}, {1, 1});
  int se2_free = 0, t3_free = 0;
  const int samples = 20000;
  for (int s = 0; s < samples; ++s) {
    const double x = rng.uniform01();
    const double y = rng.uniform01();
    const double t = rng.uniform(-kPi, kPi);
    se2_free += world.is_free(config({x, y, t}));
    const double a1 = rng.uniform(-kPi, kPi);
    const double a2 = rng.uniform(-kPi, kPi);
    const double a3 = rng.uniform(-kPi, kPi);
    t3_free += arm_world.is_free(config({a1, a2, a3}));
  }
  CHECK(std::fabs(se2_ref - se2_free / static_cast<double>(samples)) < 0.015);
  CHECK(std::fabs(t3_ref - t3_free / static_cast<double>(samples)) < 0.015);
  CHECK(se2_ref > 0.1);
  CHECK(se2_ref < 0.95);
  CHECK(t3_ref > 0.1);
  CHECK(t3_ref < 0.95);
}

TEST_CASE("arm3 slices refuse an arm of another size") {
  CHECK_THROWS_AS(csl::Arm3Slices(csl::ArmRobot({0, 0}, 0.3, 0.2), {}), std::invalid_argument);
}
