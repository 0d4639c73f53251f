// Robots: forward kinematics, their spaces, and the motion bound lambda(p, q) checked against
// the actual motion of points of the robot along the straight line in C-space.
#include <doctest/doctest.h>

#include <cmath>

#include "core/angles.hpp"
#include "core/robot.hpp"

using csl::config;
using csl::kPi;
using csl::Vec2;

namespace {
// Points spread over the robot at q: samples along the arm's links / the polygon's edges
// (the farthest-moving points of a rigid polygon lie on its boundary... and inside it move
// less than its vertices, so boundary samples suffice), or the point itself.
std::vector<Vec2> robot_points(const csl::Robot& robot, const csl::Config& q) {
  std::vector<Vec2> pts;
  if (const auto* arm = std::get_if<csl::ArmRobot>(&robot)) {
    const auto pose = csl::arm_pose(*arm, q);
    for (int i = 0; i <= 10; ++i) {
      const double s = i / 10.0;
      pts.push_back(pose.base + s * (pose.elbow - pose.base));
      pts.push_back(pose.elbow + s * (pose.tip - pose.elbow));
    }
  } else if (const auto* poly = std::get_if<csl::PolygonRobot>(&robot)) {
    csl::Polygon world;
    csl::polygon_pose(*poly, q, world);
    for (std::size_t k = 0; k < world.size(); ++k)
      for (int i = 0; i < 5; ++i) pts.push_back(world[k] + (i / 5.0) * (world[(k + 1) % world.size()] - world[k]));
  } else {
    pts.push_back(Vec2(q[0], q[1]));
  }
  return pts;
}

// The longest path any sampled robot point travels along p -> q (fine polyline).
double max_travel(const csl::Robot& robot, const csl::Space& space, const csl::Config& p, const csl::Config& q) {
  constexpr int kSteps = 400;
  std::vector<Vec2> prev = robot_points(robot, p);
  std::vector<double> travelled(prev.size(), 0.0);
  for (int k = 1; k <= kSteps; ++k) {
    const auto now = robot_points(robot, space.interpolate(p, q, double(k) / kSteps));
    for (std::size_t i = 0; i < now.size(); ++i) travelled[i] += (now[i] - prev[i]).norm();
    prev = now;
  }
  double best = 0.0;
  for (double t : travelled) best = std::max(best, t);
  return best;
}
}  // namespace

TEST_CASE("the 2-link arm's forward kinematics (theta2 relative to link 1)") {
  const csl::ArmRobot arm{{0.5, 0.5}, 0.3, 0.2};
  auto pose = csl::arm_pose(arm, config({0, 0}));
  CHECK(pose.elbow.isApprox(Vec2(0.8, 0.5)));
  CHECK(pose.tip.isApprox(Vec2(1.0, 0.5)));
  pose = csl::arm_pose(arm, config({kPi / 2, -kPi / 2}));
  CHECK((pose.elbow - Vec2(0.5, 0.8)).norm() < 1e-15);
  CHECK((pose.tip - Vec2(0.7, 0.8)).norm() < 1e-15);
  pose = csl::arm_pose(arm, config({kPi, kPi}));  // folded back onto link 1
  CHECK((pose.tip - Vec2(0.4, 0.5)).norm() < 1e-15);
}

TEST_CASE("robots have the homework's configuration spaces") {
  CHECK(csl::robot_space(csl::PointRobot{}, {0, 0}, {1, 1}).notation() == "R^2");
  CHECK(csl::robot_space(csl::ArmRobot{}, {0, 0}, {1, 1}).notation() == "T^2");
  const auto poly = csl::make_polygon_robot({{-0.1, -0.05}, {0.1, -0.05}, {0.1, 0.05}, {-0.1, 0.05}});
  const auto se2 = csl::robot_space(poly, {0, 0}, {1, 1});
  CHECK(se2.notation() == "SE(2)");
  CHECK(se2.coordinate(2).weight == doctest::Approx(std::sqrt(0.0125)));
}

TEST_CASE("the polygon robot's pose turns about its reference point") {
  const auto robot = csl::make_polygon_robot({{0, 0}, {1, 0}, {0, 1}});
  csl::Polygon out;
  csl::polygon_pose(robot, config({2, 3, kPi / 2}), out);
  CHECK((out[0] - Vec2(2, 3)).norm() < 1e-15);
  CHECK((out[1] - Vec2(2, 4)).norm() < 1e-15);
  CHECK((out[2] - Vec2(1, 3)).norm() < 1e-15);
}

TEST_CASE("lambda is an upper bound on every point's travel (property, all robots)") {
  csl::Rng rng(77);
  const csl::Robot robots[] = {
      csl::PointRobot{},
      csl::ArmRobot{{0.5, 0.5}, 0.35, 0.25},
      csl::ArmRobot{{0.0, 0.0}, 0.1, 0.9},
      csl::make_polygon_robot({{-0.1, -0.05}, {0.12, -0.04}, {0.1, 0.06}, {0.0, 0.02}, {-0.1, 0.05}}),
  };
  for (const csl::Robot& robot : robots) {
    const auto space = csl::robot_space(robot, {0, 0}, {1, 1});
    double tightest = 0.0;
    for (int i = 0; i < 300; ++i) {
      const auto p = space.sample(rng);
      // Short and long moves, including ones across the seam of S^1.
      auto q = space.sample(rng);
      if (i % 2) q = space.interpolate(p, q, 0.05);
      const double lambda = csl::motion_bound(robot, p, q);
      const double travel = max_travel(robot, space, p, q);
      REQUIRE(travel <= lambda * (1 + 1e-9) + 1e-12);
      if (lambda > 0) tightest = std::max(tightest, travel / lambda);
    }
    // And not uselessly loose: some move comes close to the bound.
    CHECK(tightest > 0.9);
  }
}

TEST_CASE("the arm's lambda uses the wrapped joint differences") {
  const csl::ArmRobot arm{{0, 0}, 1.0, 1.0};
  // From 3 to -3 on S^1 is 2 pi - 6 = 0.283 the short way, not 6.
  const double lambda = csl::motion_bound(arm, config({3.0, 0.0}), config({-3.0, 0.0}));
  CHECK(lambda == doctest::Approx(2 * (csl::kTwoPi - 6.0)));
  // Link 2 keeps its absolute direction when d1 + d2 = 0: only the elbow's motion counts.
  CHECK(csl::motion_bound(arm, config({0.0, 0.0}), config({0.5, -0.5})) == doctest::Approx(0.5));
}

TEST_CASE("lambda <= K d(p, q): the robots' Lipschitz constants bound their motion") {
  csl::Rng rng(31);
  const csl::Robot robots[] = {csl::PointRobot{}, csl::ArmRobot{{0, 0}, 0.7, 0.4},
                               csl::make_polygon_robot({{-0.2, -0.1}, {0.3, -0.1}, {0.1, 0.2}})};
  for (const auto& robot : robots) {
    const auto space = csl::robot_space(robot, {0, 0}, {1, 1});
    const double k = csl::motion_lipschitz(robot);
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
      const auto p = space.sample(rng), q = space.sample(rng);
      const double ratio = csl::motion_bound(robot, p, q) / space.distance(p, q);
      REQUIRE(ratio <= k * (1 + 1e-12));
      worst = std::max(worst, ratio);
    }
    CHECK(worst > 0.97 * k);  // and K is (nearly) attained: not a loose constant
  }
}
