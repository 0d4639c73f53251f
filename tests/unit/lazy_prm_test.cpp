// Lazy PRM (core/planning/lazy_prm.hpp): paths proven free by the exact check on random scenes in
// every space, the same answer as PRM from the same samples with far fewer checks, replay to any
// step, what it reports as never checked, the same roadmap in every build (pinned hash), and its
// searches (ShortestPaths: edges removed between searches, the answers of a fresh search).
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <vector>

#include "core/checking/edge_check.hpp"
#include "core/planning/lazy_prm.hpp"
#include "core/planning/planner_json.hpp"
#include "core/planning/potential_connector.hpp"
#include "core/planning/prm.hpp"

using csl::config;
using csl::LazyPrm;
using csl::PlannerEvent;

namespace {

csl::PrmParams params(int n, std::uint64_t seed, const char* rule = "k:10", const char* sampler = "uniform") {
  csl::PrmParams p;
  p.samples = n;
  p.neighbors = csl::NeighborRule::parse(rule);
  p.sampler = csl::SamplerSpec::parse(sampler);
  p.seed = seed;
  return p;
}

// A random scene of `disks` disks in the unit square for `robot`, and a free start and goal
// (drawn uniformly until free); false if none was found.
struct RandomScene {
  std::vector<csl::Obstacle> obstacles;
  csl::Config start, goal;
};
RandomScene random_scene(const csl::Robot& robot, std::uint64_t seed, int disks, double radius) {
  csl::Rng rng(seed * 7919 + 13);
  RandomScene s;
  for (int i = 0; i < disks; ++i)
    s.obstacles.push_back(csl::Disk{{rng.uniform(0.1, 0.9), rng.uniform(0.1, 0.9)}, rng.uniform(0.5, 1.0) * radius});
  const csl::CollisionWorld world(robot, s.obstacles, {0, 0}, {1, 1});
  for (csl::Config* q : {&s.start, &s.goal}) {
    do *q = world.space().sample(rng);
    while (!world.is_free(*q));
  }
  return s;
}

// Every edge of the path exists, is alive, was checked, and is free by the exact check run anew.
void require_proven_path(const LazyPrm& lazy) {
  REQUIRE(lazy.solved());
  const auto& r = lazy.roadmap();
  const auto& path = lazy.path();
  REQUIRE(path.front() == 0);
  REQUIRE(path.back() == 1);
  const csl::EdgeCheckerSpec exact = csl::EdgeCheckerSpec::parse("bisection");
  double length = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const int a = std::min(path[i], path[i + 1]), b = std::max(path[i], path[i + 1]);
    bool found = false;
    for (std::size_t e = 0; e < r.edges.size(); ++e)
      if (r.edges[e].a == a && r.edges[e].b == b && r.edges[e].alive) {
        found = true;
        CHECK(lazy.edge_checked()[e] == 1);
      }
    REQUIRE(found);
    const auto& p = r.vertices[static_cast<std::size_t>(path[i])];
    const auto& q = r.vertices[static_cast<std::size_t>(path[i + 1])];
    REQUIRE_FALSE(csl::check_edge(lazy.world(), exact, p, q).collision);
    length += lazy.world().space().distance(p, q);
  }
  CHECK(lazy.path_length() == doctest::Approx(length));
}

}  // namespace

TEST_CASE("Lazy PRM's paths are proven free by the exact check, and PRM from the same samples agrees") {
  struct Case {
    const char* name;
    csl::Robot robot;
    int disks;
    double radius;
    int samples;
  };
  const Case cases[] = {
      {"point robot, R^2", csl::PointRobot{}, 8, 0.12, 300},
      {"2-link arm, T^2", csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, 4, 0.08, 300},
      {"polygon, SE(2)", csl::make_polygon_robot({{-0.05, -0.03}, {0.06, -0.03}, {0.0, 0.05}}), 6, 0.1, 400},
      {"4-link arm, T^4", csl::ArmRobot{{0.5, 0.5}, {0.15, 0.12, 0.1, 0.08}}, 4, 0.07, 500},
  };
  for (const Case& c : cases) {
    int solved = 0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      CAPTURE(c.name);
      CAPTURE(seed);
      const RandomScene s = random_scene(c.robot, seed, c.disks, c.radius);
      const csl::CollisionWorld world(c.robot, s.obstacles, {0, 0}, {1, 1});
      LazyPrm lazy(world, s.start, s.goal, params(c.samples, seed));
      lazy.run();
      csl::Prm prm(world, s.start, s.goal, params(c.samples, seed));
      prm.run();
      // The same samples (the uniform sampler takes the rng as PRM does) and the same close pairs:
      // PRM's free edges are among Lazy PRM's survivors, and its path is free, so both find a path
      // or neither, and both the shortest in the free graph.
      REQUIRE(lazy.roadmap().vertices.size() == prm.roadmap().vertices.size());
      CHECK(lazy.roadmap().edges.size() >= static_cast<std::size_t>(prm.edge_checks()));
      REQUIRE(lazy.solved() == prm.solved());
      if (!lazy.solved()) continue;
      ++solved;
      require_proven_path(lazy);
      CHECK(lazy.path_length() == doctest::Approx(prm.path_length()).epsilon(1e-12));
      // What laziness saves: far fewer edges checked than PRM checks.
      CHECK(lazy.edge_checks() * 5 < prm.edge_checks());
      CHECK(lazy.edges_unchecked() > 0);
    }
    CAPTURE(c.name);
    CHECK(solved >= 2);  // the test means something in every space
  }
}

TEST_CASE("Lazy PRM's steps: unchecked edges, a search, checks of its edges, removals, a proven path") {
  // A wall with a gap: most straight edges across the wall collide, found only when a path uses them.
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 0.4}}, csl::Wall{{0.5, 0.6}, {0.5, 1.0}}},
                                  {0, 0}, {1, 1});
  LazyPrm lazy(world, config({0.1, 0.9}), config({0.9, 0.9}), params(300, 2));
  int added = 0, candidates = 0, checked = 0, removed = 0, found = 0;
  const csl::EdgeCheckerSpec exact = csl::EdgeCheckerSpec::parse("bisection");
  while (!lazy.done()) {
    const PlannerEvent& e = lazy.step();
    const auto& v = lazy.roadmap().vertices;
    switch (e.kind) {
      case PlannerEvent::Kind::EdgeAdded:
        ++added;
        CHECK(e.evaluations == 0);
        CHECK(std::string(lazy.phase_label()) != "checking");
        break;
      case PlannerEvent::Kind::PathCandidate:
        ++candidates;
        CHECK(e.candidates > 0);
        break;
      case PlannerEvent::Kind::EdgeChecked:
        ++checked;
        CHECK_FALSE(csl::check_edge(world, exact, v[static_cast<std::size_t>(e.vertex)], v[static_cast<std::size_t>(e.other)]).collision);
        break;
      case PlannerEvent::Kind::PathEdgeRemoved:
        ++removed;
        CHECK(csl::check_edge(world, exact, v[static_cast<std::size_t>(e.vertex)], v[static_cast<std::size_t>(e.other)]).collision);
        break;
      case PlannerEvent::Kind::PathFound:
        ++found;
        break;
      default:
        break;
    }
    CHECK_FALSE(lazy.describe(e, csl::Scene{}).empty());
  }
  CHECK(added == static_cast<int>(lazy.roadmap().edges.size()));
  CHECK(removed > 0);
  CHECK(candidates == removed + 1);  // each removal sends it back to search; the last search's path holds
  CHECK(checked + removed == lazy.edge_checks());
  CHECK(found == 1);
  require_proven_path(lazy);
  CHECK(lazy.edges_alive() == static_cast<long>(lazy.roadmap().edges.size()) - removed);
  CHECK(lazy.edges_unchecked() == lazy.edges_alive() - checked);

  // The JSON: the count and a flag per live edge, true exactly for the checked ones.
  const nlohmann::json j = csl::planner_state_json(lazy, true);
  CHECK(j["edges_unchecked"] == lazy.edges_unchecked());
  REQUIRE(j["edge_checked"].size() == j["edge_list"].size());
  int flagged = 0;
  for (const auto& f : j["edge_checked"]) flagged += f.get<bool>();
  CHECK(flagged == checked);
  // PRM's JSON is as it was.
  csl::Prm prm(world, config({0.1, 0.9}), config({0.9, 0.9}), params(50, 2));
  prm.run();
  CHECK_FALSE(csl::planner_state_json(prm, true).contains("edge_checked"));
  CHECK_FALSE(csl::planner_state_json(prm, false).contains("edges_unchecked"));
  // The interface says it, not the type: what a wrapper (the app's RecordingPlanner) passes on.
  const csl::Planner& as_planner = lazy;
  CHECK(as_planner.checked_edge_flags() == &lazy.edge_checked());
  CHECK(as_planner.edges_unchecked() == lazy.edges_unchecked());
  CHECK(static_cast<const csl::Planner&>(prm).checked_edge_flags() == nullptr);
}

TEST_CASE("Lazy PRM: going back to step k gives the identical state; finish_phase() as stepping") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 0.45}}, csl::Wall{{0.5, 0.55}, {0.5, 1.0}},
                                                      csl::Disk{{0.25, 0.7}, 0.1}},
                                  {0, 0}, {1, 1});
  for (const char* sampler : {"uniform", "gaussian:0.05"}) {
    CAPTURE(sampler);
    LazyPrm lazy(world, config({0.1, 0.5}), config({0.9, 0.2}), params(120, 4, "k:8", sampler));
    std::vector<std::uint64_t> hash_at;
    std::vector<PlannerEvent::Kind> kind_at;
    std::vector<long> checks_at;
    while (!lazy.done()) {
      kind_at.push_back(lazy.step().kind);
      hash_at.push_back(csl::roadmap_hash(lazy.roadmap()));
      checks_at.push_back(lazy.edge_checks());
    }
    const long total = lazy.steps();
    for (long k : {1L, 2L, 50L, 130L, total / 2, total - 3, total - 1, total}) {
      CAPTURE(k);
      lazy.run_to(k);
      REQUIRE(lazy.steps() == k);
      CHECK(csl::roadmap_hash(lazy.roadmap()) == hash_at[static_cast<std::size_t>(k - 1)]);
      CHECK(lazy.last_event().kind == kind_at[static_cast<std::size_t>(k - 1)]);
      CHECK(lazy.edge_checks() == checks_at[static_cast<std::size_t>(k - 1)]);
    }
    LazyPrm bulk(world, config({0.1, 0.5}), config({0.9, 0.2}), params(120, 4, "k:8", sampler));
    while (!bulk.done()) {
      bulk.finish_phase();
      const long k = bulk.steps();
      CHECK(csl::roadmap_hash(bulk.roadmap()) == hash_at[static_cast<std::size_t>(k - 1)]);
      CHECK(bulk.last_event().kind == kind_at[static_cast<std::size_t>(k - 1)]);
    }
    CHECK(bulk.steps() == total);
  }
}

TEST_CASE("Lazy PRM refuses what it cannot honour, and reports no path through a closed wall") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 1.0}}}, {0, 0}, {1, 1});
  csl::PrmParams with_connector = params(50, 1);
  with_connector.connector = std::make_shared<const csl::PotentialConnector>();
  CHECK_THROWS_AS(LazyPrm(world, config({0.1, 0.5}), config({0.9, 0.5}), with_connector), std::invalid_argument);
  LazyPrm lazy(world, config({0.1, 0.5}), config({0.9, 0.5}), params(100, 1));
  lazy.run();
  CHECK_FALSE(lazy.solved());
  CHECK(lazy.last_event().kind == PlannerEvent::Kind::NoPath);
  // Every edge across the wall that a search proposed was checked and removed.
  for (const auto& e : lazy.roadmap().edges) {
    const bool across = (lazy.roadmap().vertices[static_cast<std::size_t>(e.a)][0] < 0.5) !=
                        (lazy.roadmap().vertices[static_cast<std::size_t>(e.b)][0] < 0.5);
    if (across) CHECK_FALSE(e.alive);
  }
  // Through the factory, as the app and experiments make planners.
  auto made = csl::lazy_prm_factory(params(100, 1))(world, config({0.1, 0.5}), config({0.9, 0.5}));
  made->run();
  CHECK(std::string(made->name()) == "lazy-prm");
  CHECK(csl::roadmap_hash(made->roadmap()) == csl::roadmap_hash(lazy.roadmap()));
}

TEST_CASE("Lazy PRM gives the same roadmap in every build (pinned hash)") {
  const csl::CollisionWorld world(csl::PointRobot{},
                                  {csl::Disk{{0.3, 0.3}, 0.1}, csl::Disk{{0.7, 0.6}, 0.15},
                                   csl::PolygonObstacle{{{0.4, 0.7}, {0.5, 0.9}, {0.3, 0.85}}}, csl::Wall{{0.6, 0.0}, {0.6, 0.3}}},
                                  {0, 0}, {1, 1});
  LazyPrm lazy(world, config({0.05, 0.05}), config({0.95, 0.95}), params(500, 42));
  lazy.run();
  require_proven_path(lazy);
  CHECK(lazy.edge_checks() == 22);  // of 2500-odd edges
  CHECK(csl::roadmap_hash(lazy.roadmap()) == 6808534347597131235ull);
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.8, 0.8}, 0.1}, csl::Disk{{0.2, 0.4}, 0.08}},
                                {0, 0}, {1, 1});
  LazyPrm on_torus(arm, config({0.0, 0.0}), config({3.0, -1.0}), params(400, 3, "k:8", "halton"));
  on_torus.run();
  require_proven_path(on_torus);
  CHECK(csl::roadmap_hash(on_torus.roadmap()) == 511576638298890320ull);
}

// The A* that shortest_path() was before ShortestPaths, written again here as the reference
// (shortest_path() is built on ShortestPaths now, so comparing the two alone would be circular):
// each vertex's edges in index order, a std::priority_queue of (f, vertex) with a copy per
// improvement, closed vertices skipped when popped.
static std::vector<int> reference_path(int n, const std::vector<csl::GraphEdge>& edges, const std::vector<char>& alive,
                                int source, int target, const std::vector<double>& h, std::vector<int>& via) {
  std::vector<std::vector<std::pair<int, int>>> adjacent(static_cast<std::size_t>(n));  // (other end, edge)
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (alive[i]) {
      adjacent[static_cast<std::size_t>(edges[i].a)].push_back({edges[i].b, static_cast<int>(i)});
      adjacent[static_cast<std::size_t>(edges[i].b)].push_back({edges[i].a, static_cast<int>(i)});
    }
  const auto un = static_cast<std::size_t>(n);
  std::vector<double> dist(un, std::numeric_limits<double>::infinity());
  std::vector<int> previous(un, -1), previous_edge(un, -1);
  std::vector<char> closed(un, 0);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[static_cast<std::size_t>(source)] = 0.0;
  open.push({h[static_cast<std::size_t>(source)], source});
  while (!open.empty()) {
    const int v = open.top().second;
    open.pop();
    const auto uv = static_cast<std::size_t>(v);
    if (closed[uv]) continue;
    closed[uv] = 1;
    if (v == target) break;
    for (const auto& [w, e] : adjacent[uv]) {
      const auto uw = static_cast<std::size_t>(w);
      const double d = dist[uv] + edges[static_cast<std::size_t>(e)].length;
      if (d < dist[uw]) {
        dist[uw] = d;
        previous[uw] = v;
        previous_edge[uw] = e;
        open.push({d + h[uw], w});
      }
    }
  }
  std::vector<int> path;
  via.clear();
  if (!closed[static_cast<std::size_t>(target)]) return path;
  for (int v = target; v != -1; v = previous[static_cast<std::size_t>(v)]) {
    path.push_back(v);
    if (v != source) via.push_back(previous_edge[static_cast<std::size_t>(v)]);
  }
  std::reverse(path.begin(), path.end());
  std::reverse(via.begin(), via.end());
  return path;
}

TEST_CASE("ShortestPaths: edges removed between searches give what a fresh shortest_path() gives") {
  // Ties by vertex index: two paths of length 2 from 0 to 1, through 3 (listed first) and 2.
  const std::vector<csl::GraphEdge> square = {{0, 3, 1.0}, {3, 1, 1.0}, {0, 2, 1.0}, {2, 1, 1.0}};
  csl::ShortestPaths paths;
  paths.build(4, square, [](int) { return true; });
  std::vector<int> path, via;
  paths.search(0, 1, [](int) { return 0.0; }, path, &via);
  CHECK(path == std::vector<int>{0, 2, 1});
  CHECK(via == std::vector<int>{2, 3});
  paths.remove(3);
  paths.search(0, 1, [](int) { return 0.0; }, path, &via);
  CHECK(path == std::vector<int>{0, 3, 1});
  paths.remove(0);
  paths.search(0, 1, [](int) { return 0.0; }, path, &via);
  CHECK(path.empty());
  CHECK(via.empty());

  // Random multigraphs with many equal lengths, searched again after each removal.
  csl::Rng rng(24);
  const auto pick = [&](std::size_t k) { return static_cast<int>(rng.below(static_cast<std::uint64_t>(k))); };
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 2 + pick(40);
    std::vector<csl::GraphEdge> edges(static_cast<std::size_t>(pick(static_cast<std::size_t>(4 * n))));
    for (csl::GraphEdge& e : edges) {
      e.a = pick(static_cast<std::size_t>(n));
      e.b = pick(static_cast<std::size_t>(n));
      e.length = pick(4);
    }
    std::vector<double> h(static_cast<std::size_t>(n));
    for (double& x : h) x = pick(2);
    std::vector<char> alive(edges.size(), 1);
    const auto usable = [&](int i) { return alive[static_cast<std::size_t>(i)] != 0; };
    const auto heuristic = [&](int v) { return h[static_cast<std::size_t>(v)]; };
    paths.build(n, edges, usable);
    for (int round = 0; round < 6; ++round) {
      const int s = pick(static_cast<std::size_t>(n)), t = pick(static_cast<std::size_t>(n));
      std::vector<int> fresh_via;
      const std::vector<int> fresh = csl::shortest_path(n, edges, usable, s, t, heuristic, &fresh_via);
      paths.search(s, t, heuristic, path, &via);
      REQUIRE(path == fresh);
      REQUIRE(via == fresh_via);
      std::vector<int> reference_via;
      REQUIRE(path == reference_path(n, edges, alive, s, t, h, reference_via));
      REQUIRE(via == reference_via);
      if (!via.empty()) {
        const int e = via[static_cast<std::size_t>(pick(via.size()))];
        alive[static_cast<std::size_t>(e)] = 0;
        paths.remove(e);
      }
    }
  }
}
