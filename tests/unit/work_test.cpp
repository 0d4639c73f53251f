// Work estimates (core/teaching/work.hpp): the measure every surface's budget counts in.
#include <doctest/doctest.h>

#include <cmath>

#include "core/base/angles.hpp"
#include "core/scene/scene.hpp"
#include "core/teaching/work.hpp"

namespace {
csl::PrmParams params(int samples, const char* rule, const char* checker) {
  csl::PrmParams p;
  p.samples = samples;
  p.neighbors = csl::NeighborRule::parse(rule);
  p.checker = csl::EdgeCheckerSpec::parse(checker);
  return p;
}
}  // namespace

TEST_CASE("a configuration's cost counts the robot's parts against the obstacles' primitives") {
  std::vector<csl::Obstacle> obstacles{csl::Disk{{0.5, 0.5}, 0.1}, csl::Wall{{0, 0}, {1, 0}},
                                       csl::PolygonObstacle{{{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}}}};
  CHECK(csl::CollisionWorld(csl::PointRobot{}, obstacles, {0, 0}, {1, 1}).evaluation_cost() == 1 + 2 + 2 + 5);
  csl::ArmRobot arm;
  CHECK(csl::CollisionWorld(arm, obstacles, {-2, -2}, {2, 2}).evaluation_cost() == 1 + 3 + 3 + 9);
  const auto robot = csl::make_polygon_robot({{-0.1, -0.1}, {0.1, -0.1}, {0, 0.1}});
  CHECK(csl::CollisionWorld(robot, obstacles, {0, 0}, {1, 1}).evaluation_cost() == 1 + 4 + 4 + 13);
  CHECK(csl::CollisionWorld(csl::PointRobot{}, {}, {0, 0}, {1, 1}).evaluation_cost() == 1);
}

TEST_CASE("a roadmap's work: samples, pairs times the checker's configurations, the search") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.1}}, {0, 0}, {1, 1});
  const double cost = world.evaluation_cost();  // 3
  const auto w = csl::expected_prm_work(world, params(1000, "k:10", "grid:102"));
  CHECK(w.pairs == doctest::Approx(1002 * 10));
  CHECK(w.per_edge == doctest::Approx((1 + 100) * cost));
  CHECK(w.sampling == doctest::Approx(1002 * cost));
  CHECK(w.total() == doctest::Approx(w.sampling + w.connecting + w.neighbours));
  // A Gaussian draw tests two configurations, a bridge draw up to three (core/planning/sampler.hpp).
  auto gaussian = params(1000, "k:10", "grid:102");
  gaussian.sampler = csl::SamplerSpec::parse("gaussian:0.1");
  CHECK(csl::expected_prm_work(world, gaussian).sampling == doctest::Approx(2 * 1002 * cost));
  gaussian.sampler = csl::SamplerSpec::parse("bridge:0.1");
  CHECK(csl::expected_prm_work(world, gaussian).sampling == doctest::Approx(3 * 1002 * cost));
  // The expected edge length for k of n uniform points in the unit square: the disc of area k / n.
  CHECK(csl::expected_edge_length(world.space(), csl::NeighborRule::parse("k:10"), 998) ==
        doctest::Approx(std::sqrt(0.01 / csl::kPi)));
  CHECK(csl::expected_edge_evaluations(csl::EdgeCheckerSpec::parse("step:0.01"), 0.055) == 5);
  CHECK(csl::expected_edge_evaluations(csl::EdgeCheckerSpec::parse("bisection"), 0.5) == csl::kBisectionEvaluationsPerEdge);
}

// The issue's heavy requests, refused by the lab's budget; the lab's largest ordinary ones pass.
TEST_CASE("the lab's budget refuses what would take minutes, and takes what students do") {
  std::vector<csl::Obstacle> polygons;
  for (int i = 0; i < 1000; ++i) {
    csl::Polygon poly;
    for (int k = 0; k < 256; ++k)
      poly.push_back({0.5 + 0.01 * std::cos(2 * csl::kPi * k / 256 + i), 0.5 + 0.01 * std::sin(2 * csl::kPi * k / 256 + i)});
    polygons.push_back(csl::PolygonObstacle{poly});
  }
  const csl::CollisionWorld heavy(csl::PointRobot{}, polygons, {0, 0}, {1, 1});
  CHECK(csl::expected_prm_work(heavy, params(2000, "k:10", "grid:1000000")).total() > csl::kCliMaxWork);
  CHECK(csl::expected_prm_work(heavy, params(2000, "k:10", "bisection")).total() > csl::kLabMaxWork);
  CHECK(csl::expected_prm_work(heavy, params(100, "k:10", "bisection")).total() < csl::kLabMaxWork);
  const csl::Scene demo = csl::scene_from_string(
      R"({"version": 1, "obstacles": [{"type": "disk", "center": [0.3, 0.3], "radius": 0.1},
          {"type": "polygon", "vertices": [[0.5, 0.5], [0.8, 0.5], [0.8, 0.8], [0.5, 0.8]]}]})");
  const csl::CollisionWorld light(demo);
  CHECK(csl::expected_prm_work(light, params(20000, "k:50", "bisection")).total() < csl::kLabMaxWork);
  CHECK(csl::expected_prm_work(light, params(20000, "k:10", "grid:200")).total() < csl::kLabMaxWork);
  // k = 1000 is cheap work here but 2e7 pairs of memory (the wasm ran out): the pairs budget.
  CHECK(csl::expected_candidate_pairs(light.space(), csl::NeighborRule::parse("k:1000"), 20000) > csl::kLabMaxPairs);
  CHECK(csl::expected_candidate_pairs(light.space(), csl::NeighborRule::parse("k:49"), 20000) <= csl::kLabMaxPairs);
}
