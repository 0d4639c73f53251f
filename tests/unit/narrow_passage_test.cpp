// The narrow-passage scene (core/scene/narrow_passage.hpp): its gap is exactly w wide where the
// lesson's slider says, its start and goal are free on either side, a closed wall (w = 0) leaves
// no path, and a width out of range is refused with the parameter's one error text.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "core/checking/collision.hpp"
#include "core/planning/planner_choice.hpp"
#include "core/scene/narrow_passage.hpp"

TEST_CASE("narrow passage: the gap is w wide, at the wall's middle, and nothing else is open") {
  for (double w : {0.01, 0.05, 0.2}) {
    CAPTURE(w);
    const csl::Scene s = csl::narrow_passage_scene(w);
    REQUIRE(s.obstacles.size() == 2);
    const csl::CollisionWorld world(s);
    CHECK(world.is_free(s.start));
    CHECK(world.is_free(s.goal));
    CHECK(s.start[0] < 0.4);
    CHECK(s.goal[0] > 0.6);
    // Inside the gap, at its middle and just within its edges, across the wall's thickness.
    for (double x : {0.41, 0.5, 0.59}) {
      CHECK(world.is_free(csl::config({x, 0.5})));
      CHECK(world.is_free(csl::config({x, 0.5 + 0.45 * w})));
      CHECK(world.is_free(csl::config({x, 0.5 - 0.45 * w})));
      // Just past its edges: the wall.
      CHECK_FALSE(world.is_free(csl::config({x, 0.5 + 0.55 * w})));
      CHECK_FALSE(world.is_free(csl::config({x, 0.5 - 0.55 * w})));
      CHECK_FALSE(world.is_free(csl::config({x, 0.02})));
      CHECK_FALSE(world.is_free(csl::config({x, 0.98})));
    }
    // Outside the wall's thickness, free from top to bottom.
    CHECK(world.is_free(csl::config({0.39, 0.9})));
    CHECK(world.is_free(csl::config({0.61, 0.1})));
  }
}

TEST_CASE("narrow passage: a planner gets through a wide gap, never through a closed wall") {
  csl::PlannerChoice c;
  c.kind = csl::PlannerChoice::Kind::RrtConnect;
  c.samples = 2000;
  c.seed = 3;
  {
    const csl::Scene s = csl::narrow_passage_scene(0.2);
    const csl::CollisionWorld world(s);
    auto planner = csl::make_planner_factory(c)(world, s.start, s.goal);
    planner->run();
    CHECK(planner->solved());
  }
  {
    const csl::Scene s = csl::narrow_passage_scene(0.0);
    const csl::CollisionWorld world(s);
    auto planner = csl::make_planner_factory(c)(world, s.start, s.goal);
    planner->run();
    CHECK_FALSE(planner->solved());
  }
}

TEST_CASE("narrow passage: a width out of range is refused with the parameter's text") {
  for (double w : {-0.01, 0.51, 1.0}) {
    CAPTURE(w);
    try {
      csl::narrow_passage_scene(w);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()) == csl::param_error(csl::kPassageWidth));
      CHECK(std::string(e.what()).rfind("passage: ", 0) == 0);
    }
  }
}
