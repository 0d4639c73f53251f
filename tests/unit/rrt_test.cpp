// RRT and RRT-Connect (core/planning/rrt.hpp, rrt_connect.hpp): paths proven free by the exact
// checker on random scenes in every space the lab has, trees that are trees, extensions of at
// most D the short way round S^1, replay to any step, and the same trees in every build (the
// pinned hashes run natively and in wasm).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/base/angles.hpp"
#include "core/checking/edge_check.hpp"
#include "core/planning/planner_choice.hpp"
#include "core/planning/rrt.hpp"
#include "core/planning/rrt_connect.hpp"
#include "core/teaching/work.hpp"

using csl::config;

namespace {

csl::TreeParams tree(int samples, std::uint64_t seed, double step = 0.0, double bias = 0.05,
                     const char* checker = "bisection") {
  csl::TreeParams p;
  p.samples = samples;
  p.seed = seed;
  p.step = step;
  p.goal_bias = bias;
  p.checker = csl::EdgeCheckerSpec::parse(checker);
  return p;
}

std::unique_ptr<csl::TreePlanner> make(bool connect, const csl::CollisionWorld& world, const csl::Config& start,
                                       const csl::Config& goal, const csl::TreeParams& p) {
  if (connect) return std::make_unique<csl::RrtConnect>(world, start, goal, p);
  return std::make_unique<csl::Rrt>(world, start, goal, p);
}

// A found path runs from vertex 0 to vertex 1 along live roadmap edges, each proven free by the
// exact check (bisection, run here afresh), and its length is the sum of the space's distances.
void require_valid_path(const csl::Planner& planner) {
  REQUIRE(planner.solved());
  const auto& r = planner.roadmap();
  const auto& path = planner.path();
  REQUIRE(path.front() == 0);
  REQUIRE(path.back() == 1);
  std::set<std::pair<int, int>> live;
  for (const auto& e : r.edges)
    if (e.alive) live.insert({e.a, e.b});
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const int a = path[i], b = path[i + 1];
    REQUIRE(live.count({std::min(a, b), std::max(a, b)}) == 1);
    const auto& qa = r.vertices[static_cast<std::size_t>(a)];
    const auto& qb = r.vertices[static_cast<std::size_t>(b)];
    const auto exact = csl::check_edge(planner.world(), csl::EdgeCheckerSpec::parse("bisection"), qa, qb);
    REQUIRE_FALSE(exact.collision);
    length += planner.world().space().distance(qa, qb);
  }
  CHECK(planner.path_length() == doctest::Approx(length).epsilon(1e-12));
}

// Every vertex but the roots hangs under one parent by an edge no longer than D; the live edges
// are the parent edges and at most one join.
void require_trees(const csl::TreePlanner& planner) {
  const auto& r = planner.roadmap();
  const double d = planner.step_size();
  int parents = 0;
  for (std::size_t v = 2; v < r.vertices.size(); ++v) {
    const int p = planner.parent_of(static_cast<int>(v));
    REQUIRE(p >= 0);
    REQUIRE(p < static_cast<int>(v));
    ++parents;
    REQUIRE(planner.world().space().distance(r.vertices[static_cast<std::size_t>(p)], r.vertices[v]) <= d * (1 + 1e-12));
  }
  CHECK(planner.parent_of(0) == -1);
  CHECK(planner.parent_of(1) == -1);
  const long joins = planner.join_edge() >= 0 ? 1 : 0;
  CHECK(static_cast<long>(r.edges.size()) == parents + joins);
}

// Random disks over [0,1]^2.
std::vector<csl::Obstacle> random_disks(csl::Rng& rng, int count, double r_hi) {
  std::vector<csl::Obstacle> out;
  for (int i = 0; i < count; ++i) {
    const double x = rng.uniform01(), y = rng.uniform01();
    out.push_back(csl::Disk{{x, y}, rng.uniform(0.02, r_hi)});
  }
  return out;
}

csl::Config free_config(const csl::CollisionWorld& world, csl::Rng& rng) {
  for (;;) {
    const csl::Config q = world.space().sample(rng);
    if (world.is_free(q)) return q;
  }
}

}  // namespace

TEST_CASE("RRT and RRT-Connect paths are free by the exact check on random scenes in every space") {
  csl::Rng rng(2024);
  struct Space {
    const char* name;
    csl::Robot robot;
    int disks;
    double r_hi;
    int samples;
  };
  const std::vector<Space> spaces = {
      {"point robot, R^2", csl::PointRobot{}, 12, 0.08, 3000},
      {"2-link arm, T^2", csl::ArmRobot{{0.5, 0.5}, 0.25, 0.2}, 4, 0.06, 3000},
      {"polygon robot, SE(2)",
       csl::make_polygon_robot({{-0.06, -0.025}, {0.06, -0.025}, {0.06, 0.025}, {-0.06, 0.025}}), 8, 0.07, 4000},
      {"4-link arm, T^4", csl::ArmRobot{{0.5, 0.5}, std::vector<double>{0.15, 0.12, 0.1, 0.08}}, 4, 0.05, 4000},
  };
  for (const Space& s : spaces) {
    int solved[2] = {0, 0};
    for (int scene = 0; scene < 4; ++scene) {
      const csl::CollisionWorld world(s.robot, random_disks(rng, s.disks, s.r_hi), {0, 0}, {1, 1});
      const csl::Config start = free_config(world, rng), goal = free_config(world, rng);
      for (int connect = 0; connect < 2; ++connect) {
        CAPTURE(s.name);
        CAPTURE(scene);
        CAPTURE(connect);
        auto planner = make(connect == 1, world, start, goal, tree(s.samples, 100 + static_cast<std::uint64_t>(scene)));
        planner->run();
        require_trees(*planner);
        if (!planner->solved()) continue;
        ++solved[connect];
        require_valid_path(*planner);
      }
    }
    CAPTURE(s.name);
    // The scenes are open enough that most runs find a path: a planner that never does fails here.
    CHECK(solved[0] >= 3);
    CHECK(solved[1] >= 3);
  }
}

TEST_CASE("RRT with goal bias 1 on an empty square walks straight to the goal in steps of D") {
  const csl::CollisionWorld world(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  csl::Rrt rrt(world, config({0.1, 0.1}), config({0.9, 0.7}), tree(100, 1, 0.1, 1.0));
  rrt.run();
  require_valid_path(rrt);
  // |goal - start| = 1: ten extensions of 0.1 (the last reaching q_final by the join).
  CHECK(rrt.path().size() == 11);
  CHECK(rrt.path_length() == doctest::Approx(1.0));
  CHECK(rrt.samples_drawn() == 10);
}

TEST_CASE("a D shorter than a thousandth of the extent is taken as that; the work prices connects") {
  const csl::CollisionWorld world(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  const double extent = csl::space_extent(world.space());
  CHECK(extent == doctest::Approx(std::sqrt(2.0)));
  CHECK(csl::tree_step(world.space(), 1e-9) == doctest::Approx(1e-3 * extent));
  CHECK(csl::tree_step(world.space(), 0.05) == 0.05);
  CHECK(csl::tree_step(world.space(), 0.0) == doctest::Approx(0.2 * extent));
  // RRT-Connect with the shortest D: one connect across the empty square adds at most ~1000
  // vertices, and the planner says D as used.
  csl::RrtConnect planner(world, config({0.0, 0.0}), config({1.0, 1.0}), tree(1, 1, 1e-9));
  planner.run();
  CHECK(planner.step_size() == doctest::Approx(1e-3 * extent));
  CHECK(planner.solved());
  CHECK(planner.roadmap().vertices.size() <= 1010);
  // What the CLI and the compare lesson price it at: 1 + extent / (2 D) edges per sample.
  csl::TreeParams params;
  params.step = 1e-9;
  CHECK(csl::tree_edges_per_sample(world.space(), params, true) == doctest::Approx(501.0));
  CHECK(csl::tree_edges_per_sample(world.space(), params, false) == 1.0);
  // The one price of a choice (work.hpp) that the CLI and the lesson hold against budgets: the
  // connects' 501 edges a sample for RRT-Connect, 1 for RRT, on the same per-edge cost.
  csl::PlannerChoice choice;
  choice.kind = csl::PlannerChoice::Kind::RrtConnect;
  choice.step = 1e-9;
  choice.samples = 1000;
  const csl::WorkEstimate connect = csl::expected_tree_work(world, choice);
  CHECK(connect.pairs == doctest::Approx(501.0 * 1002.0));
  choice.kind = csl::PlannerChoice::Kind::Rrt;
  const csl::WorkEstimate rrt = csl::expected_tree_work(world, choice);
  CHECK(rrt.pairs == doctest::Approx(1002.0));
  CHECK(rrt.per_edge == connect.per_edge);
  CHECK(connect.total() > 400.0 * rrt.connecting);
  choice.kind = csl::PlannerChoice::Kind::Prm;
  CHECK_THROWS_AS(csl::expected_tree_work(world, choice), std::invalid_argument);
}

TEST_CASE("RRT-Connect keeps two trees until they meet, and grows from both ends") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 0.45}}, csl::Wall{{0.5, 0.55}, {0.5, 1.0}}},
                                  {0, 0}, {1, 1});
  csl::RrtConnect planner(world, config({0.1, 0.5}), config({0.9, 0.5}), tree(2000, 3, 0.05));
  bool two_trees = false;
  while (!planner.done() && planner.join_edge() < 0) {
    planner.step();
    if (planner.roadmap().vertices.size() > 6) {
      const auto labels = planner.component_labels();
      two_trees |= labels[0] != labels[1] && planner.components() == 2;
    }
  }
  CHECK(two_trees);
  planner.run();
  require_valid_path(planner);
  require_trees(planner);
  int in_goal_tree = 0;
  for (std::size_t v = 2; v < planner.roadmap().vertices.size(); ++v) in_goal_tree += planner.tree_of(static_cast<int>(v)) == 1;
  CHECK(in_goal_tree > 0);
  CHECK(planner.components() == 1);
}

TEST_CASE("going back to step k gives the identical state (RRT and RRT-Connect)") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.3, 0.3}, 0.1}, csl::Disk{{0.7, 0.6}, 0.15}, csl::Wall{{0.6, 0.0}, {0.6, 0.3}}},
                                  {0, 0}, {1, 1});
  for (int connect = 0; connect < 2; ++connect) {
    CAPTURE(connect);
    auto planner = make(connect == 1, world, config({0.05, 0.05}), config({0.95, 0.95}), tree(400, 7, 0.05, 0.1, "step:0.02"));
    std::vector<std::uint64_t> hash_at;
    std::vector<int> kind_at, drawn_at;
    while (!planner->done()) {
      planner->step();
      hash_at.push_back(csl::roadmap_hash(planner->roadmap()));
      kind_at.push_back(static_cast<int>(planner->last_event().kind));
      drawn_at.push_back(planner->samples_drawn());
    }
    REQUIRE(hash_at.size() > 20);
    const long n = static_cast<long>(hash_at.size());
    for (long k : {1L, 2L, 3L, 17L, n / 2, n - 1, n, 5L}) {
      planner->run_to(k);
      REQUIRE(planner->steps() == k);
      REQUIRE(csl::roadmap_hash(planner->roadmap()) == hash_at[static_cast<std::size_t>(k - 1)]);
      REQUIRE(static_cast<int>(planner->last_event().kind) == kind_at[static_cast<std::size_t>(k - 1)]);
      REQUIRE(planner->samples_drawn() == drawn_at[static_cast<std::size_t>(k - 1)]);
    }
  }
}

TEST_CASE("finish_phase() leaves the state stepping leaves (RRT and RRT-Connect)") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.3, 0.3}, 0.1}, csl::Disk{{0.7, 0.6}, 0.15}}, {0, 0}, {1, 1});
  const csl::CollisionWorld wall(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 1.0}}}, {0, 0}, {1, 1});
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.8, 0.8}, 0.1}}, {0, 0}, {1, 1});
  struct Case {
    const csl::CollisionWorld* world;
    csl::Config start, goal;
    csl::TreeParams params;
  };
  const std::vector<Case> cases = {
      {&world, config({0.05, 0.05}), config({0.95, 0.95}), tree(500, 5, 0.05, 0.05, "bisection")},
      {&world, config({0.05, 0.05}), config({0.95, 0.95}), tree(500, 6, 0.1, 0.2, "grid:5")},
      {&world, config({0.05, 0.05}), config({0.95, 0.95}), tree(3, 6, 0.1, 0.2, "grid:5")},  // runs out
      {&wall, config({0.1, 0.5}), config({0.9, 0.5}), tree(300, 2, 0.3, 0.3, "grid:2")},  // edges removed
      {&arm, config({0.0, 0.0}), config({3.0, -1.0}), tree(800, 9, 0.0, 0.05, "step:0.05")},
      {&world, config({0.3, 0.3}), config({0.95, 0.95}), tree(30, 8)},  // start in a disk
  };
  for (const Case& c : cases)
    for (int connect = 0; connect < 2; ++connect) {
      auto stepped = make(connect == 1, *c.world, c.start, c.goal, c.params);
      auto bulk = make(connect == 1, *c.world, c.start, c.goal, c.params);
      while (!bulk->done()) {
        const csl::TreePhase phase = bulk->phase();
        bulk->finish_phase();
        while (!stepped->done() && stepped->phase() == phase) stepped->step();
        REQUIRE(bulk->steps() == stepped->steps());
        REQUIRE(bulk->phase() == stepped->phase());
        REQUIRE(csl::roadmap_hash(bulk->roadmap()) == csl::roadmap_hash(stepped->roadmap()));
        REQUIRE(bulk->samples_drawn() == stepped->samples_drawn());
        REQUIRE(bulk->edge_checks() == stepped->edge_checks());
        REQUIRE(bulk->evaluations() == stepped->evaluations());
        REQUIRE(bulk->edges_alive() == stepped->edges_alive());
        const csl::PlannerEvent &a = bulk->last_event(), &b = stepped->last_event();
        REQUIRE(a.kind == b.kind);
        REQUIRE(a.step == b.step);
        REQUIRE(a.vertex == b.vertex);
        REQUIRE(a.other == b.other);
        REQUIRE(a.sample == b.sample);
      }
      REQUIRE(stepped->done());
      REQUIRE(bulk->path() == stepped->path());
    }
}

TEST_CASE("a coarse grid lets tree edges through a wall; the exact re-check removes them") {
  const csl::CollisionWorld wall(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 1.0}}}, {0, 0}, {1, 1});
  for (int connect = 0; connect < 2; ++connect) {
    auto planner = make(connect == 1, wall, config({0.1, 0.5}), config({0.9, 0.5}), tree(300, 2, 0.3, 0.3, "grid:2"));
    int removed = 0;
    while (!planner->done()) removed += planner->step().kind == csl::PlannerEvent::Kind::PathEdgeRemoved;
    CHECK(removed > 0);
    CHECK_FALSE(planner->solved());  // the wall is closed
    // What hung below a removed edge is in no tree, and no live tree edge crosses the wall.
    for (const auto& e : planner->roadmap().edges)
      if (e.alive && planner->tree_of(e.a) >= 0 && planner->tree_of(e.b) >= 0)
        CHECK(planner->tree_of(e.a) == planner->tree_of(e.b));
  }
}

TEST_CASE("tree edges across the seam of S^1 go the short way round") {
  // The arm from 2.5 to -2.5: the short way is through pi (1.28 rad); the disk sits at angle 0.
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.85, 0.5}, 0.08}}, {0, 0}, {1, 1});
  for (int connect = 0; connect < 2; ++connect) {
    CAPTURE(connect);
    auto planner = make(connect == 1, arm, config({2.5, 0.0}), config({-2.5, 0.0}), tree(2000, 4, 0.3, 0.1));
    planner->run();
    require_valid_path(*planner);
    require_trees(*planner);  // every edge within D = 0.3 in the wrapped metric
    int across = 0;
    for (const auto& e : planner->roadmap().edges) {
      const auto& a = planner->roadmap().vertices[static_cast<std::size_t>(e.a)];
      const auto& b = planner->roadmap().vertices[static_cast<std::size_t>(e.b)];
      // Chart coordinates more than pi apart: the edge crosses the seam; its length is the short way.
      if (std::fabs(a[0] - b[0]) > csl::kPi || std::fabs(a[1] - b[1]) > csl::kPi) {
        ++across;
        CHECK(e.length <= 0.3 * (1 + 1e-12));
      }
      CHECK(a[0] >= -csl::kPi);
      CHECK(a[0] < csl::kPi);
    }
    CHECK(across > 0);
    CHECK(planner->path_length() < 2.5);
  }
}

TEST_CASE("the same inputs give the same trees in every build (pinned hashes)") {
  const csl::CollisionWorld world(csl::PointRobot{},
                                  {csl::Disk{{0.3, 0.3}, 0.1}, csl::Disk{{0.7, 0.6}, 0.15},
                                   csl::PolygonObstacle{{{0.4, 0.7}, {0.5, 0.9}, {0.3, 0.85}}}, csl::Wall{{0.6, 0.0}, {0.6, 0.3}}},
                                  {0, 0}, {1, 1});
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.8, 0.8}, 0.1}, csl::Disk{{0.2, 0.4}, 0.08}},
                                {0, 0}, {1, 1});
  csl::Rrt rrt(world, config({0.05, 0.05}), config({0.95, 0.95}), tree(1000, 42, 0.05));
  rrt.run();
  require_valid_path(rrt);
  CHECK(csl::roadmap_hash_text(rrt.roadmap()) == "1a118d941c7a9a82");
  csl::RrtConnect connect(world, config({0.05, 0.05}), config({0.95, 0.95}), tree(1000, 42, 0.05));
  connect.run();
  require_valid_path(connect);
  CHECK(csl::roadmap_hash_text(connect.roadmap()) == "2dab45b7b785da9a");
  // The arm on its torus (the lab's own sine and cosine), D by default.
  csl::Rrt rrt_arm(arm, config({0.0, 0.0}), config({3.0, -1.0}), tree(1000, 3));
  rrt_arm.run();
  require_valid_path(rrt_arm);
  CHECK(csl::roadmap_hash_text(rrt_arm.roadmap()) == "b4f539ac7897758c");
  csl::RrtConnect connect_arm(arm, config({0.0, 0.0}), config({3.0, -1.0}), tree(1000, 3));
  connect_arm.run();
  require_valid_path(connect_arm);
  CHECK(csl::roadmap_hash_text(connect_arm.roadmap()) == "1e0b775eeed437e7");
}

TEST_CASE("tree planners refuse a bad budget, bias or step") {
  const csl::CollisionWorld world(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  const auto s = config({0.1, 0.1}), g = config({0.9, 0.9});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH_AS(csl::Rrt(world, s, g, tree(-1, 1)), csl::param_error(csl::kPrmSamples).c_str(), std::invalid_argument);
  CHECK_THROWS_WITH_AS(csl::Rrt(world, s, g, tree(10, 1, 0.1, 1.5)), csl::param_error(csl::kGoalBias).c_str(),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(csl::Rrt(world, s, g, tree(10, 1, 0.1, nan)), csl::param_error(csl::kGoalBias).c_str(),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(csl::RrtConnect(world, s, g, tree(10, 1, -0.1)), csl::param_error(csl::kTreeStep).c_str(),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(csl::RrtConnect(world, s, g, tree(10, 1, nan)), csl::param_error(csl::kTreeStep).c_str(),
                       std::invalid_argument);
  CHECK_THROWS_AS(csl::Rrt(world, s, config({0.5}), tree(10, 1)), std::invalid_argument);
  // The choice says the same before any planner is made.
  csl::PlannerChoice c;
  c.kind = csl::PlannerChoice::Kind::Rrt;
  c.goal_bias = -0.01;
  CHECK_THROWS_WITH_AS(csl::validate(c), csl::param_error(csl::kGoalBias).c_str(), std::invalid_argument);
  c.goal_bias = 0.5;
  c.step = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH_AS(csl::validate(c), csl::param_error(csl::kTreeStep).c_str(), std::invalid_argument);
}

TEST_CASE("the choice makes RRT and RRT-Connect with its options; describe() has a line per event") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.2}}, {0, 0}, {1, 1});
  csl::Scene scene;
  scene.obstacles = {csl::Disk{{0.5, 0.5}, 0.2}};
  for (const char* name : {"rrt", "rrt-connect"}) {
    CAPTURE(name);
    csl::PlannerChoice c;
    c.kind = csl::parse_planner_kind(name);
    c.samples = 500;
    c.step = 0.07;
    c.goal_bias = 0.2;
    c.seed = 11;
    auto planner = csl::make_planner_factory(c)(world, config({0.1, 0.1}), config({0.9, 0.9}));
    CHECK(std::string(planner->name()) == name);
    const auto& t = dynamic_cast<const csl::TreePlanner&>(*planner);
    CHECK(t.step_size() == 0.07);
    CHECK(t.params().seed == 11);
    std::set<int> kinds;
    while (!planner->done()) {
      const auto& e = planner->step();
      const std::string line = planner->describe(e, scene);
      REQUIRE(line.size() > 10);
      REQUIRE(line.find('\n') == std::string::npos);
      kinds.insert(static_cast<int>(e.kind));
    }
    CHECK(kinds.count(static_cast<int>(csl::PlannerEvent::Kind::SampleAccepted)) == 1);
    CHECK(kinds.count(static_cast<int>(csl::PlannerEvent::Kind::EdgeAdded)) == 1);
    CHECK(kinds.count(static_cast<int>(csl::PlannerEvent::Kind::PathFound)) == 1);
  }
}
