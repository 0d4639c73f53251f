// PRM: the homework's algorithm step by step, its neighbour rules, its graph, replay to any
// step, and the same roadmap in every build (the pinned hash runs natively and in wasm).
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/base/angles.hpp"
#include "core/planning/potential_connector.hpp"
#include "core/planning/prm.hpp"
#include "core/scene/scene.hpp"

using csl::config;
using csl::Prm;
using csl::PrmEvent;
using csl::PrmParams;

namespace {
// P9's square: a wall at x = 1/2 with an opening of height 0.2 in the middle.
csl::CollisionWorld wall_with_gap() {
  return csl::CollisionWorld(csl::PointRobot{},
                             {csl::Wall{{0.5, 0.0}, {0.5, 0.4}}, csl::Wall{{0.5, 0.6}, {0.5, 1.0}}}, {0, 0}, {1, 1});
}

PrmParams params(int n, const char* rule = "k:10", const char* checker = "bisection", std::uint64_t seed = 7) {
  PrmParams p;
  p.samples = n;
  p.neighbors = csl::NeighborRule::parse(rule);
  p.checker = csl::EdgeCheckerSpec::parse(checker);
  p.seed = seed;
  return p;
}

// An outside oracle for "free", written here from the geometry and sharing nothing with the
// planner's checkers (no clearance, no motion bound, no bisection): where a robot's segments
// are at a configuration, and whether a segment meets an obstacle (closed: touching counts).
using Seg = std::pair<csl::Vec2, csl::Vec2>;

double cross(const csl::Vec2& o, const csl::Vec2& a, const csl::Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

double point_segment(const csl::Vec2& p, const Seg& s) {
  const csl::Vec2 d = s.second - s.first;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - s.first).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (s.first + t * d)).norm();
}

bool segments_meet(const Seg& a, const Seg& b) {
  const double d1 = cross(b.first, b.second, a.first), d2 = cross(b.first, b.second, a.second);
  const double d3 = cross(a.first, a.second, b.first), d4 = cross(a.first, a.second, b.second);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return point_segment(a.first, b) == 0 || point_segment(a.second, b) == 0 || point_segment(b.first, a) == 0 ||
         point_segment(b.second, a) == 0;
}

bool inside_polygon(const csl::Vec2& p, const csl::Polygon& poly) {  // even-odd rule
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    if ((poly[i].y() > p.y()) != (poly[j].y() > p.y()) &&
        p.x() < (poly[j].x() - poly[i].x()) * (p.y() - poly[i].y()) / (poly[j].y() - poly[i].y()) + poly[i].x())
      in = !in;
  return in;
}

bool segment_hits(const Seg& s, const csl::Obstacle& o) {
  if (const auto* d = std::get_if<csl::Disk>(&o)) return point_segment(d->center, s) <= d->radius;
  if (const auto* w = std::get_if<csl::Wall>(&o)) return segments_meet(s, {w->a, w->b});
  const csl::Polygon& poly = std::get<csl::PolygonObstacle>(o).vertices;
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (segments_meet(s, {poly[i], poly[(i + 1) % poly.size()]})) return true;
  return inside_polygon(s.first, poly);
}

// The robot's parts at q as segments: a point robot's one (degenerate) segment, the arm's links
// (any number) with std::cos and std::sin (the planner uses its own).
std::vector<Seg> robot_segments(const csl::Robot& robot, const csl::Config& q) {
  if (std::holds_alternative<csl::PointRobot>(robot)) return {{csl::Vec2(q[0], q[1]), csl::Vec2(q[0], q[1])}};
  const auto& arm = std::get<csl::ArmRobot>(robot);
  std::vector<Seg> links;
  csl::Vec2 at = arm.base;
  double angle = 0;
  for (std::size_t i = 0; i < arm.lengths.size(); ++i) {
    angle += q[static_cast<Eigen::Index>(i)];
    const csl::Vec2 next = at + arm.lengths[i] * csl::Vec2(std::cos(angle), std::sin(angle));
    links.push_back({at, next});
    at = next;
  }
  return links;
}

bool oracle_free(const csl::CollisionWorld& world, const csl::Config& q) {
  for (const Seg& s : robot_segments(world.robot(), q))
    for (const csl::Obstacle& o : world.obstacles())
      if (segment_hits(s, o)) return false;
  return true;
}

// The motion from a to b free by the oracle: for a point robot, exactly (the swept segment);
// for the arm, at 2000 configurations along the short way round each angle, in turns computed
// here (a dense check cannot prove a motion free, but it shares no code with the planner's).
bool oracle_edge_free(const csl::CollisionWorld& world, const csl::Config& a, const csl::Config& b) {
  if (std::holds_alternative<csl::PointRobot>(world.robot())) {
    const Seg s{csl::Vec2(a[0], a[1]), csl::Vec2(b[0], b[1])};
    for (const csl::Obstacle& o : world.obstacles())
      if (segment_hits(s, o)) return false;
    return true;
  }
  csl::Config d = b - a;
  for (Eigen::Index i = 0; i < d.size(); ++i) d[i] = std::remainder(d[i], 2.0 * csl::kPi);  // the shorter turn
  for (int k = 0; k <= 2000; ++k)
    if (!oracle_free(world, a + (k / 2000.0) * d)) return false;
  return true;
}

// A found path joins start to goal, and every edge of it is free by the outside oracle.
void require_valid_path(const Prm& prm) {
  REQUIRE(prm.solved());
  const auto& v = prm.roadmap().vertices;
  REQUIRE(prm.path().front() == 0);
  REQUIRE(prm.path().back() == 1);
  double length = 0;
  for (std::size_t i = 0; i + 1 < prm.path().size(); ++i) {
    const auto& a = v[static_cast<std::size_t>(prm.path()[i])];
    const auto& b = v[static_cast<std::size_t>(prm.path()[i + 1])];
    REQUIRE(oracle_edge_free(prm.world(), a, b));
    length += prm.world().space().distance(a, b);
  }
  CHECK(prm.path_length() == doctest::Approx(length));
}
}  // namespace

TEST_CASE("the steps follow the homework's order") {
  const auto world = wall_with_gap();
  Prm prm(world, config({0.1, 0.5}), config({0.9, 0.5}), params(50));
  CHECK(prm.step().kind == PrmEvent::Kind::AddEndpoint);
  CHECK(prm.roadmap().vertices.size() == 1);
  CHECK(prm.step().kind == PrmEvent::Kind::AddEndpoint);
  int accepted = 0, rejected = 0;
  for (int i = 1; i <= 50; ++i) {
    const PrmEvent& e = prm.step();
    REQUIRE(e.sample == i);
    REQUIRE((e.kind == PrmEvent::Kind::SampleAccepted || e.kind == PrmEvent::Kind::SampleRejected));
    (e.kind == PrmEvent::Kind::SampleAccepted ? accepted : rejected)++;
  }
  CHECK(prm.roadmap().vertices.size() == static_cast<std::size_t>(2 + accepted));
  CHECK(prm.phase() == csl::PrmPhase::Connecting);
  const PrmEvent& first = prm.step();
  CHECK(first.kind == PrmEvent::Kind::Neighbors);
  CHECK(first.vertex == 0);
  prm.run();
  CHECK(prm.done());
  CHECK((prm.last_event().kind == PrmEvent::Kind::PathFound || prm.last_event().kind == PrmEvent::Kind::NoPath));
}

TEST_CASE("PRM finds a path through the gap, and every edge it reports is free") {
  const auto world = wall_with_gap();
  Prm prm(world, config({0.1, 0.5}), config({0.9, 0.5}), params(400));
  prm.run();
  require_valid_path(prm);
  // The path passes through the opening: it has vertices on both sides of the wall, and each
  // of its edges that crosses x = 1/2 does so within the gap (0.4, 0.6).
  const auto& v = prm.roadmap().vertices;
  int left = 0, right = 0, crossings = 0;
  for (std::size_t i = 0; i < prm.path().size(); ++i) {
    const auto& a = v[static_cast<std::size_t>(prm.path()[i])];
    (a[0] < 0.5 ? left : right) += 1;
    if (i + 1 == prm.path().size()) continue;
    const auto& b = v[static_cast<std::size_t>(prm.path()[i + 1])];
    if ((a[0] < 0.5) == (b[0] < 0.5)) continue;
    ++crossings;
    const double y = a[1] + (0.5 - a[0]) / (b[0] - a[0]) * (b[1] - a[1]);
    CHECK((y > 0.4 && y < 0.6));
  }
  CHECK(left > 0);
  CHECK(right > 0);
  CHECK(crossings % 2 == 1);
  // And every edge of the roadmap is free by the outside oracle.
  for (const auto& e : prm.roadmap().edges)
    if (e.alive) REQUIRE(oracle_edge_free(world, v[static_cast<std::size_t>(e.a)], v[static_cast<std::size_t>(e.b)]));
}

TEST_CASE("no samples: only the straight line from start to goal is tried") {
  const csl::CollisionWorld empty(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  Prm prm(empty, config({0.1, 0.1}), config({0.9, 0.5}), params(0));
  prm.run();
  require_valid_path(prm);
  CHECK(prm.path() == std::vector<int>{0, 1});
  CHECK(prm.edge_checks() == 1);
  const auto walls = wall_with_gap();
  Prm blocked(walls, config({0.1, 0.1}), config({0.9, 0.1}), params(0));
  blocked.run();
  CHECK_FALSE(blocked.solved());
  CHECK(blocked.last_event().kind == PrmEvent::Kind::NoPath);
}

TEST_CASE("a closed wall: PRM declares that no path exists") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 1.0}}}, {0, 0}, {1, 1});
  Prm prm(world, config({0.1, 0.5}), config({0.9, 0.5}), params(300));
  prm.run();
  CHECK_FALSE(prm.solved());
  CHECK(prm.components() >= 2);
  const auto labels = prm.component_labels();
  CHECK(labels[0] != labels[1]);
}

TEST_CASE("an endpoint in collision ends the run at once") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.2}}, {0, 0}, {1, 1});
  Prm prm(world, config({0.1, 0.1}), config({0.5, 0.5}), params(100));
  prm.step();
  const PrmEvent& e = prm.step();
  CHECK(e.kind == PrmEvent::Kind::EndpointInCollision);
  CHECK(e.obstacle == 0);
  CHECK(prm.done());
  CHECK_FALSE(prm.solved());
}

TEST_CASE("each close pair is checked once, and only close pairs") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.15}}, {0, 0}, {1, 1});
  for (const char* rule : {"k:6", "radius:0.12", "prm*"}) {
    Prm prm(world, config({0.05, 0.05}), config({0.95, 0.95}), params(300, rule));
    std::set<std::pair<int, int>> checked;
    while (!prm.done()) {
      const PrmEvent& e = prm.step();
      if (e.kind == PrmEvent::Kind::EdgeAdded || e.kind == PrmEvent::Kind::EdgeRejected)
        REQUIRE(checked.insert({std::min(e.vertex, e.other), std::max(e.vertex, e.other)}).second);
    }
    // The expected pairs, by brute force.
    const auto& v = prm.roadmap().vertices;
    const auto n = static_cast<int>(v.size());
    const auto rule_parsed = csl::NeighborRule::parse(rule);
    std::set<std::pair<int, int>> expected;
    for (int p = 0; p < n; ++p) {
      if (rule_parsed.kind == csl::NeighborRule::Kind::Radius) {
        for (int q = 0; q < n; ++q)
          if (q != p && world.space().distance(v[static_cast<std::size_t>(p)], v[static_cast<std::size_t>(q)]) <= 0.12)
            expected.insert({std::min(p, q), std::max(p, q)});
      } else {
        const int k = rule_parsed.kind == csl::NeighborRule::Kind::PrmStar ? csl::NeighborRule::prm_star_k(n, 2) : 6;
        for (const auto& nb : csl::brute_force_k_nearest(world.space(), v, v[static_cast<std::size_t>(p)], k, p))
          expected.insert({std::min(p, nb.index), std::max(p, nb.index)});
      }
    }
    CHECK(checked == expected);
    CHECK(prm.edge_checks() == static_cast<long>(expected.size()));
  }
}

TEST_CASE("a vertex's close pairs: the new ones, and those seen already from the other vertex") {
  // What the log tells a student ("0 close pairs to check" is not an error when all of them were
  // checked from the other side): candidates + seen is every close vertex, counted here by brute force.
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.15}}, {0, 0}, {1, 1});
  for (const char* rule : {"k:6", "radius:0.12", "prm*"}) {
    Prm prm(world, config({0.05, 0.05}), config({0.95, 0.95}), params(300, rule));
    const auto parsed = csl::NeighborRule::parse(rule);
    int all_seen = 0, zero_new = 0;
    while (!prm.done()) {
      const PrmEvent& e = prm.step();
      if (e.kind != PrmEvent::Kind::Neighbors) continue;
      const auto& v = prm.roadmap().vertices;
      const int n = static_cast<int>(v.size());
      int close = 0;
      if (parsed.kind == csl::NeighborRule::Kind::Radius) {
        for (int q = 0; q < n; ++q)
          close += q != e.vertex && world.space().distance(v[static_cast<std::size_t>(e.vertex)], v[static_cast<std::size_t>(q)]) <= 0.12;
      } else {
        const int k = parsed.kind == csl::NeighborRule::Kind::PrmStar ? csl::NeighborRule::prm_star_k(n, 2) : 6;
        close = std::min(k, n - 1);
      }
      REQUIRE(e.seen >= 0);
      REQUIRE(e.candidates + e.seen == close);
      all_seen += e.seen;
      zero_new += e.candidates == 0 && e.seen > 0;
    }
    // The pairs seen twice are counted once as candidates: for k rules some pairs are mutual,
    // and a radius's every pair is (it is seen again from its larger vertex).
    CHECK(all_seen > 0);
    if (parsed.kind == csl::NeighborRule::Kind::Radius) CHECK(all_seen == prm.edge_checks());
    CHECK(zero_new > 0);  // the case the log explains happens
  }
}

TEST_CASE("PRM*'s k(n) = ceil(e (1 + 1/d) ln n)") {
  CHECK(csl::NeighborRule::prm_star_k(20000, 2) == 41);
  CHECK(csl::NeighborRule::prm_star_k(1000, 3) == 26);
  CHECK(csl::NeighborRule::parse("k:7").k == 7);
  CHECK(csl::NeighborRule::parse("radius:0.25").name() == "radius:0.25");
  CHECK_THROWS_AS(csl::NeighborRule::parse("k:0"), std::invalid_argument);
  CHECK_THROWS_AS(csl::NeighborRule::parse("k:2.5"), std::invalid_argument);
  CHECK_THROWS_AS(csl::NeighborRule::parse("radius:-1"), std::invalid_argument);
  CHECK_THROWS_AS(csl::NeighborRule::parse("nearest"), std::invalid_argument);
}

TEST_CASE("the expected number of candidate pairs, against the pairs PRM checks") {
  const csl::CollisionWorld empty(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  const csl::Space& square = empty.space();
  const auto rule = [](const char* text) { return csl::NeighborRule::parse(text); };
  CHECK(csl::expected_candidate_pairs(square, rule("k:10"), 998) == 10000);
  CHECK(csl::expected_candidate_pairs(square, rule("k:10"), 3) == 10);  // all 5 * 4 / 2 pairs
  CHECK(csl::expected_candidate_pairs(square, rule("prm*"), 998) == 1000 * csl::NeighborRule::prm_star_k(1000, 2));
  // Radius: C(1000, 2) pairs, each within r with probability pi r^2 (the unit square).
  const double pi = 3.141592653589793;
  CHECK(csl::expected_candidate_pairs(square, rule("radius:0.1"), 998) == doctest::Approx(499500 * pi * 0.01));
  CHECK(csl::expected_candidate_pairs(square, rule("radius:3"), 998) == 499500);

  // What PRM counts, in empty spaces: only balls sticking out of Q make it fewer. For r = 0.1
  // in the unit square that is 8.3% (exactly pi r^2 - 8 r^3 / 3 + r^4 / 2); on the arm's torus
  // (volume 4 pi^2, no boundary) nothing; in SE(2) with the angle weighted by the robot's
  // radius 0.1 (volume 4 * 4 * 2 pi 0.1, 3-d balls) a few percent at the x and y walls.
  const csl::CollisionWorld arm(csl::ArmRobot{}, {}, {-3, -3}, {3, 3});
  const csl::CollisionWorld se2(csl::make_polygon_robot({{-0.1, 0.0}, {0.1, 0.0}, {0.0, 0.1}}), {}, {0, 0}, {4, 4});
  struct Case {
    const csl::CollisionWorld* world;
    const char* rule;
    int n;
    double low, high;  // measured / expected
  };
  for (const Case& c : {Case{&empty, "radius:0.1", 998, 0.88, 0.95}, Case{&arm, "radius:0.5", 998, 0.93, 1.07},
                        Case{&se2, "radius:0.3", 998, 0.85, 1.02}}) {
    const csl::Space& space = c.world->space();
    const csl::Config start = space.dim() == 2 ? config({0.5, 0.5}) : config({1.0, 1.0, 0.0});
    const csl::Config goal = space.dim() == 2 ? config({0.7, 0.2}) : config({3.0, 2.0, 1.0});
    double measured = 0;
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      Prm prm(*c.world, start, goal, params(c.n, c.rule, "bisection", seed));
      prm.run();
      REQUIRE(prm.roadmap().vertices.size() == static_cast<std::size_t>(c.n + 2));  // all free
      measured += static_cast<double>(prm.edge_checks()) / 3;
    }
    const double expected = csl::expected_candidate_pairs(space, rule(c.rule), c.n);
    INFO(std::string(c.rule) << " in " << space.dim() << "-d: measured " << measured << ", expected " << expected);
    CHECK(measured / expected >= c.low);
    CHECK(measured / expected <= c.high);
  }

  // The inverse, and no radius at all when every pair is within the count.
  for (const csl::Space* space : {&square, &arm.space(), &se2.space()}) {
    csl::NeighborRule r = rule("radius:1");
    r.radius = csl::radius_for_pairs(*space, 20000, 1e6);
    CHECK(csl::expected_candidate_pairs(*space, r, 20000) == doctest::Approx(1e6));
  }
  CHECK(csl::radius_for_pairs(square, 20000, 1e6) == doctest::Approx(std::sqrt(1e6 / (20002.0 * 20001 / 2) / pi)));
  CHECK(std::isinf(csl::radius_for_pairs(square, 500, 1e6)));  // C(502, 2) = 125751 pairs in all
  CHECK(std::isinf(csl::radius_for_pairs(square, 0, 1)));
}

TEST_CASE("the pairs budget: the radius it names, as text, fits, and a hair more does not") {
  const csl::CollisionWorld square(csl::PointRobot{}, {}, {0, 0}, {1, 1});
  const csl::CollisionWorld arm(csl::ArmRobot{{0, 0}, 1.0, 1.0}, {}, {-3, -3}, {3, 3});
  const auto radius = [](double r) {
    csl::NeighborRule rule = csl::NeighborRule::parse("radius:1");
    rule.radius = r;
    return rule;
  };
  for (const csl::Space* space : {&square.space(), &arm.space()})
    for (const int n : {300, 2000, 5000, 20000, 100000, 1000000})
      for (const double pairs : {1000.0, 20000.0, 123457.0, 1e6, 2e7}) {
        const double fits = csl::radius_for_pairs(*space, n, pairs);
        if (std::isinf(fits)) continue;
        const std::string text = csl::radius_for_pairs_text(*space, n, pairs);
        const double shown = std::strtod(text.c_str(), nullptr);
        INFO(n << " samples, " << pairs << " pairs: " << text << " for " << fits);
        CHECK(shown <= fits);
        CHECK(shown >= fits * (1 - 2e-3));  // 4 significant digits, rounded down
        CHECK(csl::within_pairs_budget(*space, radius(shown), n, pairs));
        CHECK(csl::within_pairs_budget(*space, radius(fits), n, pairs));  // the inverse itself passes
        CHECK_FALSE(csl::within_pairs_budget(*space, radius(fits * 1.001), n, pairs));
      }
  // k rules: (n + 2) k pairs, no radius to fall back on.
  CHECK(csl::within_pairs_budget(square.space(), csl::NeighborRule::parse("k:10"), 998, 10000));
  CHECK_FALSE(csl::within_pairs_budget(square.space(), csl::NeighborRule::parse("k:10"), 999, 10000));
  CHECK(csl::radius_for_pairs_text(square.space(), 20000, 1e6) == "0.03989");  // the app's limit
  CHECK(csl::radius_for_pairs_text(square.space(), 500, 1e6) == "any");  // every pair fits
}

TEST_CASE("edge lengths are the space's distances to the bit, and candidates carry them") {
  // The k-nearest rows keep floats; PRM measures each candidate again. It must get the bits the
  // space's distance gives (and the neighbour search compared): on the plane and the torus (the
  // grid), in weighted SE(2) (the k-d tree), for the k rules and PRM*, grid checker or not.
  const csl::CollisionWorld plane(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.2}}, {0, 0}, {1, 1});
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.9, 0.5}, 0.08}}, {0, 0}, {1, 1});
  const csl::CollisionWorld se2(csl::make_polygon_robot({{-0.1, 0.0}, {0.1, 0.0}, {0.0, 0.1}}),
                                {csl::Disk{{2.0, 2.0}, 0.5}}, {0, 0}, {4, 4});
  struct Case {
    const csl::CollisionWorld* world;
    csl::Config start, goal;
  };
  for (const Case& c : {Case{&plane, config({0.1, 0.1}), config({0.9, 0.9})},
                        Case{&arm, config({2.0, 0.5}), config({-2.0, -0.5})},  // pointing away from the disk
                        Case{&se2, config({0.5, 0.5, 0.0}), config({3.5, 3.5, 1.0})}}) {
    const csl::CollisionWorld* world = c.world;
    const csl::Space& space = world->space();
    const csl::Config& start = c.start;
    const csl::Config& goal = c.goal;
    for (const char* rule : {"k:7", "prm*"}) {
      Prm prm(*world, start, goal, params(400, rule, rule[0] == 'k' ? "step:0.02" : "bisection"));
      long candidates = 0;
      while (prm.phase() != csl::PrmPhase::Query && !prm.done()) {
        const PrmEvent& e = prm.step();
        if (e.kind != PrmEvent::Kind::Neighbors) continue;
        const auto& v = prm.roadmap().vertices;
        for (const csl::Neighbor& nb : prm.candidates()) {
          REQUIRE(nb.squared_distance == space.squared_distance(v[static_cast<std::size_t>(e.vertex)],
                                                                v[static_cast<std::size_t>(nb.index)]));
          ++candidates;
        }
      }
      REQUIRE(candidates > 1000);
      const auto& v = prm.roadmap().vertices;
      for (const csl::RoadmapEdge& edge : prm.roadmap().edges)
        REQUIRE(edge.length == space.distance(v[static_cast<std::size_t>(edge.a)], v[static_cast<std::size_t>(edge.b)]));
      CHECK(prm.roadmap().edges.size() > 500);
    }
  }
}

TEST_CASE("going back to step k gives the identical state") {
  const auto world = wall_with_gap();
  Prm prm(world, config({0.1, 0.5}), config({0.9, 0.5}), params(200));
  std::vector<std::uint64_t> hash_at;
  std::vector<long> edges_at;
  while (!prm.done()) {
    prm.step();
    hash_at.push_back(csl::roadmap_hash(prm.roadmap()));
    edges_at.push_back(prm.edges_alive());
  }
  for (long k : {1L, 2L, 57L, 203L, 250L, static_cast<long>(hash_at.size()) - 1, static_cast<long>(hash_at.size())}) {
    prm.run_to(k);
    REQUIRE(prm.steps() == k);
    REQUIRE(csl::roadmap_hash(prm.roadmap()) == hash_at[static_cast<std::size_t>(k - 1)]);
    REQUIRE(prm.edges_alive() == edges_at[static_cast<std::size_t>(k - 1)]);
  }
}

TEST_CASE("finish_phase() and run() leave the state stepping leaves, phase by phase") {
  const csl::CollisionWorld disks(csl::PointRobot{},
                                  {csl::Disk{{0.3, 0.3}, 0.1}, csl::Disk{{0.7, 0.6}, 0.15}, csl::Wall{{0.6, 0.0}, {0.6, 0.3}}},
                                  {0, 0}, {1, 1});
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.8, 0.8}, 0.1}}, {0, 0}, {1, 1});
  struct Case {
    const csl::CollisionWorld* world;
    csl::Config start, goal;
    PrmParams params;
  };
  PrmParams with_connector = params(60, "k:5", "bisection", 4);
  with_connector.connector = std::make_shared<csl::PotentialConnector>();
  const std::vector<Case> cases = {
      {&disks, config({0.05, 0.05}), config({0.95, 0.95}), params(300, "k:10", "step:0.02", 5)},
      {&disks, config({0.05, 0.05}), config({0.95, 0.95}), params(300, "radius:0.1", "grid:5", 6)},
      {&disks, config({0.05, 0.05}), config({0.95, 0.95}), params(200, "prm*", "bisection", 7)},
      {&disks, config({0.05, 0.05}), config({0.95, 0.95}), params(1, "k:3", "bisection", 8)},
      {&disks, config({0.05, 0.05}), config({0.95, 0.95}), params(0, "k:3", "bisection", 8)},
      {&disks, config({0.05, 0.05}), config({0.95, 0.95}), with_connector},
      {&arm, config({0.0, 0.0}), config({3.0, -1.0}), params(300, "k:8", "step:0.05", 9)},
      {&disks, config({0.3, 0.3}), config({0.95, 0.95}), params(30, "k:3", "bisection", 8)},  // start in a disk
  };
  for (const Case& c : cases) {
    Prm stepped(*c.world, c.start, c.goal, c.params), bulk(*c.world, c.start, c.goal, c.params);
    while (!bulk.done()) {
      const csl::PrmPhase phase = bulk.phase();
      bulk.finish_phase();
      while (!stepped.done() && stepped.phase() == phase) stepped.step();
      REQUIRE(bulk.steps() == stepped.steps());
      REQUIRE(bulk.phase() == stepped.phase());
      REQUIRE(csl::roadmap_hash(bulk.roadmap()) == csl::roadmap_hash(stepped.roadmap()));
      REQUIRE(bulk.samples_drawn() == stepped.samples_drawn());
      REQUIRE(bulk.edge_checks() == stepped.edge_checks());
      REQUIRE(bulk.evaluations() == stepped.evaluations());
      REQUIRE(bulk.edges_alive() == stepped.edges_alive());
      REQUIRE(bulk.components() == stepped.components());
      REQUIRE(bulk.connecting_vertex() == stepped.connecting_vertex());
      const PrmEvent &a = bulk.last_event(), &b = stepped.last_event();
      REQUIRE(a.kind == b.kind);
      REQUIRE(a.step == b.step);
      REQUIRE(a.vertex == b.vertex);
      REQUIRE(a.other == b.other);
      REQUIRE(a.sample == b.sample);
    }
    REQUIRE(stepped.done());
    REQUIRE(bulk.path() == stepped.path());
    Prm ran(*c.world, c.start, c.goal, c.params);
    ran.run();
    REQUIRE(ran.steps() == stepped.steps());
    REQUIRE(csl::roadmap_hash(ran.roadmap()) == csl::roadmap_hash(stepped.roadmap()));
    // Stepping on from a finished phase, and going back into it, still agree.
    ran.run_to(ran.steps() / 2);
    stepped.run_to(stepped.steps() / 2);
    REQUIRE(csl::roadmap_hash(ran.roadmap()) == csl::roadmap_hash(stepped.roadmap()));
  }
}

TEST_CASE("the same inputs give the same roadmap in every build (pinned hash)") {
  const csl::CollisionWorld world(csl::PointRobot{},
                                  {csl::Disk{{0.3, 0.3}, 0.1}, csl::Disk{{0.7, 0.6}, 0.15},
                                   csl::PolygonObstacle{{{0.4, 0.7}, {0.5, 0.9}, {0.3, 0.85}}}, csl::Wall{{0.6, 0.0}, {0.6, 0.3}}},
                                  {0, 0}, {1, 1});
  Prm prm(world, config({0.05, 0.05}), config({0.95, 0.95}), params(500, "k:10", "bisection", 42));
  prm.run();
  require_valid_path(prm);
  CHECK(prm.roadmap().vertices.size() == 446);
  CHECK(prm.edges_alive() == 2549);
  CHECK(csl::roadmap_hash(prm.roadmap()) == 6501816432234514842ull);

  // The arm on its torus, whose kinematics use the lab's own sine and cosine.
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.8, 0.8}, 0.1}, csl::Disk{{0.2, 0.4}, 0.08}},
                                {0, 0}, {1, 1});
  Prm on_torus(arm, config({0.0, 0.0}), config({3.0, -1.0}), params(400, "k:8", "bisection", 3));
  on_torus.run();
  require_valid_path(on_torus);
  CHECK(csl::roadmap_hash(on_torus.roadmap()) == 10815498988223929989ull);
}

TEST_CASE("on the torus, edges cross the seams") {
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.85, 0.5}, 0.08}}, {0, 0}, {1, 1});
  Prm prm(arm, config({2.5, 0.0}), config({-2.5, 0.0}), params(300, "k:10"));
  prm.run();
  require_valid_path(prm);
  int across = 0;
  for (const auto& e : prm.roadmap().edges) {
    const auto& a = prm.roadmap().vertices[static_cast<std::size_t>(e.a)];
    const auto& b = prm.roadmap().vertices[static_cast<std::size_t>(e.b)];
    across += std::fabs(a[0] - b[0]) > csl::kPi || std::fabs(a[1] - b[1]) > csl::kPi;
  }
  CHECK(across > 10);
  // From 2.5 to -2.5 the short way is through pi, 1.28 rad, not 5 rad through 0 (where the disk is).
  CHECK(prm.path_length() < 2.0);
}

TEST_CASE("edges a coarse grid let through a wall are caught when the path is re-checked") {
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Wall{{0.5, 0.0}, {0.5, 1.0}}}, {0, 0}, {1, 1});
  // grid:2 tests only the endpoints: every edge across the wall gets in.
  Prm prm(world, config({0.1, 0.5}), config({0.9, 0.5}), params(100, "k:10", "grid:2"));
  int removed = 0;
  while (!prm.done()) removed += prm.step().kind == PrmEvent::Kind::PathEdgeRemoved;
  CHECK(removed > 0);
  CHECK_FALSE(prm.solved());  // the wall is closed: once the bad edges are gone, no path is left
}

TEST_CASE("a 3-link arm is a scene: PRM plans on T^3, each path edge free by the oracle") {
  // Issue 23: a robot of another number of links is data, not a new type.
  const nlohmann::json j = nlohmann::json::parse(R"({
    "version": 1, "workspace": {"min": [0, 0], "max": [1, 1]},
    "robot": {"type": "arm", "base": [0.5, 0.5], "lengths": [0.22, 0.16, 0.1]},
    "obstacles": [{"type": "disk", "center": [0.85, 0.55], "radius": 0.07},
                  {"type": "disk", "center": [0.3, 0.85], "radius": 0.08},
                  {"type": "polygon", "vertices": [[0.15, 0.15], [0.35, 0.2], [0.25, 0.35]]}],
    "start": [1.6, 0.3, -0.4], "goal": [2.6, -0.5, 1.0]})");
  const csl::Scene scene = csl::scene_from_json(j);
  REQUIRE(std::get<csl::ArmRobot>(scene.robot).links() == 3);
  CHECK(csl::scene_to_json(scene)["robot"] == j["robot"]);  // written back as read
  const csl::CollisionWorld world(scene);
  CHECK(world.space().dim() == 3);
  REQUIRE(world.is_free(scene.start));
  REQUIRE(world.is_free(scene.goal));
  Prm prm(world, scene.start, scene.goal, params(400, "k:10", "bisection", 5));
  prm.run();
  require_valid_path(prm);
  // Roadmap edges too, by the oracle (a sample of them: each is 2000 arm poses).
  int checked = 0;
  for (std::size_t e = 0; e < prm.roadmap().edges.size(); e += 23, ++checked) {
    const auto& edge = prm.roadmap().edges[e];
    if (!edge.alive) continue;
    REQUIRE(oracle_edge_free(world, prm.roadmap().vertices[static_cast<std::size_t>(edge.a)],
                             prm.roadmap().vertices[static_cast<std::size_t>(edge.b)]));
  }
  CHECK(checked > 20);
  // And the same roadmap in every build (the wasm unit tests run this file too).
  CHECK(csl::roadmap_hash(prm.roadmap()) == 10840063105130579134ull);
}
