// Robots: forward kinematics, their spaces, and the motion bound lambda(p, q) checked against
// the actual motion of points of the robot along the straight line in C-space.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/base/angles.hpp"
#include "core/robots/robot.hpp"

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
    // Its joints written out again here (std::cos and std::sin; the robot's own use det::sincos).
    Vec2 at = arm->base;
    double angle = 0.0;
    for (std::size_t k = 0; k < arm->lengths.size(); ++k) {
      angle += q[static_cast<Eigen::Index>(k)];
      const Vec2 next = at + arm->lengths[k] * Vec2(std::cos(angle), std::sin(angle));
      for (int i = 0; i <= 10; ++i) pts.push_back(at + (i / 10.0) * (next - at));
      at = next;
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
      csl::ArmRobot{{0.5, 0.5}, {0.2, 0.15, 0.1}},
      csl::ArmRobot{{0.2, 0.3}, {0.05, 0.3, 0.1, 0.2}},
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
                               csl::ArmRobot{{0, 0}, {0.3, 0.2, 0.25}},
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

TEST_CASE("an N-link arm: T^N, its joints, and the 2-link arm's numbers unchanged") {
  const csl::ArmRobot three{{0.5, 0.5}, {0.3, 0.2, 0.1}};
  CHECK(csl::robot_dof(three) == 3);
  CHECK(csl::robot_space(three, {0, 0}, {1, 1}).notation() == "T^3");
  CHECK(std::string(csl::robot_type_name(three)) == "arm");
  CHECK(std::string(csl::robot_type_name(csl::ArmRobot{{0, 0}, 0.3, 0.2})) == "arm2");
  CHECK(csl::robot_kind(three) == csl::RobotKind::Arm);
  // Straight out along x, then each joint turned a quarter: a staircase up and back.
  Vec2 j[csl::ArmRobot::kMaxLinks + 1];
  csl::arm_joints(three, config({0.0, kPi / 2, kPi / 2}), j);
  CHECK(j[1].x() == doctest::Approx(0.8));
  CHECK(j[1].y() == doctest::Approx(0.5));
  CHECK(j[2].x() == doctest::Approx(0.8));
  CHECK(j[2].y() == doctest::Approx(0.7));
  CHECK(j[3].x() == doctest::Approx(0.7));
  CHECK(j[3].y() == doctest::Approx(0.7));
  // lambda and K by the formulas: sum l_i |d_1 + ... + d_i|, |a| with a_j = l_j + ... + l_N.
  const double d1 = 0.1, d2 = -0.3, d3 = 0.05;
  CHECK(csl::motion_bound(three, config({0, 0, 0}), config({d1, d2, d3})) ==
        doctest::Approx(0.3 * std::fabs(d1) + 0.2 * std::fabs(d1 + d2) + 0.1 * std::fabs(d1 + d2 + d3)));
  CHECK(csl::motion_lipschitz(three) == doctest::Approx(std::sqrt(0.6 * 0.6 + 0.3 * 0.3 + 0.1 * 0.1)));
  // The 2-link arm's expressions, to the bit (the roadmap hashes pinned elsewhere rest on them).
  const csl::ArmRobot two{{0.1, 0.2}, 0.35, 0.25};
  const auto p = config({0.3, -1.2}), q = config({-2.9, 2.8});
  const double e1 = csl::angle_difference(p[0], q[0]), e2 = csl::angle_difference(p[1], q[1]);
  CHECK(csl::motion_bound(two, p, q) == 0.35 * std::fabs(e1) + 0.25 * std::fabs(e1 + e2));
  CHECK(csl::motion_lipschitz(two) == std::sqrt((0.35 + 0.25) * (0.35 + 0.25) + 0.25 * 0.25));
}
