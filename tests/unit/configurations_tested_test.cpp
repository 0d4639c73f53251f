// "Collision checks" as one measure for every planner: Planner::configurations_tested(), the
// configurations each planner gave the collision checker (CollisionWorld::configurations_tested()
// counts them; the planners take differences around their steps). Checked here against counts
// made independently of the planners: the world's counter read by the test around a whole run,
// a count by hand on an empty square (where every test's outcome is known), and the same run
// stepped, run by phases, replayed, and interleaved with another planner on a shared world.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/base/rng.hpp"
#include "core/planning/planner_choice.hpp"

using csl::config;

namespace {

struct Case {
  const char* name;
  csl::PlannerChoice choice;
};

csl::PlannerChoice choice(const char* planner, const char* sampler = "uniform", int samples = 120) {
  csl::PlannerChoice c;
  c.kind = csl::parse_planner_kind(planner);
  c.samples = samples;
  c.seed = 11;
  c.sampler = csl::SamplerSpec::parse(sampler);
  return c;
}

// Every planner, and PRM and Lazy PRM with each sampler (a bridge or Gaussian draw tests up to
// three configurations, which the samples count leaves out).
std::vector<Case> cases() {
  std::vector<Case> out;
  for (const char* p : {"prm", "prm-star", "lazy-prm", "rrt", "rrt-connect"}) out.push_back({p, choice(p)});
  for (const char* s : {"gaussian:0.05", "bridge:0.1", "halton"}) {
    out.push_back({"prm", choice("prm", s)});
    out.push_back({"lazy-prm", choice("lazy-prm", s)});
  }
  csl::PlannerChoice grid = choice("rrt");
  grid.checker = csl::EdgeCheckerSpec::parse("grid:6");  // the ends' clearances, then grid points
  out.push_back({"rrt, grid:6", grid});
  return out;
}

struct World {
  const char* name;
  csl::CollisionWorld world;
  csl::Config start, goal;
};

std::vector<World> worlds() {
  std::vector<World> out;
  out.push_back({"point, R^2",
                 csl::CollisionWorld(csl::PointRobot{},
                                     {csl::Disk{{0.5, 0.5}, 0.2}, csl::Wall{{0.2, 0.0}, {0.2, 0.35}}},
                                     {0, 0}, {1, 1}),
                 config({0.1, 0.1}), config({0.9, 0.9})});
  out.push_back({"2-link arm, T^2",
                 csl::CollisionWorld(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.85, 0.5}, 0.08}}, {0, 0}, {1, 1}),
                 config({0.0, 0.3}), config({3.0, -0.5})});
  out.push_back({"4-link arm, T^4",
                 csl::CollisionWorld(csl::ArmRobot{{0.5, 0.5}, std::vector<double>{0.15, 0.12, 0.1, 0.08}},
                                     {csl::Disk{{0.85, 0.5}, 0.08}, csl::Disk{{0.2, 0.3}, 0.06}}, {0, 0}, {1, 1}),
                 config({0.0, 0.3, 0.2, 0.1}), config({2.5, -0.5, 0.4, -1.0})});
  return out;
}

std::unique_ptr<csl::Planner> make(const csl::PlannerChoice& c, const World& w) {
  return csl::make_planner_factory(c)(w.world, w.start, w.goal);
}

}  // namespace

TEST_CASE("configurations_tested is every test the planner gave the world, however it is stepped") {
  for (const World& w : worlds())
    for (const Case& c : cases()) {
      CAPTURE(w.name);
      CAPTURE(c.name);
      CAPTURE(c.choice.sampler.name());
      // Run to the end by phases: the planner's count is the world's counter, read by the test
      // before the planner was made and after it finished (nothing else tests in between).
      const std::uint64_t before = w.world.configurations_tested();
      auto run = make(c.choice, w);
      run->run();
      const long long tested = run->configurations_tested();
      CHECK(tested == static_cast<long long>(w.world.configurations_tested() - before));
      CHECK(tested > 0);
      // What the planner calls evaluations never exceeds it (PRM's leaves its samples out).
      CHECK(run->evaluations() <= tested);
      // Step by step (the events' words are built, obstacles named: not tests), the same count.
      auto stepped = make(c.choice, w);
      while (!stepped->done()) stepped->step();
      CHECK(stepped->configurations_tested() == tested);
      // Back to a step in the middle and forward again: a replay counts from nothing.
      const long half = stepped->steps() / 2;
      stepped->run_to(half);
      auto fresh = make(c.choice, w);
      fresh->run_to(half);
      CHECK(stepped->configurations_tested() == fresh->configurations_tested());
      stepped->run();
      CHECK(stepped->configurations_tested() == tested);
      stepped->reset();
      CHECK(stepped->configurations_tested() == 0);
    }
}

TEST_CASE("two planners on one world each count their own tests") {
  // The compare lesson's case: two planners step in turn on the same world.
  const World w = worlds()[0];
  auto a_alone = make(choice("prm", "bridge:0.1"), w);
  a_alone->run();
  auto b_alone = make(choice("rrt-connect"), w);
  b_alone->run();
  const std::uint64_t before = w.world.configurations_tested();
  auto a = make(choice("prm", "bridge:0.1"), w);
  auto b = make(choice("rrt-connect"), w);
  while (!a->done() || !b->done()) {
    if (!a->done()) a->step();
    if (!b->done()) b->step();
  }
  CHECK(a->configurations_tested() == a_alone->configurations_tested());
  CHECK(b->configurations_tested() == b_alone->configurations_tested());
  CHECK(a->configurations_tested() + b->configurations_tested() ==
        static_cast<long long>(w.world.configurations_tested() - before));
}

TEST_CASE("on an empty square the count is what a hand count gives") {
  // With no obstacles every configuration is free and every clearance infinite, so each test's
  // outcome is known and the motion bound proves every edge free without a point between.
  const csl::CollisionWorld empty(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  // 0.75 apart, a multiple of the RRT's step below: every coordinate on the way is exact.
  const csl::Config start = config({0.125, 0.5}), goal = config({0.875, 0.5});
  SUBCASE("PRM, uniform, bisection") {
    // The two endpoints' tests; per sample is_free() and then its clearance (bisection keeps
    // every vertex's); no edge needs a point tested; the path's exact re-check asks the two
    // ends' clearances of each path edge afresh.
    const int n = 30;
    csl::PlannerChoice c = choice("prm", "uniform", n);
    auto prm = csl::make_planner_factory(c)(empty, start, goal);
    prm->run();
    REQUIRE(prm->solved());
    const long path_edges = static_cast<long>(prm->path().size()) - 1;
    CHECK(prm->configurations_tested() == 2 + 2L * n + 2 * path_edges);
    // PRM's own evaluations count the points its checks tested between an edge's ends: none
    // here, where all of the above were tested.
    CHECK(prm->evaluations() == 0);
  }
  SUBCASE("RRT with goal bias 1 walks straight to the goal") {
    // The two endpoints' tests; each extension but the last tests its new end once (its
    // clearance, which the vertex keeps); the last reaches the goal vertex, whose clearance its
    // endpoint test gave, so it tests nothing. The path's re-check asks the clearances of
    // vertices 0 and 1 afresh (an endpoint's is nearest()'s, maybe other bits) and has the rest.
    csl::PlannerChoice c = choice("rrt", "uniform", 50);
    c.goal_bias = 1.0;
    c.step = 0.125;  // D: 6 extensions over the 0.75 between start and goal
    auto rrt = csl::make_planner_factory(c)(empty, start, goal);
    rrt->run();
    REQUIRE(rrt->solved());
    const long extensions = 6;
    REQUIRE(static_cast<long>(rrt->path().size()) - 1 == extensions);
    CHECK(rrt->configurations_tested() == 2 + (extensions - 1) + 2);
    CHECK(rrt->evaluations() == extensions - 1);  // RRT's own: each new end
  }
}
