// The limits of the lab, each asked for exactly and once more: the maximum works (in wasm this
// grows the memory well past its initial size), one more is refused with a clear message.
#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/base/angles.hpp"
#include "core/planning/prm.hpp"
#include "core/scene/scene.hpp"

using nlohmann::json;

namespace {
json regular_polygon(std::size_t n, double cx, double cy, double r) {
  json v = json::array();
  for (std::size_t i = 0; i < n; ++i) {
    const double a = csl::kTwoPi * static_cast<double>(i) / static_cast<double>(n);
    v.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return v;
}
}  // namespace

TEST_CASE("the most obstacles and polygon vertices a scene may have, and one more") {
  json scene{{"version", 1}, {"obstacles", json::array()}};
  for (std::size_t i = 0; i < csl::kMaxObstacles; ++i)
    scene["obstacles"].push_back({{"type", "polygon"}, {"vertices", regular_polygon(csl::kMaxPolygonVertices, 0.5, 0.5, 0.0004 * static_cast<double>(i + 1))}});
  const csl::Scene s = csl::scene_from_json(scene);
  CHECK(s.obstacles.size() == csl::kMaxObstacles);
  const csl::CollisionWorld world(s);
  CHECK_FALSE(world.is_free(csl::config({0.5, 0.5})));
  CHECK(world.is_free(csl::config({0.05, 0.05})));

  json more = scene;
  more["obstacles"].push_back(scene["obstacles"][0]);
  CHECK_THROWS_WITH(csl::scene_from_json(more), "obstacles: more than 1000 obstacles");
  json bigger{{"version", 1},
              {"obstacles", {{{"type", "polygon"}, {"vertices", regular_polygon(csl::kMaxPolygonVertices + 1, 0.5, 0.5, 0.2)}}}}};
  CHECK_THROWS_WITH(csl::scene_from_json(bigger), "obstacles[0].vertices: has more than 256 vertices");
  json robot{{"version", 1}, {"robot", {{"type", "polygon"}, {"vertices", regular_polygon(csl::kMaxRobotVertices + 1, 0, 0, 0.05)}}}};
  CHECK_THROWS_WITH(csl::scene_from_json(robot), "robot.vertices: has more than 32 vertices");
}

TEST_CASE("PRM at its largest sample count, and one more") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.2}}, {0, 0}, {1, 1});
  csl::PrmParams p;
  p.samples = csl::kMaxPrmSamples;
  p.neighbors = csl::NeighborRule::parse("radius:0.001");
  csl::Prm prm(world, csl::config({0.05, 0.05}), csl::config({0.95, 0.95}), p);
  // Draw every sample and index them all (about 10^6 vertices: well over 100 MB).
  while (prm.phase() != csl::PrmPhase::Connecting) prm.step();
  prm.step();  // the first vertex's neighbours, from the full index
  const double kept = static_cast<double>(prm.roadmap().vertices.size() - 2) / csl::kMaxPrmSamples;
  CHECK(kept == doctest::Approx(1.0 - csl::kPi * 0.04).epsilon(0.01));

  p.samples = csl::kMaxPrmSamples + 1;
  CHECK_THROWS_WITH_AS(csl::Prm(world, csl::config({0.05, 0.05}), csl::config({0.95, 0.95}), p),
                       "the number of samples must be in [0, 1000000]", std::invalid_argument);
}
