// The lab's descriptions in words (what the page's parallel DOM reads out): numbers to 4
// significant digits, every obstacle named with its place, start and goal with their verdict,
// and a planner's path with the length it has.
#include <doctest/doctest.h>

#include <string>

#include "core/base/text.hpp"
#include "core/checking/scene_text.hpp"
#include "core/planning/planner_text.hpp"
#include "core/planning/prm.hpp"

using csl::config;

TEST_CASE("significant: 4 digits, no exponent at ordinary sizes, no -0") {
  CHECK(csl::significant(1.23456) == "1.235");
  CHECK(csl::significant(0.02) == "0.02");
  CHECK(csl::significant(1234.56) == "1235");
  CHECK(csl::significant(-0.0) == "0");
  CHECK(csl::significant(2.0 / 3.0, 2) == "0.67");
}

TEST_CASE("a scene in words: bounds, each obstacle, start and goal free or not") {
  csl::Scene s;
  s.workspace_max = csl::Vec2(2.0, 1.0);
  s.obstacles = {csl::Disk{{0.5, 0.5}, 0.125},
                 csl::PolygonObstacle{{{1.0, 0.0}, {1.5, 0.0}, {1.5, 0.5}, {1.0, 0.5}}},
                 csl::Wall{{0.25, 0.0}, {0.25, 0.75}}};
  s.start = config({0.5, 0.55});  // inside the disk
  s.goal = config({1.9, 0.9});
  const std::string text = csl::describe_scene(s, csl::CollisionWorld(s));
  CHECK(text.find("x from 0 to 2 and y from 0 to 1") != std::string::npos);
  CHECK(text.find("3 obstacles: disk 1 at (0.5, 0.5), radius 0.125; polygon 2 with 4 vertices around (1.25, 0.25); "
                  "wall 3 from (0.25, 0) to (0.25, 0.75).") != std::string::npos);
  CHECK(text.find("Start at (0.5, 0.55), in collision") != std::string::npos);
  CHECK(text.find("Goal at (1.9, 0.9), free.") != std::string::npos);
  CHECK(text.find("a point robot") != std::string::npos);
}

TEST_CASE("a planner in words: no path yet, then the path's edges and rounded length") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.2}}, {0, 0}, {1, 1});
  csl::PrmParams params;
  params.samples = 100;
  csl::Prm prm(world, config({0.1, 0.1}), config({0.9, 0.9}), params);
  CHECK(csl::describe_planner(prm).find("Step 0, phase") == 0);
  CHECK(csl::describe_planner(prm).find("No path yet.") != std::string::npos);
  prm.run();
  REQUIRE(prm.solved());
  const std::string text = csl::describe_planner(prm);
  CHECK(text.find("Path found: " + std::to_string(prm.path().size() - 1) + " edges, length " +
                  csl::significant(prm.path_length()) + ".") != std::string::npos);
  CHECK(text.find("The roadmap has " + std::to_string(prm.roadmap().vertices.size()) + " vertices") != std::string::npos);
}
