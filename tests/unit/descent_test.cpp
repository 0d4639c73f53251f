// Gradient descent on the potential field: it reaches the goal in free scenes, stops in the
// cup's local minimum, escapes it by seeded random walks (the same trajectory in every build),
// and never steps into collision. Runs natively and in wasm.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "core/checking/edge_check.hpp"
#include "core/fields/descent.hpp"

using csl::config;
using csl::Config;
using csl::Descent;
using csl::DescentEvent;
using csl::DescentOutcome;
using csl::DescentParams;

namespace {

// A U-shaped obstacle opening downward, between the start below it and the goal above it.
const csl::Polygon kCup{{0.3, 0.4}, {0.4, 0.4}, {0.4, 0.6}, {0.6, 0.6}, {0.6, 0.4},
                        {0.7, 0.4}, {0.7, 0.7}, {0.3, 0.7}};

// Every piece of the trajectory is free by the exact check, and no piece is longer than a step
// (or a random-walk step).
void require_free_polyline(const csl::CollisionWorld& world, const std::vector<Config>& t, double max_piece) {
  const auto bisection = csl::EdgeCheckerSpec::parse("bisection");
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    REQUIRE(world.space().distance(t[i], t[i + 1]) <= max_piece);
    REQUIRE_FALSE(csl::check_edge(world, bisection, t[i], t[i + 1]).collision);
  }
}

// FNV-1a of the trajectory's bits: pins the same run in every build.
std::uint64_t trajectory_hash(const std::vector<Config>& t) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const Config& q : t)
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      std::uint64_t bits;
      std::memcpy(&bits, &q[i], sizeof bits);
      for (int b = 0; b < 8; ++b) {
        h ^= (bits >> (8 * b)) & 0xffu;
        h *= 0x100000001b3ull;
      }
    }
  return h;
}

}  // namespace

TEST_CASE("free scenes: the descent reaches the goal (point, polygon, arm)") {
  {
    const csl::CollisionWorld world(csl::PointRobot{}, {}, {0, 0}, {1, 1});
    const csl::PotentialField field(world, config({0.9, 0.7}));
    Descent d(field, config({0.1, 0.2}));
    d.run();
    CHECK(d.outcome() == DescentOutcome::Goal);
    CHECK(d.last_event().kind == DescentEvent::Kind::ReachedGoal);
    CHECK(d.distance_to_goal() <= d.params().tolerance);
    // Attraction alone pulls a point straight at the goal: |pq| / alpha steps, all on the line.
    CHECK(d.descent_steps() == static_cast<int>(std::ceil((std::sqrt(0.8 * 0.8 + 0.5 * 0.5) - 0.01) / 0.01)));
    for (const Config& q : d.trajectory()) CHECK(std::fabs((q[0] - 0.1) * 0.5 - (q[1] - 0.2) * 0.8) < 1e-12);
  }
  {
    // SE(2): position and heading both converge (the vertices pull toward their goal places).
    const auto robot = csl::make_polygon_robot({{-0.08, -0.04}, {0.08, -0.04}, {0.08, 0.04}, {-0.08, 0.04}});
    const csl::CollisionWorld world(robot, {}, {0, 0}, {1, 1});
    const csl::PotentialField field(world, config({0.8, 0.75, 1.5}));
    Descent d(field, config({0.2, 0.3, -0.5}));
    d.run();
    CHECK(d.outcome() == DescentOutcome::Goal);
    CHECK(std::fabs(csl::angle_difference(d.q()[2], 1.5)) * robot.radius <= 0.01);
  }
  {
    const csl::CollisionWorld world(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {}, {0, 0}, {1, 1});
    const csl::PotentialField field(world, config({2.0, -1.0}));
    Descent d(field, config({-0.5, 0.8}));
    d.run();
    CHECK(d.outcome() == DescentOutcome::Goal);
  }
}

TEST_CASE("around obstacles that make no trap, the descent reaches the goal, every piece free") {
  const csl::CollisionWorld world(csl::PointRobot{},
                                  {csl::Disk{{0.5, 0.52}, 0.1}, csl::Wall{{0.75, 0.1}, {0.75, 0.3}},
                                   csl::PolygonObstacle{{{0.2, 0.7}, {0.35, 0.75}, {0.25, 0.85}}}},
                                  {0, 0}, {1, 1});
  const csl::PotentialField field(world, config({0.85, 0.5}));
  Descent d(field, config({0.15, 0.5}));
  d.run();
  CHECK(d.outcome() == DescentOutcome::Goal);
  CHECK(d.local_minima() == 0);
  require_free_polyline(world, d.trajectory(), 0.01 + 1e-12);
  // It went around the disk (below it: the disk's centre is a little above the line).
  double lowest = 1;
  for (const Config& q : d.trajectory()) lowest = std::min(lowest, q[1]);
  CHECK(lowest < 0.42);
}

TEST_CASE("the cup: plain descent stops in the local minimum, random walks escape it") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::PolygonObstacle{kCup}}, {0, 0}, {1, 1});
  const csl::PotentialField field(world, config({0.5, 0.9}));
  const Config start = config({0.52, 0.2});

  Descent plain(field, start);
  plain.run();
  CHECK(plain.outcome() == DescentOutcome::LocalMinimum);
  CHECK(plain.last_event().kind == DescentEvent::Kind::GaveUp);
  CHECK(plain.local_minima() == 1);
  // Stuck in the cup's mouth, under its ceiling (y = 0.6), where the ceiling's push balances
  // the pull of the goal above: 1e-4 (1/rho - 10) / rho^2 = 0.2 at rho ~ 0.06.
  CHECK(std::fabs(plain.q()[0] - 0.5) < 0.02);
  CHECK(plain.q()[1] > 0.5);
  CHECK(plain.q()[1] < 0.6);
  CHECK(plain.distance_to_goal() > 0.3);

  DescentParams params;
  params.escapes = 10;
  params.seed = 2;
  Descent escape(field, start, params);
  int minima = 0, walks = 0;
  while (!escape.done()) {
    const DescentEvent& e = escape.step();
    minima += e.kind == DescentEvent::Kind::LocalMinimum;
    walks += e.kind == DescentEvent::Kind::RandomWalk;
    if (e.kind == DescentEvent::Kind::LocalMinimum) CHECK(escape.q()[1] < 0.6);  // each one in the cup
  }
  CHECK(escape.outcome() == DescentOutcome::Escaped);
  CHECK(escape.distance_to_goal() <= params.tolerance);
  CHECK(minima == escape.escapes_used());
  CHECK(walks == minima * params.walk_steps);
  CHECK(escape.walk_steps() == walks);
  require_free_polyline(world, escape.trajectory(), 0.1 * std::sqrt(2.0) + 1e-12);

  // Seeded: the same run again, and after reset(); pinned so that wasm must agree bit for bit.
  const auto hash = trajectory_hash(escape.trajectory());
  Descent again(field, start, params);
  again.run();
  CHECK(trajectory_hash(again.trajectory()) == hash);
  again.reset();
  again.run();
  CHECK(trajectory_hash(again.trajectory()) == hash);
  MESSAGE("cup escape (seed 2): " << escape.steps() << " steps, " << escape.escapes_used() << " escapes, hash " << hash);
  CHECK(escape.steps() == 154);
  CHECK(escape.escapes_used() == 1);
  CHECK(hash == 18381538553532658162ull);
}

TEST_CASE("steps never enter collision: a long step is halved, a blocked one is a minimum") {
  // Goal right behind a wall: the descent slides up to it and cannot pass.
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Wall{{0.5, 0.1}, {0.5, 0.9}}}, {0, 0}, {1, 1});
  csl::PotentialParams weak;
  weak.eta = 1e-9;  // almost no repulsion: the wall alone must stop it
  const csl::PotentialField field(world, config({0.7, 0.5}), weak);
  DescentParams params;
  params.step = 0.07;
  params.max_halvings = 3;
  Descent d(field, config({0.2, 0.5}), params);
  int halved = 0;
  bool blocked = false;
  while (!d.done()) {
    const DescentEvent& e = d.step();
    halved += e.halvings > 0;
    blocked = blocked || e.blocked;
  }
  CHECK(d.outcome() == DescentOutcome::LocalMinimum);
  CHECK(halved > 0);
  CHECK(blocked);
  CHECK(d.q()[0] < 0.5);
  require_free_polyline(world, d.trajectory(), 0.07 + 1e-12);
}

TEST_CASE("the step budget, the event sequence and bad parameters") {
  const csl::CollisionWorld world(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  const csl::PotentialField field(world, config({0.9, 0.9}));
  DescentParams params;
  params.max_steps = 5;
  Descent d(field, config({0.1, 0.1}), params);
  for (int i = 1; i <= 5; ++i) {
    const DescentEvent& e = d.step();
    CHECK(e.kind == DescentEvent::Kind::Descend);
    CHECK(e.step == i);
    CHECK(e.q == d.q());
    CHECK(e.U == d.potential());
  }
  CHECK(d.step().kind == DescentEvent::Kind::GaveUp);
  CHECK(d.outcome() == DescentOutcome::MaxSteps);
  CHECK(d.trajectory().size() == 6);
  CHECK_THROWS_AS(d.step(), std::logic_error);

  params = DescentParams{};
  params.step = 0;
  CHECK_THROWS_AS(Descent(field, config({0.1, 0.1}), params), std::invalid_argument);
  const csl::CollisionWorld disk(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.1}}, {0, 0}, {1, 1});
  const csl::PotentialField disk_field(disk, config({0.9, 0.9}));
  CHECK_THROWS_AS(Descent(disk_field, config({0.5, 0.5})), std::invalid_argument);  // not free
  csl::PotentialParams bad;
  bad.rho0 = -1;
  CHECK_THROWS_AS(csl::PotentialField(world, config({0.5, 0.5}), bad), std::invalid_argument);
  CHECK(std::string(csl::outcome_name(DescentOutcome::Escaped)) == "escaped");
  CHECK(std::string(csl::descent_event_name(DescentEvent::Kind::RandomWalk)) == "random_walk");
}
