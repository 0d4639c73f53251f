// The exact C-space map of the 2-link arm: against brute force (CollisionWorld::is_free at every
// pixel centre) on seeded random scenes, hand-computed interval ends, whole blocked columns,
// intervals across -pi/pi, the free fraction, and the interval invariants.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/base/angles.hpp"
#include "core/base/rng.hpp"
#include "core/checking/collision.hpp"
#include "core/teaching/cspace_map.hpp"

#include "random_polygon.hpp"

using csl::AngleInterval;
using csl::config;
using csl::kPi;
using csl::kTwoPi;

namespace {

// Sorted, disjoint (with a gap: touching ones are merged), inside [-pi, pi].
void check_invariants(const std::vector<AngleInterval>& v) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    REQUIRE(v[k].lo <= v[k].hi);
    REQUIRE(v[k].lo >= -kPi);
    REQUIRE(v[k].hi <= kPi);
    if (k > 0) REQUIRE(v[k - 1].hi < v[k].lo);
  }
}

bool in_intervals(const std::vector<AngleInterval>& v, double t) {
  for (const AngleInterval& iv : v)
    if (iv.lo <= t && t <= iv.hi) return true;
  return false;
}

// A simple star-shaped polygon about c (random_polygon.hpp), kept only above 1e-4 * size² in
// twice its area.
csl::Polygon random_polygon(csl::Rng& rng, const csl::Vec2& c, double size) {
  return csl::test::random_star_polygon_about(rng, c, size, 1e-4);
}

struct RandomScene {
  csl::ArmRobot arm;
  std::vector<csl::Obstacle> obstacles;
};

// kinds: bit 0 disks, bit 1 polygons, bit 2 walls. The base is anywhere in [0,1]^2 or beyond
// (some bases see no obstacle within reach of link 1, some lie inside one).
RandomScene random_scene(std::uint64_t seed, int kinds) {
  csl::Rng rng(seed);
  RandomScene s;
  const double bx = rng.uniform(0.1, 0.9);
  const double by = rng.uniform(0.1, 0.9);
  const double l1 = rng.uniform(0.1, 0.35);
  s.arm = csl::ArmRobot{{bx, by}, l1, rng.uniform(0.1, 0.35)};
  const int count = 3 + static_cast<int>(rng.below(8));
  for (int k = 0; k < count; ++k) {
    int kind;
    do kind = static_cast<int>(rng.below(3));
    while (!(kinds & (1 << kind)));
    // One draw per statement: the order of function arguments' evaluation is unspecified
    // (GCC and Clang differ), and the scenes must be the same natively and in wasm.
    const double cx = rng.uniform01();
    const double cy = rng.uniform01();
    const csl::Vec2 c(cx, cy);
    if (kind == 0) {
      s.obstacles.push_back(csl::Disk{c, rng.uniform(0.02, 0.12)});
    } else if (kind == 1) {
      s.obstacles.push_back(csl::PolygonObstacle{random_polygon(rng, c, rng.uniform(0.05, 0.2))});
    } else {
      const double a = rng.uniform(-kPi, kPi), len = rng.uniform(0.05, 0.5);
      s.obstacles.push_back(csl::Wall{c, c + len * csl::Vec2(csl::det::cos(a), csl::det::sin(a))});
    }
  }
  return s;
}

struct Agreement {
  long long pixels = 0, disagree = 0, not_at_boundary = 0, free = 0;
  double fraction() const { return 1.0 - static_cast<double>(disagree) / static_cast<double>(pixels); }
};

// Whether is_free changes within `h` radians of q in some direction (q lies on a boundary).
bool near_boundary(const csl::CollisionWorld& world, double t1, double t2, double h) {
  const bool here = world.is_free(config({t1, t2}));
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b)
      if (world.is_free(config({t1 + a * h, t2 + b * h})) != here) return true;
  return false;
}

// The exact map's raster against is_free at every pixel centre.
Agreement compare_with_brute_force(const RandomScene& s, int resolution) {
  const csl::ArmCSpaceMap map(s.arm, s.obstacles);
  const csl::CollisionWorld world(s.arm, s.obstacles, {0, 0}, {1, 1});
  std::vector<std::uint8_t> pixels;
  const double free_fraction = map.rasterize(resolution, pixels);
  REQUIRE(pixels.size() == static_cast<std::size_t>(resolution * resolution));
  Agreement a;
  std::vector<AngleInterval> column;
  for (int i = 0; i < resolution; ++i) {
    const double t1 = csl::cspace_pixel_angle(i, resolution);
    map.blocked_theta2(t1, column);
    check_invariants(column);
    for (int j = 0; j < resolution; ++j) {
      const double t2 = csl::cspace_pixel_angle(j, resolution);
      const std::uint8_t p = pixels[static_cast<std::size_t>(j * resolution + i)];
      REQUIRE((p == 0 || p == 255));
      REQUIRE((p == 0) == in_intervals(column, t2));  // the raster is the intervals
      ++a.pixels;
      a.free += p == 255;
      if ((p == 255) != world.is_free(config({t1, t2}))) {
        ++a.disagree;
        if (!near_boundary(world, t1, t2, 1e-7)) ++a.not_at_boundary;
      }
    }
  }
  CHECK(free_fraction == static_cast<double>(a.free) / static_cast<double>(a.pixels));
  return a;
}

}  // namespace

TEST_CASE("the exact map agrees with is_free at pixel centres on random scenes") {
  // 8 scenes each of disks, polygons (many concave), walls, and mixed: 32 scenes.
  const int kinds[] = {1, 2, 4, 7};
  const int resolution = 128;
  double worst = 1.0;
  long long pixels = 0, disagree = 0, blocked_pixels = 0;
  int scenes_with_both = 0;
  for (int kind : kinds)
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const RandomScene s = random_scene(seed * 100 + static_cast<std::uint64_t>(kind), kind);
      CAPTURE(kind);
      CAPTURE(seed);
      const Agreement a = compare_with_brute_force(s, resolution);
      CHECK(a.not_at_boundary == 0);
      CHECK(a.fraction() >= 0.999);
      worst = std::min(worst, a.fraction());
      pixels += a.pixels;
      disagree += a.disagree;
      blocked_pixels += a.pixels - a.free;
      scenes_with_both += a.free > 0 && a.free < a.pixels;
    }
  CHECK(scenes_with_both >= 24);                           // the scenes are not trivial
  CHECK(blocked_pixels > pixels / 10);
  MESSAGE("exact C-space map vs is_free at pixel centres: 32 scenes of " << resolution << "^2, worst agreement "
          << 100.0 * worst << "%, " << disagree << " of " << pixels << " pixels differ");
}

TEST_CASE("blocked() agrees with is_free at random configurations") {
  csl::Rng rng(77);
  long long n = 0, differ = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const RandomScene s = random_scene(seed * 7919, 7);
    const csl::ArmCSpaceMap map(s.arm, s.obstacles);
    const csl::CollisionWorld world(s.arm, s.obstacles, {0, 0}, {1, 1});
    for (int k = 0; k < 2000; ++k) {
      const double t1 = rng.uniform(-kPi, kPi), t2 = rng.uniform(-kPi, kPi);
      ++n;
      if (map.blocked(t1, t2) != world.is_free(config({t1, t2}))) continue;  // they agree
      ++differ;
      CHECK(near_boundary(world, t1, t2, 1e-7));
    }
    // Angles outside the chart wrap.
    CHECK(map.blocked(0.3 + kTwoPi, -0.2 - kTwoPi) == map.blocked(0.3, -0.2));
  }
  CHECK(differ <= n / 1000);
}

TEST_CASE("a disk within reach of link 2: interval ends by hand") {
  // Base at the origin, l1 = l2 = 1; at theta1 = 0 the elbow is (1, 0).
  const csl::ArmRobot arm{{0, 0}, 1.0, 1.0};
  std::vector<AngleInterval> v;

  SUBCASE("the tangent from the elbow touches within the link: half-width asin(r / d)") {
    // d = 0.5, r = 0.3: tangent length 0.4 <= l2, half-width asin(0.6).
    const csl::ArmCSpaceMap map(arm, {csl::Disk{{1.5, 0.0}, 0.3}});
    map.blocked_theta2(0.0, v);
    REQUIRE(v.size() == 1);
    CHECK(v[0].lo == doctest::Approx(-std::asin(0.6)).epsilon(1e-14));
    CHECK(v[0].hi == doctest::Approx(std::asin(0.6)).epsilon(1e-14));
    // Elbow up at (0, 1), the disk to its right at (1.5, 1): link 2 at absolute angle 0, i.e.
    // theta2 = -pi/2.
    const csl::ArmCSpaceMap up(arm, {csl::Disk{{0.5, 1.0}, 0.3}});
    up.blocked_theta2(kPi / 2, v);
    REQUIRE(v.size() == 1);
    CHECK(v[0].lo == doctest::Approx(-kPi / 2 - std::asin(0.6)).epsilon(1e-14));
    CHECK(v[0].hi == doctest::Approx(-kPi / 2 + std::asin(0.6)).epsilon(1e-14));
  }

  SUBCASE("only the tip reaches the disk: half-width from the law of cosines") {
    // d = 1.2, r = 0.3: tangent length sqrt(1.35) > l2 = 1 >= d - r = 0.9, so the tip circle
    // crosses the disk: 1.44 + 1 - 2.4 cos w = 0.09, cos w = 47/48.
    const csl::ArmCSpaceMap map(arm, {csl::Disk{{2.2, 0.0}, 0.3}});
    map.blocked_theta2(0.0, v);
    REQUIRE(v.size() == 1);
    const double w = std::acos(47.0 / 48.0);
    CHECK(v[0].lo == doctest::Approx(-w).epsilon(1e-12));
    CHECK(v[0].hi == doctest::Approx(w).epsilon(1e-12));
    // The ends are where the tip touches the circle.
    const csl::CollisionWorld world(arm, {csl::Disk{{2.2, 0.0}, 0.3}}, {-3, -3}, {3, 3});
    CHECK_FALSE(world.is_free(config({0.0, w * (1 - 1e-9)})));
    CHECK(world.is_free(config({0.0, w * (1 + 1e-9)})));
  }

  SUBCASE("out of reach: d - r > l2") {
    const csl::ArmCSpaceMap map(arm, {csl::Disk{{2.31, 0.0}, 0.3}});
    map.blocked_theta2(0.0, v);
    CHECK(v.empty());
    CHECK(map.link1_blocked().empty());
  }
}

TEST_CASE("whole columns: the elbow inside a disk, link 1 blocked") {
  const csl::ArmRobot arm{{0, 0}, 1.0, 1.0};
  std::vector<AngleInterval> v;
  // A small disk about the elbow at theta1 = 0 (it also meets link 1 there).
  const csl::ArmCSpaceMap elbow(arm, {csl::Disk{{1.0, 0.02}, 0.05}});
  elbow.blocked_theta2(0.0, v);
  REQUIRE(v.size() == 1);
  CHECK(v[0].lo == -kPi);
  CHECK(v[0].hi == kPi);
  CHECK(elbow.link1_blocked_at(0.0));

  // A disk on link 1's path: blocked for theta1 in pi/2 +- asin(0.1 / 0.5) (the tangent
  // length sqrt(0.24) < l1 = 1), whatever theta2.
  const csl::ArmCSpaceMap map(arm, {csl::Disk{{0.0, 0.5}, 0.1}});
  REQUIRE(map.link1_blocked().size() == 1);
  CHECK(map.link1_blocked()[0].lo == doctest::Approx(kPi / 2 - std::asin(0.2)).epsilon(1e-14));
  CHECK(map.link1_blocked()[0].hi == doctest::Approx(kPi / 2 + std::asin(0.2)).epsilon(1e-14));
  map.blocked_theta2(kPi / 2, v);
  REQUIRE(v.size() == 1);
  CHECK((v[0].lo == -kPi && v[0].hi == kPi));
  CHECK(map.blocked(kPi / 2, 1.0));
  // Beside it, link 2 can still swing into the disk from the elbow, but not everywhere.
  map.blocked_theta2(kPi / 2 + 0.5, v);
  check_invariants(v);
  CHECK_FALSE(v.empty());
  CHECK(v.back().hi - v.front().lo < kPi);

  // The whole image column is 0 there.
  std::vector<std::uint8_t> pixels;
  const int n = 64;
  map.rasterize(n, pixels);
  const int i = 48;  // theta1 = -pi + 48.5 * 2pi / 64, about pi/2 + 0.05
  REQUIRE(map.link1_blocked_at(csl::cspace_pixel_angle(i, n)));
  for (int j = 0; j < n; ++j) CHECK(pixels[static_cast<std::size_t>(j * n + i)] == 0);

  // The base inside an obstacle: everything is blocked.
  const csl::ArmCSpaceMap inside(arm, {csl::PolygonObstacle{{{-0.1, -0.1}, {0.1, -0.1}, {0.0, 0.1}}}});
  REQUIRE(inside.link1_blocked().size() == 1);
  CHECK((inside.link1_blocked()[0].lo == -kPi && inside.link1_blocked()[0].hi == kPi));
  CHECK(inside.rasterize(16, pixels) == 0.0);
}

TEST_CASE("sets across -pi/pi are split in two") {
  // l2 > l1: folded back (theta2 near +-pi) the tip reaches past the base, to a disk behind it.
  const csl::ArmRobot arm{{0, 0}, 0.5, 1.0};
  const csl::ArmCSpaceMap map(arm, {csl::Disk{{-0.4, 0.0}, 0.1}});
  std::vector<AngleInterval> v;
  map.blocked_theta2(0.0, v);  // elbow (0.5, 0): d = 0.9, tangent sqrt(0.8) <= 1: asin(1/9)
  REQUIRE(v.size() == 2);
  const double w = std::asin(1.0 / 9.0);
  CHECK(v[0].lo == -kPi);
  CHECK(v[0].hi == doctest::Approx(-kPi + w).epsilon(1e-14));
  CHECK(v[1].lo == doctest::Approx(kPi - w).epsilon(1e-14));
  CHECK(v[1].hi == kPi);
  CHECK(map.blocked(0.0, -kPi));
  CHECK(map.blocked(0.0, kPi - w / 2));
  CHECK_FALSE(map.blocked(0.0, kPi - 2 * w));
  // Link 1 meets the same disk around theta1 = pi: split the same way. d = 0.4, r = 0.1,
  // tangent sqrt(0.15) <= 0.5: half-width asin(1/4).
  REQUIRE(map.link1_blocked().size() == 2);
  CHECK(map.link1_blocked()[0].lo == -kPi);
  CHECK(map.link1_blocked()[0].hi == doctest::Approx(-kPi + std::asin(0.25)).epsilon(1e-14));
  CHECK(map.link1_blocked()[1].lo == doctest::Approx(kPi - std::asin(0.25)).epsilon(1e-14));
  CHECK(map.link1_blocked()[1].hi == kPi);
  CHECK(map.link1_blocked_at(-kPi));
  CHECK(map.link1_blocked_at(kPi));  // wraps to -pi
}

TEST_CASE("walls and polygon edges: arcs between the directions of the chord's ends") {
  const csl::ArmRobot arm{{0, 0}, 1.0, 1.0};
  std::vector<AngleInterval> v;
  // A wall across link 2's reach, x = 1.5 for y in [-0.5, 0.5]; elbow (1, 0). Both ends are
  // within reach (|(0.5, +-0.5)| < 1): directions +-pi/4, widened by the wall's tolerance.
  const csl::ArmCSpaceMap wall(arm, {csl::Wall{{1.5, -0.5}, {1.5, 0.5}}});
  wall.blocked_theta2(0.0, v);
  REQUIRE(v.size() == 1);
  CHECK(v[0].lo == doctest::Approx(-kPi / 4).epsilon(1e-5));
  CHECK(v[0].hi == doctest::Approx(kPi / 4).epsilon(1e-5));
  CHECK(v[0].hi > kPi / 4);  // the capsule is a little wider than the segment
  // A longer wall: the chord inside the reach is y in [-sqrt(0.75), sqrt(0.75)], i.e. the
  // directions +-acos(0.5) = +-pi/3.
  const csl::ArmCSpaceMap chord(arm, {csl::Wall{{1.5, -3.0}, {1.5, 3.0}}});
  chord.blocked_theta2(0.0, v);
  REQUIRE(v.size() == 1);
  CHECK(v[0].lo == doctest::Approx(-kPi / 3).epsilon(1e-5));
  CHECK(v[0].hi == doctest::Approx(kPi / 3).epsilon(1e-5));
  // The same as a square's edge (exact, no tolerance): the chord's ends exactly.
  const csl::ArmCSpaceMap square(arm, {csl::PolygonObstacle{{{1.5, -3.0}, {4.0, -3.0}, {4.0, 3.0}, {1.5, 3.0}}}});
  square.blocked_theta2(0.0, v);
  REQUIRE(v.size() == 1);
  CHECK(v[0].lo == doctest::Approx(-kPi / 3).epsilon(1e-14));
  CHECK(v[0].hi == doctest::Approx(kPi / 3).epsilon(1e-14));
  // A concave C-shape opening towards the elbow: the union of its edges' arcs, checked along
  // the column against is_free.
  const csl::ArmCSpaceMap u(arm, {csl::PolygonObstacle{
                                     {{1.6, -0.6}, {1.8, -0.6}, {1.8, 0.6}, {1.6, 0.6}, {1.6, 0.5}, {1.7, 0.5},
                                      {1.7, -0.5}, {1.6, -0.5}}}});
  u.blocked_theta2(0.0, v);
  check_invariants(v);
  CHECK(v.size() == 1);  // seen from the elbow its parts overlap in direction
  const csl::CollisionWorld world(arm, {csl::PolygonObstacle{{{1.6, -0.6}, {1.8, -0.6}, {1.8, 0.6}, {1.6, 0.6},
                                                              {1.6, 0.5}, {1.7, 0.5}, {1.7, -0.5}, {1.6, -0.5}}}},
                                  {-3, -3}, {3, 3});
  for (int k = -200; k <= 200; ++k) {
    const double t2 = k * 0.004;
    CHECK(world.is_free(config({0.0, t2})) == !in_intervals(v, t2));
  }
}

TEST_CASE("the free fraction") {
  std::vector<std::uint8_t> pixels;
  const csl::ArmRobot arm{{0, 0}, 1.0, 0.001};
  CHECK(csl::ArmCSpaceMap(arm, {}).rasterize(32, pixels) == 1.0);
  CHECK(std::all_of(pixels.begin(), pixels.end(), [](std::uint8_t p) { return p == 255; }));
  // A tiny link 2: the map is (nearly) link 1's blocked band, of width 2 asin(0.1 / 0.5).
  const csl::ArmCSpaceMap map(arm, {csl::Disk{{0.0, 0.5}, 0.1}});
  const int n = 1024;
  const double f = map.rasterize(n, pixels);
  const auto free = std::count(pixels.begin(), pixels.end(), std::uint8_t{255});
  CHECK(f == static_cast<double>(free) / (static_cast<double>(n) * n));
  CHECK(f == doctest::Approx(1.0 - 2.0 * std::asin(0.2) / kTwoPi).epsilon(3.0 / n));
  // Resolution 1: the one pixel is (0, 0) (arm stretched along +x), free here.
  CHECK(map.rasterize(1, pixels) == 1.0);
  CHECK(pixels.size() == 1);
  CHECK(csl::cspace_pixel_angle(0, 1) == 0.0);
}
