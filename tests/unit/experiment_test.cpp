// Experiments: PRM's measured failure rate falls with n, stays under the bound of section 2.1,
// and the runner is reproducible and reports its progress step by step.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "core/base/angles.hpp"
#include "core/teaching/experiment.hpp"

using csl::config;

namespace {
// The least clearance along a path of straight edges, sampled at most `spacing` apart: the
// truth the proven clearances are checked against (a sample can only be too large).
double path_clearance(const csl::CollisionWorld& world, const std::vector<csl::Config>& path, double spacing) {
  double least = world.clearance(path.front());
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const csl::Config delta = world.space().difference(path[i], path[i + 1]);
    const double length = world.space().distance(path[i], path[i + 1]);
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / spacing)));
    for (int k = 1; k <= pieces; ++k)
      least = std::fmin(least, world.clearance(world.space().along(path[i], delta, double(k) / pieces)));
  }
  return least;
}

csl::CollisionWorld narrow_gap() {
  return csl::CollisionWorld(csl::PointRobot{},
                             {csl::Wall{{0.5, 0.0}, {0.5, 0.48}}, csl::Wall{{0.5, 0.52}, {0.5, 1.0}}}, {0, 0}, {1, 1});
}
csl::ExperimentParams params(std::vector<int> ns, int trials) {
  csl::ExperimentParams p;
  p.sample_counts = std::move(ns);
  p.trials = trials;
  p.seed = 11;
  p.neighbors = csl::NeighborRule::parse("k:5");
  p.volume_samples = 20000;
  return p;
}
}  // namespace

TEST_CASE("the failure rate falls with n and respects the bound") {
  const auto world = narrow_gap();
  csl::Experiment ex(world, config({0.15, 0.85}), config({0.85, 0.75}), params({15, 150, 1500}, 40));
  CHECK(ex.progress() == 0.0);
  ex.step();  // the reference run
  const auto& ref = ex.reference();
  REQUIRE(ref.path_exists);
  CHECK(ref.dimension == 2);
  CHECK(ref.free_fraction == doctest::Approx(1.0).epsilon(0.01));  // walls have no area
  CHECK(ref.path_length >= 0.6);
  // The path must squeeze through the 0.04 gap: its clearance is at most 0.02; the widest
  // path of the reference roadmap passes near the gap's middle, not by a wall's end (r is
  // proven, a little below what the path has).
  CHECK(ref.clearance > 0.01);
  CHECK(ref.clearance <= 0.02);
  ex.run();
  CHECK(ex.progress() == 1.0);
  const auto& rows = ex.rows();
  REQUIRE(rows.size() == 3);
  for (const auto& row : rows) {
    CHECK(row.trials == 40);
    REQUIRE(row.has_bound);
    // The bound holds for the true failure probability; the measured rate's interval must
    // reach below it (or the bound says nothing at all).
    CHECK((row.bound.vacuous || row.failure_rate.low <= row.bound.bound));
    MESSAGE("n = " << row.samples << ": " << row.failures << "/" << row.trials << " failures, bound "
                   << row.bound.bound);
  }
  CHECK(rows[0].failures > rows[2].failures);
  CHECK(rows[0].failures > 0);
  CHECK(rows[2].failure_rate.estimate < 0.2);
}

TEST_CASE("where the bound says something, it is m e^(-sigma r^d n) and the measured rate respects it") {
  // A wide opening (0.3) gives a clearance large enough for the bound to fall below 1 at a few
  // hundred samples; the narrow gap above leaves every row vacuous, where "rate <= bound" could
  // not fail. The bound is written again here from the handout: m = ceil(L / (r/2)),
  // sigma = mu(B_1) / (2^d mu(F)) with mu(B_1) = pi in the plane.
  const csl::CollisionWorld wide(csl::PointRobot{},
                                 {csl::Wall{{0.5, 0.0}, {0.5, 0.35}}, csl::Wall{{0.5, 0.65}, {0.5, 1.0}}}, {0, 0}, {1, 1});
  csl::Experiment ex(wide, config({0.15, 0.5}), config({0.85, 0.5}), params({20, 200, 600}, 30));
  ex.run();
  const auto& ref = ex.reference();
  REQUIRE(ref.path_exists);
  REQUIRE(ref.dimension == 2);
  int real = 0;
  for (const auto& row : ex.rows()) {
    REQUIRE(row.has_bound);
    const double m = std::ceil(ref.path_length / (ref.clearance / 2));
    const double sigma = csl::kPi / (4.0 * ref.free_volume);
    const double bound = m * std::exp(-sigma * ref.clearance * ref.clearance * row.samples);
    CHECK(row.bound.balls == m);
    CHECK(row.bound.bound == doctest::Approx(bound).epsilon(1e-9));
    CHECK(row.bound.vacuous == (bound >= 1.0));
    if (row.bound.vacuous) continue;
    ++real;
    CHECK(row.failure_rate.low <= row.bound.bound);
    MESSAGE("n = " << row.samples << ": " << row.failures << "/" << row.trials << " failures, bound " << row.bound.bound);
  }
  CHECK(real >= 1);  // a row whose bound can be tested
}

TEST_CASE("experiments are reproducible from their seed") {
  const auto world = narrow_gap();
  csl::Experiment a(world, config({0.15, 0.85}), config({0.85, 0.75}), params({30}, 15));
  csl::Experiment b(world, config({0.15, 0.85}), config({0.85, 0.75}), params({30}, 15));
  a.run();
  b.run();
  CHECK(a.rows()[0].failures == b.rows()[0].failures);
  CHECK(a.reference().path_length == b.reference().path_length);
}

TEST_CASE("no path: the reference says so and no bound is given") {
  const csl::CollisionWorld closed(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 1.0}}}, {0, 0}, {1, 1});
  csl::Experiment ex(closed, config({0.15, 0.85}), config({0.85, 0.75}), params({20}, 3));
  ex.run();
  CHECK_FALSE(ex.reference().path_exists);
  CHECK_FALSE(ex.rows()[0].has_bound);
  CHECK(ex.rows()[0].failures == 3);
}

TEST_CASE("bad experiment parameters are refused") {
  const auto world = narrow_gap();
  CHECK_THROWS_AS(csl::Experiment(world, config({0.15, 0.85}), config({0.85, 0.75}), params({}, 3)), std::invalid_argument);
  CHECK_THROWS_AS(csl::Experiment(world, config({0.15, 0.85}), config({0.85, 0.75}), params({-5}, 3)), std::invalid_argument);
  CHECK_THROWS_AS(csl::Experiment(world, config({0.15, 0.85}), config({0.85, 0.75}), params({5}, 0)), std::invalid_argument);
}

TEST_CASE("the widest path: the roadmap's path of largest proven clearance, then the shortest") {
  const auto world = narrow_gap();
  csl::PrmParams p;
  p.samples = 3000;
  p.seed = 4;
  csl::Prm prm(world, config({0.15, 0.85}), config({0.85, 0.75}), p);
  prm.run();
  REQUIRE(prm.solved());
  const auto& r = prm.roadmap();
  const std::vector<int> wide = csl::widest_path(world, r);
  REQUIRE(wide.size() >= 2);
  CHECK(wide.front() == 0);
  CHECK(wide.back() == 1);
  // A path of the roadmap: consecutive vertices joined by an edge.
  for (std::size_t i = 0; i + 1 < wide.size(); ++i) {
    bool joined = false;
    for (const auto& e : r.edges)
      joined = joined || (e.alive && ((e.a == wide[i] && e.b == wide[i + 1]) || (e.b == wide[i] && e.a == wide[i + 1])));
    CHECK(joined);
  }
  const auto clearance = [&](const std::vector<int>& path) {
    std::vector<csl::Config> q;
    for (int v : path) q.push_back(r.vertices[static_cast<std::size_t>(v)]);
    return path_clearance(world, q, 1e-4);
  };
  // PRM's own (shortest) path passes a wall's end; the widest keeps away, toward the 0.02 the
  // gap allows (as near as the 3000 samples and the edges' proofs get).
  const double shortest = clearance(prm.path()), widest = clearance(wide);
  MESSAGE("clearance: shortest path " << shortest << ", widest " << widest);
  CHECK(widest > 5 * shortest);
  CHECK(widest > 0.008);
  CHECK(widest <= 0.02 + 1e-12);
  // Unconnected: nothing.
  csl::PrmParams few = p;
  few.samples = 0;
  csl::Prm blocked(world, config({0.15, 0.85}), config({0.85, 0.75}), few);
  blocked.run();
  CHECK(csl::widest_path(world, blocked.roadmap()).empty());
}

TEST_CASE("the proven clearance of an edge: a lower bound, close to the truth") {
  // The segment (0,0) -> (1,0) passes a disk of radius 0.05 centred 0.1 above its middle: its
  // least clearance is 0.05, at x = 0.5, where neither end's clearance tells it.
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.1}, 0.05}}, {-1, -1}, {2, 1});
  const auto p = config({0, 0}), q = config({1, 0});
  const double eta_p = world.clearance(p), eta_q = world.clearance(q);
  const double fine = csl::proven_edge_clearance(world, p, q, eta_p, eta_q, 4096);
  CHECK(fine <= 0.05);
  CHECK(fine > 0.048);  // halving stops within 1% of the least found so far
  // No clearance computed between the ends: the ends' bound alone, far below.
  CHECK(csl::proven_edge_clearance(world, p, q, eta_p, eta_q, 0) == doctest::Approx((eta_p + eta_q - 1.0) / 2));
  CHECK(csl::proven_edge_clearance(world, p, q, eta_p, eta_q, 4) < fine);
  // Along a path, the least over its edges; never above the sampled clearance.
  const std::vector<csl::Config> path = {config({-0.5, 0.5}), p, q};
  const double proven = csl::proven_path_clearance(world, path, 4096);
  CHECK(proven <= path_clearance(world, path, 1e-4));
  CHECK(proven == doctest::Approx(fine).epsilon(1e-9));
}
