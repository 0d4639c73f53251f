// PRM's samplers (core/planning/sampler.hpp): the text form, det::log, the Halton points by hand,
// normal deviates' moments, pinned roadmaps per sampler, and the lesson itself: the bridge test
// finds a narrow passage that uniform sampling starves, Gaussian sampling hugs obstacles.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/planning/prm.hpp"
#include "core/planning/sampler.hpp"
#include "core/scene/narrow_passage.hpp"

using csl::config;
using csl::SamplerSpec;

namespace {

csl::PrmParams params(int n, const std::string& sampler, std::uint64_t seed) {
  csl::PrmParams p;
  p.samples = n;
  p.sampler = SamplerSpec::parse(sampler);
  p.seed = seed;
  return p;
}

csl::PolygonObstacle box(double x0, double y0, double x1, double y1) {
  return csl::PolygonObstacle{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

// A thick wall (x in [0.4, 0.6]) across the unit square with a gap of 3% of the width at
// y in [0.485, 0.515], and two disks elsewhere so that the bridge test has other gaps to find.
csl::CollisionWorld narrow_passage() {
  return csl::CollisionWorld(csl::PointRobot{},
                             {box(0.4, 0.0, 0.6, 0.485), box(0.4, 0.515, 0.6, 1.0), csl::Disk{{0.2, 0.25}, 0.08},
                              csl::Disk{{0.8, 0.75}, 0.1}},
                             {0, 0}, {1, 1});
}
bool in_passage(const csl::Config& q) { return q[0] >= 0.4 && q[0] <= 0.6 && q[1] >= 0.485 && q[1] <= 0.515; }

// The accepted samples (roadmap vertices but the endpoints) of PRM's sampling phase.
std::vector<csl::Config> accepted(const csl::CollisionWorld& world, const std::string& sampler, int n, std::uint64_t seed) {
  csl::Prm prm(world, config({0.05, 0.5}), config({0.95, 0.5}), params(n, sampler, seed));
  while (!prm.done() && prm.phase() != csl::PrmPhase::Connecting) prm.finish_phase();
  const auto& v = prm.roadmap().vertices;
  return {v.begin() + 2, v.end()};
}

}  // namespace

TEST_CASE("the sampler's text: the four kinds, read back, and clear errors") {
  CHECK(SamplerSpec::parse("uniform").kind == SamplerSpec::Kind::Uniform);
  CHECK(SamplerSpec::parse("halton").kind == SamplerSpec::Kind::Halton);
  const SamplerSpec g = SamplerSpec::parse("gaussian:0.05");
  CHECK(g.kind == SamplerSpec::Kind::Gaussian);
  CHECK(g.sigma == 0.05);
  CHECK(g.name() == "gaussian:0.05");
  const SamplerSpec b = SamplerSpec::parse("bridge:1e-3");
  CHECK(b.kind == SamplerSpec::Kind::Bridge);
  CHECK(b.name() == "bridge:0.001");
  CHECK(SamplerSpec::parse(b.name()).sigma == b.sigma);
  CHECK(SamplerSpec::parse("gaussian:0.1").name() == "gaussian:0.1");
  for (const char* bad : {"gaussian:0", "gaussian:-0.1", "bridge:nan", "bridge:NaN", "gaussian:inf", "gaussian:",
                          "gaussian: 0.1", "bridge:0.1x", "gaussian", "bridge", "Uniform", "sobol", ""}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(SamplerSpec::parse(bad), std::invalid_argument);
  }
  CHECK_THROWS_WITH(SamplerSpec::parse("sobol"),
                    "unknown sampler 'sobol' (uniform, gaussian:S, bridge:S or halton; a hybrid adds a uniform share: "
                    "bridge:S,uniform:W)");
  // The hybrids: ,uniform:W after gaussian or bridge, W in [0, 1); W = 0 is the plain sampler.
  const SamplerSpec h = SamplerSpec::parse("bridge:0.05,uniform:0.3");
  CHECK(h.kind == SamplerSpec::Kind::Bridge);
  CHECK(h.sigma == 0.05);
  CHECK(h.uniform_share == 0.3);
  CHECK(h.name() == "bridge:0.05,uniform:0.3");
  CHECK(SamplerSpec::parse("gaussian:0.1,uniform:0.25").name() == "gaussian:0.1,uniform:0.25");
  CHECK(SamplerSpec::parse("bridge:0.1,uniform:0").name() == "bridge:0.1");
  // A sigma in exponent form, with its sign, stays readable, alone and in a hybrid.
  CHECK(SamplerSpec::parse("gaussian:1e+2").sigma == 100.0);
  CHECK(SamplerSpec::parse("gaussian:1e+0,uniform:0.3").name() == "gaussian:1,uniform:0.3");
  CHECK(SamplerSpec::parse(SamplerSpec::parse("bridge:1e16").name()).sigma == 1e16);
  for (const char* bad : {"bridge:0.1,uniform:1", "bridge:0.1,uniform:-0.1", "bridge:0.1,uniform:", "bridge:0.1,uniform",
                          "bridge:0.1+gaussian:0.1", "uniform,uniform:0.3", "halton,uniform:0.3", "bridge,uniform:0.3",
                          "bridge:0.1,uniform:nan", ",uniform:0.3", "bridge:0.1+uniform:0.3", "bridge:0.1 uniform:0.3"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(SamplerSpec::parse(bad), std::invalid_argument);
  }
  CHECK_THROWS_WITH(SamplerSpec::parse("halton,uniform:0.3"),
                    "sampler 'halton,uniform:0.3': only gaussian:S and bridge:S take a uniform share (S,uniform:W)");
  CHECK_THROWS_WITH(SamplerSpec::parse("gaussian"), "sampler 'gaussian' needs its sigma: gaussian:S, e.g. gaussian:0.05");
}

TEST_CASE("det::log is within an ulp of the C library's and exact where it must be") {
  CHECK(csl::det::log(1.0) == 0.0);
  CHECK(std::isinf(csl::det::log(0.0)));
  CHECK(csl::det::log(0.0) < 0);
  CHECK(std::isnan(csl::det::log(-1.0)));
  CHECK(csl::det::log(2.0) == 0x1.62e42fefa39efp-1);  // ln 2 rounded
  CHECK(csl::det::log(5e-324) == doctest::Approx(-744.44007192138126));
  csl::Rng rng(9);
  for (int i = 0; i < 100000; ++i) {
    // Over many binades: the polar method's s in (0, 1), and beyond.
    const double x = std::ldexp(0.5 + rng.uniform01(), static_cast<int>(rng.below(120)) - 100);
    const double ours = csl::det::log(x), libm = std::log(x);
    REQUIRE(std::fabs(ours - libm) <= std::ldexp(std::fabs(libm), -52));  // 1 ulp (libm's is within 1 too)
  }
}

TEST_CASE("normal deviates have mean 0 and variance 1, and come in the same bits from a seed") {
  csl::Rng rng(4);
  const int n = 200000;
  std::vector<double> z(n);
  csl::normal_deviates(rng, n, z.data());
  double sum = 0, sq = 0, within1 = 0;
  for (double v : z) {
    sum += v;
    sq += v * v;
    within1 += std::fabs(v) < 1.0;
  }
  const double mean = sum / n, var = sq / n - mean * mean;
  CHECK(std::fabs(mean) < 0.01);      // sd of the mean: 1/sqrt(n) = 0.0022
  CHECK(std::fabs(var - 1.0) < 0.02);  // sd of the variance: sqrt(2/n) = 0.0032
  CHECK(within1 / n == doctest::Approx(0.6827).epsilon(0.01));  // P(|Z| < 1)
  csl::Rng again(4);
  double first[3];
  csl::normal_deviates(again, 3, first);
  CHECK(first[0] == z[0]);
  CHECK(first[1] == z[1]);
}

TEST_CASE("Halton points are the radical inverses in bases 2, 3, 5, scaled to the bounds") {
  const double base2[] = {0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875, 0.0625};
  const double base3[] = {1.0 / 3, 2.0 / 3, 1.0 / 9, 4.0 / 9, 7.0 / 9, 2.0 / 9, 5.0 / 9, 8.0 / 9};
  const double base5[] = {0.2, 0.4, 0.6, 0.8, 0.04, 0.24, 0.44, 0.64};
  for (int i = 1; i <= 8; ++i) {
    CAPTURE(i);
    CHECK(csl::radical_inverse(static_cast<std::uint64_t>(i), 2) == base2[i - 1]);
    CHECK(csl::radical_inverse(static_cast<std::uint64_t>(i), 3) == doctest::Approx(base3[i - 1]).epsilon(1e-15));
    CHECK(csl::radical_inverse(static_cast<std::uint64_t>(i), 5) == doctest::Approx(base5[i - 1]).epsilon(1e-15));
  }
  // A box [-1, 3] x [2, 5]: lo + (hi - lo) u.
  const csl::Space box = csl::Space::box({-1, 2}, {3, 5});
  CHECK(csl::halton_point(box, 3)[0] == -1 + 4 * 0.75);
  CHECK(csl::halton_point(box, 3)[1] == doctest::Approx(2 + 3 * (1.0 / 9)));
  // SE(2): the angle over [-pi, pi) in base 5.
  const csl::Space se2 = csl::Space::se2(0, 0, 1, 1, 0.3);
  const csl::Config q = csl::halton_point(se2, 2);
  CHECK(q[0] == 0.25);
  CHECK(q[1] == doctest::Approx(2.0 / 3));
  CHECK(q[2] == doctest::Approx(-csl::kPi + 2 * csl::kPi * 0.4));

  // PRM with halton: its vertices are the free Halton points in order, whatever the seed.
  const csl::CollisionWorld world(csl::PointRobot{}, {csl::Disk{{0.5, 0.5}, 0.2}}, {0, 0}, {1, 1});
  csl::Prm a(world, config({0.05, 0.05}), config({0.95, 0.95}), params(40, "halton", 1));
  csl::Prm b(world, config({0.05, 0.05}), config({0.95, 0.95}), params(40, "halton", 99));
  a.run();
  b.run();
  CHECK(csl::roadmap_hash(a.roadmap()) == csl::roadmap_hash(b.roadmap()));
  std::vector<csl::Config> expected;
  for (int i = 1; i <= 40; ++i) {
    const csl::Config h = config({csl::radical_inverse(static_cast<std::uint64_t>(i), 2),
                                  csl::radical_inverse(static_cast<std::uint64_t>(i), 3)});
    if ((h - config({0.5, 0.5})).norm() > 0.2) expected.push_back(h);
  }
  REQUIRE(a.roadmap().vertices.size() == expected.size() + 2);
  for (std::size_t i = 0; i < expected.size(); ++i) CHECK(a.roadmap().vertices[i + 2] == expected[i]);
}

TEST_CASE("a draw is one sample: its events say what was tested and why it was kept or not") {
  const csl::CollisionWorld world = narrow_passage();
  // The bridge test keeps about 1 draw in 200 here (both ends inside the wall's blocks, on either
  // side of the gap): 3000 draws.
  // (No structured bindings: clang 14, the wasm build's, cannot capture them in CAPTURE's lambda.)
  for (const auto& draws : {std::pair<const char*, int>{"gaussian:0.05", 300}, {"bridge:0.1", 3000}}) {
    const char* s = draws.first;
    const int n = draws.second;
    CAPTURE(s);
    csl::Prm prm(world, config({0.05, 0.5}), config({0.95, 0.5}), params(n, s, 3));
    prm.step();
    prm.step();
    int accepted = 0, rejected_free = 0, rejected_hit = 0;
    while (prm.phase() == csl::PrmPhase::Sampling) {
      const csl::PrmEvent& e = prm.step();
      CHECK(e.sample == prm.samples_drawn());
      if (e.kind == csl::PrmEvent::Kind::SampleAccepted) {
        ++accepted;
        CHECK(world.is_free(e.q));
        CHECK(prm.roadmap().vertices.back() == e.q);
      } else {
        REQUIRE(e.kind == csl::PrmEvent::Kind::SampleRejected);
        if (e.obstacle < 0) {
          ++rejected_free;
          CHECK(world.is_free(e.q));
          // The log says why a free configuration was dropped.
          const std::string text = prm.describe(e, csl::Scene{});
          CHECK(text.find(std::string(s).rfind("bridge", 0) == 0 ? "a bridge end is free" : "its Gaussian partner") !=
                std::string::npos);
        } else {
          ++rejected_hit;
          CHECK_FALSE(world.is_free(e.q));
        }
      }
    }
    CHECK(prm.samples_drawn() == n);  // n counts draws
    CHECK(accepted + rejected_free + rejected_hit == n);
    CHECK(static_cast<int>(prm.roadmap().vertices.size()) == accepted + 2);
    CHECK(accepted > 0);
    CHECK(rejected_free > 0);  // gaussian: both free; bridge: q1 (or q2) free
  }
}

TEST_CASE("each sampler gives the same roadmap in every build (pinned hashes)") {
  const csl::CollisionWorld world = narrow_passage();
  const std::pair<const char*, std::uint64_t> pinned[] = {
      {"uniform", 5341025410249772465ull},
      {"gaussian:0.05", 3798585946714865070ull},
      {"bridge:0.1", 4993253417752152880ull},
      {"halton", 15391366077283307875ull}};
  for (const auto& pin : pinned) {
    const char* sampler = pin.first;
    const std::uint64_t hash = pin.second;
    CAPTURE(sampler);
    const bool bridge = std::string(sampler).rfind("bridge", 0) == 0;
    csl::Prm prm(world, config({0.05, 0.5}), config({0.95, 0.5}), params(bridge ? 3000 : 400, sampler, 11));
    prm.run();
    MESSAGE(sampler, " ", csl::roadmap_hash(prm.roadmap()), " ", prm.roadmap().vertices.size());
    CHECK(prm.roadmap().vertices.size() > 10);
    CHECK(csl::roadmap_hash(prm.roadmap()) == hash);
  }
  // The arm on T^2: angles wrapped, the Gaussian step in radians.
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {csl::Disk{{0.8, 0.8}, 0.1}, csl::Disk{{0.2, 0.4}, 0.08}},
                                {0, 0}, {1, 1});
  csl::Prm g(arm, config({0.0, 0.0}), config({3.0, -1.0}), params(300, "gaussian:0.3", 5));
  g.run();
  CHECK(csl::roadmap_hash(g.roadmap()) == 17618189286057245897ull);
}

TEST_CASE("the bridge test puts a larger share of its samples in a narrow passage than uniform sampling") {
  const csl::CollisionWorld world = narrow_passage();
  const auto share = [&](const std::string& sampler, int n) {
    int inside = 0, total = 0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed)
      for (const csl::Config& q : accepted(world, sampler, n, seed)) {
        inside += in_passage(q);
        ++total;
      }
    MESSAGE(sampler, ": ", inside, " of ", total, " accepted samples in the passage");
    return static_cast<double>(inside) / total;
  };
  // Measured (5 seeds of 2000 draws each): uniform 56 of 7517 accepted samples in the passage
  // (0.74%, its share of the free area: 0.006 / 0.806), bridge:0.1 20 of 54 (37%, 50 times as
  // much; its other midpoints sit at the passage's mouths and between the disks and the wall).
  const double uniform = share("uniform", 2000), bridge = share("bridge:0.1", 2000);
  CHECK(uniform == doctest::Approx(0.006 / 0.806).epsilon(0.25));  // the area ratio, within sampling noise
  CHECK(bridge > 0.2);
  CHECK(bridge > 10 * uniform);
}

TEST_CASE("Gaussian sampling puts a larger share of its samples near obstacles' boundaries than uniform") {
  const csl::CollisionWorld world = narrow_passage();
  const double sigma = 0.03;
  const auto share = [&](const std::string& sampler) {
    int near = 0, total = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed)
      for (const csl::Config& q : accepted(world, sampler, 2000, seed)) {
        near += world.clearance(q) < sigma;
        ++total;
      }
    MESSAGE(sampler, ": ", near, " of ", total, " accepted samples within sigma of an obstacle");
    return static_cast<double>(near) / total;
  };
  // Measured (3 seeds of 2000 draws): uniform 600 of 4515 accepted samples within 0.03 of an
  // obstacle (13%), gaussian:0.03 417 of 517 (81%, 6 times as much).
  const double uniform = share("uniform"), gaussian = share("gaussian:0.03");
  CHECK(uniform < 0.2);
  CHECK(gaussian > 0.6);
  CHECK(gaussian > 3 * uniform);
}

TEST_CASE("the bridge test alone leaves start and goal apart; its hybrid finds the gap with fewer vertices") {
  // The Compare planners lesson's passage narrowed to 0.02 (wall 0.2 thick): start (0.1, 0.8)
  // and goal (0.9, 0.2) are out in the open, and nothing in the gap is in their sight. A bridge
  // alone keeps gap points only, so no vertex joins the two; the hybrid's uniform draws cover the
  // open space, its bridge points the gap. Per vertex kept (what a roadmap costs in edge checks)
  // the hybrid and Gaussian sampling find the passage more often than uniform sampling.
  const csl::CollisionWorld world(csl::narrow_passage_scene(0.02));
  const csl::Config start = config({0.1, 0.8}), goal = config({0.9, 0.2});
  struct Tally {
    int solved = 0;
    double vertices = 0;
  };
  const auto tally = [&](const std::string& sampler, int n) {
    Tally t;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      csl::Prm prm(world, start, goal, params(n, sampler, seed));
      prm.run();
      t.solved += prm.solved();
      t.vertices += static_cast<double>(prm.roadmap().vertices.size()) / 20;
    }
    MESSAGE(sampler, " n=", n, ": solved ", t.solved, " of 20, ", t.vertices, " vertices on average");
    return t;
  };
  // Uniform sampling with as many draws as `t` kept vertices (0.8 of its draws are free): about
  // as large a roadmap.
  const auto uniform_like = [&](const Tally& t) {
    const Tally u = tally("uniform", static_cast<int>(t.vertices / 0.8));
    CHECK(u.vertices == doctest::Approx(t.vertices).epsilon(0.1));
    return u;
  };
  // Measured, 20 seeds of 2000 draws: bridge:0.1 alone 0 solved; bridge:0.1,uniform:0.1 8 of 20
  // with 162 vertices, uniform with as many 2; gaussian:0.05 16 with 170, uniform 2.
  CHECK(tally("bridge:0.1", 2000).solved == 0);
  const Tally hybrid = tally("bridge:0.1,uniform:0.1", 2000);
  CHECK(hybrid.solved >= uniform_like(hybrid).solved + 4);
  const Tally gaussian = tally("gaussian:0.05", 2000);
  CHECK(gaussian.solved >= uniform_like(gaussian).solved + 8);
}
