// PRM's local connectors: the potential-field connector joins a pair the straight line cannot,
// PRM with it finds paths whose every piece is free, edges carry their waypoints in order, and
// replays give the same roadmap. (The straight-line default keeps its pinned hashes: prm_test.)
#include <doctest/doctest.h>

#include <memory>

#include "core/planning/potential_connector.hpp"
#include "core/planning/prm.hpp"

using csl::config;
using csl::Config;

namespace {

const csl::EdgeCheckerSpec kBisection = csl::EdgeCheckerSpec::parse("bisection");

// p -> waypoints -> q: every straight piece free by the exact check, none longer than `max_piece`.
void require_free_pieces(const csl::CollisionWorld& world, const std::vector<Config>& points, double max_piece) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    REQUIRE(world.space().distance(points[i], points[i + 1]) <= max_piece);
    REQUIRE_FALSE(csl::check_edge(world, kBisection, points[i], points[i + 1]).collision);
  }
}

csl::PrmParams params(int n, std::uint64_t seed, std::shared_ptr<const csl::LocalConnector> connector) {
  csl::PrmParams p;
  p.samples = n;
  p.neighbors = csl::NeighborRule::parse("k:8");
  p.seed = seed;
  p.connector = std::move(connector);
  return p;
}

}  // namespace

TEST_CASE("the potential connector goes around a disk the straight line hits") {
  // The disk sits a little above the line, so the field slides the descent around below it.
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.52}, 0.1}}, {0, 0}, {1, 1});
  const Config p = config({0.2, 0.5}), q = config({0.8, 0.5});
  CHECK(csl::check_edge(world, kBisection, p, q).collision);

  const csl::PotentialConnector connector;
  const csl::LocalPath path = connector.connect(world, p, q, 1);
  REQUIRE(path.connected);
  CHECK(path.waypoints.size() > 60);
  std::vector<Config> all{p};
  all.insert(all.end(), path.waypoints.begin(), path.waypoints.end());
  all.push_back(q);
  require_free_pieces(world, all, 0.02 + 1e-12);  // steps of 0.01, the last piece up to the tolerance
  CHECK(path.length == doctest::Approx(csl::polyline_length(world.space(), p, path.waypoints, q)));
  CHECK(path.length > 0.6);  // a detour
  CHECK(path.evaluations > 0);

  // Into the cup's trap it fails (no escapes in PRM's connector): a rejected edge, no path.
  const csl::Polygon cup{{0.3, 0.4}, {0.4, 0.4}, {0.4, 0.6}, {0.6, 0.6}, {0.6, 0.4}, {0.7, 0.4}, {0.7, 0.7}, {0.3, 0.7}};
  const csl::CollisionWorld trap(csl::PointRobot{}, {csl::PolygonObstacle{cup}}, {0, 0}, {1, 1});
  const csl::LocalPath none = connector.connect(trap, config({0.5, 0.2}), config({0.5, 0.9}), 1);
  CHECK_FALSE(none.connected);
  CHECK(none.waypoints.empty());
}

TEST_CASE("PRM with the potential connector: verified paths through the waypoints") {
  const csl::CollisionWorld world(csl::PointRobot{},
                                  {csl::Disk{{0.3, 0.3}, 0.1}, csl::Disk{{0.7, 0.6}, 0.15},
                                   csl::PolygonObstacle{{{0.4, 0.7}, {0.5, 0.9}, {0.3, 0.85}}},
                                   csl::Wall{{0.6, 0.0}, {0.6, 0.3}}},
                                  {0, 0}, {1, 1});
  const auto connector = std::make_shared<const csl::PotentialConnector>();
  csl::Prm prm(world, config({0.05, 0.05}), config({0.95, 0.95}), params(150, 4, connector));
  prm.run();
  REQUIRE(prm.solved());
  CHECK(prm.last_event().kind == csl::PrmEvent::Kind::PathFound);
  // Every edge of the roadmap carries its descent's waypoints, stored from a to b.
  int with_waypoints = 0, detours = 0;
  for (const csl::RoadmapEdge& e : prm.roadmap().edges) {
    std::vector<Config> all{prm.roadmap().vertices[static_cast<std::size_t>(e.a)]};
    const std::vector<Config>& waypoints = prm.roadmap().waypoints(e);
    all.insert(all.end(), waypoints.begin(), waypoints.end());
    all.push_back(prm.roadmap().vertices[static_cast<std::size_t>(e.b)]);
    require_free_pieces(world, all, 0.02 + 1e-12);  // steps of 0.01, the last piece up to the tolerance
    CHECK(e.length == doctest::Approx(csl::polyline_length(world.space(), all.front(), waypoints, all.back())));
    with_waypoints += !waypoints.empty();
    detours += csl::check_edge(world, kBisection, all.front(), all.back()).collision;
  }
  CHECK(with_waypoints > 100);
  CHECK(detours > 0);  // pairs the straight line could not have joined
  // The whole path, waypoints included, from start to goal in free pieces of at most a step.
  const std::vector<Config> path = prm.path_configurations();
  CHECK(path.front() == config({0.05, 0.05}));
  CHECK(path.back() == config({0.95, 0.95}));
  CHECK(path.size() > prm.path().size());
  require_free_pieces(world, path, 0.02 + 1e-12);
  double length = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) length += world.space().distance(path[i], path[i + 1]);
  CHECK(prm.path_length() == doctest::Approx(length));
  CHECK(prm.path_edges().size() + 1 == prm.path().size());

  // Replays give the same roadmap (the connector's seeds come from the pair).
  const auto hash = csl::roadmap_hash(prm.roadmap());
  const long steps = prm.steps();
  prm.run_to(steps / 2);
  prm.run_to(steps);
  CHECK(csl::roadmap_hash(prm.roadmap()) == hash);
  MESSAGE("PRM + potential connector: " << prm.roadmap().vertices.size() << " vertices, " << prm.edges_alive()
                                        << " edges (" << detours << " around obstacles), path of " << path.size()
                                        << " configurations, hash " << hash);
  CHECK(hash == 7858272727114337825ull);  // the same in wasm
}

TEST_CASE("a custom connector plugs in; the straight line stays the default") {
  // Accepts every pair with one waypoint at the midpoint: PRM must store it and walk through it.
  struct Midpoint final : csl::LocalConnector {
    std::string name() const override { return "midpoint"; }
    csl::LocalPath connect(const csl::CollisionWorld& world, const Config& p, const Config& q,
                           std::uint64_t) const override {
      csl::LocalPath r;
      r.connected = true;
      r.waypoints.push_back(world.space().interpolate(p, q, 0.5));
      r.length = world.space().distance(p, q);
      return r;
    }
    double expected_evaluations() const override { return 1.0; }
  };
  const csl::CollisionWorld empty(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  csl::Prm prm(empty, config({0.1, 0.1}), config({0.9, 0.5}), params(0, 1, std::make_shared<const Midpoint>()));
  prm.run();
  REQUIRE(prm.solved());
  const auto path = prm.path_configurations();
  REQUIRE(path.size() == 3);
  CHECK(path[1][0] == doctest::Approx(0.5));
  CHECK(path[1][1] == doctest::Approx(0.3));
  // Hashes: the waypoints count only when there are some.
  csl::Roadmap r = prm.roadmap();
  const auto with = csl::roadmap_hash(r);
  r.edges[0].path = -1;
  CHECK(csl::roadmap_hash(r) != with);
  csl::Prm straight(empty, config({0.1, 0.1}), config({0.9, 0.5}), params(0, 1, nullptr));
  straight.run();
  CHECK(csl::roadmap_hash(straight.roadmap()) == csl::roadmap_hash(r));
  CHECK(straight.path_configurations().size() == 2);
  // A pair seed is a function of the seed and the pair only.
  CHECK(csl::pair_seed(1, 2, 3) == csl::pair_seed(1, 2, 3));
  CHECK(csl::pair_seed(1, 2, 3) != csl::pair_seed(1, 3, 2));
  CHECK(csl::pair_seed(1, 2, 3) != csl::pair_seed(2, 2, 3));
}
