// Collision queries: clearances against hand-computed values, is_free agreeing with the
// clearance, and edge checks of the arm and the polygon robot against a very fine grid.
#include <limits>
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "core/base/angles.hpp"
#include "core/checking/edge_check.hpp"

using csl::config;
using csl::kPi;

TEST_CASE("point robot clearance: disk, polygon, wall") {
  const csl::CollisionWorld world(csl::PointRobot{},
                                  {csl::Disk{{0.2, 0.2}, 0.1}, csl::PolygonObstacle{{{0.6, 0.6}, {0.9, 0.6}, {0.9, 0.9}}},
                                   csl::Wall{{0.5, 0.0}, {0.5, 0.4}}},
                                  {0, 0}, {1, 1});
  auto n = world.nearest(config({0.2, 0.35}));
  CHECK(n.obstacle == 0);
  CHECK(n.clearance == doctest::Approx(0.05));
  CHECK(world.clearance(config({0.2, 0.2})) == doctest::Approx(-0.1));  // the disk's centre: depth 0.1
  n = world.nearest(config({0.95, 0.75}));
  CHECK(n.obstacle == 1);
  CHECK(n.clearance == doctest::Approx(0.05));
  n = world.nearest(config({0.53, 0.2}));
  CHECK(n.obstacle == 2);
  CHECK(n.clearance == doctest::Approx(0.03 - csl::kWallTolerance));
  CHECK_FALSE(world.is_free(config({0.5 + 0.5e-6, 0.2})));  // within the wall's tolerance
  CHECK(world.is_free(config({0.5 + 2e-6, 0.2})));
  CHECK(csl::CollisionWorld(csl::PointRobot{}, {}, {0, 0}, {1, 1}).clearance(config({0.5, 0.5})) == std::numeric_limits<double>::infinity());
}

TEST_CASE("arm clearance is the least link-obstacle distance") {
  const csl::ArmRobot arm{{0, 0}, 1.0, 1.0};
  const csl::CollisionWorld world(arm, {csl::Disk{{1.0, 0.5}, 0.2}}, {-2, -2}, {2, 2});
  // Stretched along +x: both links lie on y = 0, the disk is 0.5 above the elbow.
  CHECK(world.clearance(config({0, 0})) == doctest::Approx(0.3));
  // Elbow up at (0, 1), link 2 along +x at y = 1: 0.5 below it.
  CHECK(world.clearance(config({kPi / 2, -kPi / 2})) == doctest::Approx(0.3));
  CHECK_FALSE(world.is_free(config({std::atan2(0.5, 1.0), 0})));  // link 1 through the disk's centre
}

TEST_CASE("is_free agrees with clearance > 0 for every robot and obstacle kind") {
  csl::Rng rng(8);
  std::vector<csl::Obstacle> obstacles = {
      csl::Disk{{0.3, 0.7}, 0.12}, csl::Disk{{0.8, 0.2}, 0.05},
      csl::PolygonObstacle{{{0.55, 0.05}, {0.75, 0.1}, {0.65, 0.15}, {0.7, 0.35}, {0.5, 0.25}}},
      csl::Wall{{0.1, 0.1}, {0.4, 0.3}}};
  const csl::Robot robots[] = {csl::PointRobot{}, csl::ArmRobot{{0.5, 0.5}, 0.3, 0.25},
                               csl::make_polygon_robot({{-0.05, -0.03}, {0.05, -0.03}, {0.05, 0.03}, {-0.05, 0.03}})};
  for (const auto& robot : robots) {
    const csl::CollisionWorld world(robot, obstacles, {0, 0}, {1, 1});
    int free = 0, hit = 0;
    for (int i = 0; i < 5000; ++i) {
      const auto q = world.space().sample(rng);
      const bool f = world.is_free(q);
      REQUIRE(f == (world.clearance(q) > 0.0));
      (f ? free : hit)++;
    }
    CHECK(free > 100);
    CHECK(hit > 100);
  }
}

TEST_CASE("the point robot's clearance is nearest()'s, bit for bit, for any number of disks and shapes") {
  // clearance() takes the disks without a branch, four at a time; nearest() prunes and tracks
  // the obstacle. 0 to 9 disks cover every remainder of four; walls and polygons follow.
  csl::Rng rng(9);
  for (int disks = 0; disks <= 9; ++disks)
    for (int shapes = 0; shapes <= 2; ++shapes) {
      std::vector<csl::Obstacle> obstacles;
      for (int i = 0; i < disks; ++i)
        obstacles.push_back(csl::Disk{{rng.uniform01(), rng.uniform01()}, rng.uniform(0.01, 0.2)});
      if (shapes > 0) obstacles.push_back(csl::Wall{{0.1, 0.9}, {0.6, 0.7}});
      if (shapes > 1) obstacles.push_back(csl::PolygonObstacle{{{0.6, 0.1}, {0.9, 0.15}, {0.8, 0.4}}});
      const csl::CollisionWorld world(csl::PointRobot{}, obstacles, {0, 0}, {1, 1});
      for (int i = 0; i < 2000; ++i) {
        // Some points on a disk's centre or rim, where ties and zeros are.
        csl::Config q = world.space().sample(rng);
        if (disks > 0 && i % 10 == 0) {
          const auto& d = std::get<csl::Disk>(obstacles[static_cast<std::size_t>(i / 10 % disks)]);
          q = config({d.center.x() + (i % 20 == 0 ? d.radius : 0.0), d.center.y()});
        }
        const double fast = world.clearance(q), slow = world.nearest(q).clearance;
        REQUIRE(std::memcmp(&fast, &slow, sizeof fast) == 0);
      }
    }
  // A point on a polygon's edge (clearance -0) and on a disk's rim (+0): equal values, and the
  // sign of the zero is the lower obstacle index's, as nearest() breaks ties.
  for (const bool polygon_first : {true, false}) {
    std::vector<csl::Obstacle> obstacles = {csl::PolygonObstacle{{{0.05, 0.3}, {0.25, 0.3}, {0.25, 0.7}, {0.05, 0.7}}},
                                            csl::Disk{{0.5, 0.5}, 0.25}};
    if (!polygon_first) std::swap(obstacles[0], obstacles[1]);
    const csl::CollisionWorld world(csl::PointRobot{}, obstacles, {0, 0}, {1, 1});
    const csl::Config rim = config({0.25, 0.5});
    const double fast = world.clearance(rim), slow = world.nearest(rim).clearance;
    CHECK(fast == 0.0);
    CHECK(std::signbit(fast) == std::signbit(slow));
  }
}

namespace {
// Whether a very fine grid along p -> q finds a collision.
bool fine_grid_collides(const csl::CollisionWorld& world, const csl::Config& p, const csl::Config& q) {
  return csl::check_edge(world, csl::EdgeCheckerSpec::parse("grid:4001"), p, q).collision;
}

void check_against_fine_grid(const csl::CollisionWorld& world, csl::Rng& rng, int edges) {
  const auto bisection = csl::EdgeCheckerSpec::parse("bisection");
  int agree_collision = 0, agree_free = 0;
  for (int i = 0; i < edges; ++i) {
    const auto p = world.space().sample(rng);
    const auto q = world.space().interpolate(p, world.space().sample(rng), rng.uniform01());
    const auto r = csl::check_edge(world, bisection, p, q);
    const bool fine = fine_grid_collides(world, p, q);
    if (fine) REQUIRE(r.collision);  // sound: never accepts what the fine grid sees colliding
    if (r.collision) {
      // And every collision it reports has a witness (or an unresolved grazing piece).
      const auto at = world.space().interpolate(p, q, *r.collision_t);
      if (fine) REQUIRE(world.clearance(at) <= 0.0);
    }
    agree_collision += fine && r.collision;
    agree_free += !fine && !r.collision;
  }
  CHECK(agree_collision > edges / 10);
  CHECK(agree_free > edges / 10);
  CHECK(agree_collision + agree_free >= edges - edges / 50);  // disagreement only when grazing
}
}  // namespace

TEST_CASE("arm edges: bisection vs a very fine grid") {
  csl::Rng rng(21);
  const csl::CollisionWorld world(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.25},
                                  {csl::Disk{{0.85, 0.6}, 0.08}, csl::Disk{{0.2, 0.3}, 0.1},
                                   csl::PolygonObstacle{{{0.4, 0.85}, {0.6, 0.85}, {0.5, 0.95}}}},
                                  {0, 0}, {1, 1});
  check_against_fine_grid(world, rng, 400);
}

TEST_CASE("polygon robot edges: bisection vs a very fine grid") {
  csl::Rng rng(22);
  const csl::CollisionWorld world(
      csl::make_polygon_robot({{-0.08, -0.03}, {0.08, -0.03}, {0.08, 0.03}, {-0.08, 0.03}}),
      {csl::Disk{{0.3, 0.3}, 0.1}, csl::PolygonObstacle{{{0.6, 0.5}, {0.9, 0.5}, {0.75, 0.8}}},
       csl::Wall{{0.5, 0.0}, {0.5, 0.3}}},
      {0, 0}, {1, 1});
  check_against_fine_grid(world, rng, 300);
}
