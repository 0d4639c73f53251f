// Configuration spaces: notation, wrap-around distance and interpolation, sampling, volume.
#include <limits>
#include <doctest/doctest.h>

#include <cmath>

#include "core/base/angles.hpp"
#include "core/spaces/space.hpp"

using csl::config;
using csl::kPi;
using csl::Space;

TEST_CASE("spaces are written in the homework's notation") {
  CHECK(Space::box({0, 0}, {1, 1}).notation() == "R^2");
  CHECK(Space::box({0}, {1}).notation() == "R");
  CHECK(Space::circle().notation() == "S^1");
  CHECK(Space::torus(1).notation() == "S^1");
  CHECK(Space::torus(3).notation() == "T^3");
  CHECK(Space::se2(0, 0, 1, 1, 1.0).notation() == "SE(2)");
  const Space s = Space::product(Space::se2(0, 0, 1, 1, 1.0), Space::torus(6));
  CHECK(s.notation() == "SE(2) x T^6");
  CHECK(s.dim() == 9);
}

TEST_CASE("wrap_angle maps into [-pi, pi) and keeps angles already there") {
  CHECK(csl::wrap_angle(0.5) == 0.5);
  CHECK(csl::wrap_angle(-kPi) == -kPi);
  CHECK(csl::wrap_angle(kPi) == -kPi);
  CHECK(csl::wrap_angle(3 * kPi / 2) == doctest::Approx(-kPi / 2).epsilon(1e-15));
  CHECK(csl::wrap_angle(-7 * kPi / 2) == doctest::Approx(kPi / 2).epsilon(1e-15));
  CHECK(csl::wrap_angle(1000.0) == doctest::Approx(1000.0 - 159 * csl::kTwoPi).epsilon(1e-13));
  csl::Rng rng(5);
  for (int i = 0; i < 10000; ++i) {
    const double a = rng.uniform(-1e4, 1e4);
    const double w = csl::wrap_angle(a);
    REQUIRE(w >= -kPi);
    REQUIRE(w < kPi);
    // Same direction: the difference is a whole number of turns.
    const double turns = (a - w) / csl::kTwoPi;
    REQUIRE(std::fabs(turns - std::round(turns)) < 1e-9);
  }
}

TEST_CASE("S^1 distance is the shorter way round") {
  CHECK(csl::s1_distance(0.1, 0.4) == doctest::Approx(0.3));
  CHECK(csl::s1_distance(3.0, -3.0) == doctest::Approx(csl::kTwoPi - 6.0));
  CHECK(csl::s1_distance(-kPi / 2, kPi / 2) == doctest::Approx(kPi));
  CHECK(csl::s1_distance(1.0, 1.0 + 4 * kPi) == doctest::Approx(0.0).epsilon(1e-12));
}

TEST_CASE("on the torus, distances and interpolation go across the seam") {
  const Space t2 = Space::torus(2);
  const auto p = config({3.0, -3.0}), q = config({-3.0, 3.0});
  const double gap = csl::kTwoPi - 6.0;  // each coordinate is this close across the seam
  CHECK(t2.distance(p, q) == doctest::Approx(std::sqrt(2.0) * gap));
  const auto mid = t2.interpolate(p, q, 0.5);
  // Halfway across the seam at +-pi, not through the middle of the square.
  CHECK(std::fabs(std::fabs(mid[0]) - kPi) < 1e-12);
  CHECK(std::fabs(std::fabs(mid[1]) - kPi) < 1e-12);
  CHECK(t2.interpolate(p, q, 0.0) == p);
  CHECK((t2.interpolate(p, q, 1.0) - q).norm() < 1e-15);
}

TEST_CASE("boxes are plain Euclidean; interpolation is a straight line") {
  const Space r2 = Space::box({0, 0}, {1, 1});
  CHECK(r2.distance(config({0, 0}), config({0.3, 0.4})) == doctest::Approx(0.5));
  CHECK(r2.interpolate(config({0, 0}), config({1, 0.5}), 0.25) == config({0.25, 0.125}));
  CHECK(r2.volume() == 1.0);
  CHECK(r2.contains(config({0.5, 1.0})));
  CHECK_FALSE(r2.contains(config({1.5, 0.5})));
  CHECK_FALSE(r2.contains(config({0.5, std::numeric_limits<double>::quiet_NaN()})));
  CHECK_FALSE(r2.contains(config({0.5})));
}

TEST_CASE("SE(2) weighs the angle and wraps it") {
  const Space se2 = Space::se2(0, 0, 2, 1, 0.5);
  const auto p = config({0, 0, 3.0}), q = config({0, 0, -3.0});
  CHECK(se2.distance(p, q) == doctest::Approx(0.5 * (csl::kTwoPi - 6.0)));
  CHECK(se2.volume() == doctest::Approx(2.0 * 1.0 * csl::kTwoPi * 0.5));
  CHECK(se2.difference(p, q)[2] == doctest::Approx(csl::kTwoPi - 6.0));
}

TEST_CASE("the metric is a metric: symmetric, zero on the diagonal, triangle inequality") {
  const Space s = Space::product(Space::se2(0, 0, 1, 1, 0.3), Space::torus(2));
  csl::Rng rng(11);
  for (int i = 0; i < 2000; ++i) {
    const auto a = s.sample(rng), b = s.sample(rng), c = s.sample(rng);
    REQUIRE(s.distance(a, a) == 0.0);
    REQUIRE(s.distance(a, b) == doctest::Approx(s.distance(b, a)).epsilon(1e-14));
    REQUIRE(s.distance(a, c) <= s.distance(a, b) + s.distance(b, c) + 1e-12);
    // Interpolation travels along a shortest path: distances add up along it.
    const double t = rng.uniform01();
    const auto m = s.interpolate(a, b, t);
    REQUIRE(s.distance(a, m) == doctest::Approx(t * s.distance(a, b)).epsilon(1e-9));
    REQUIRE(s.distance(m, b) == doctest::Approx((1 - t) * s.distance(a, b)).epsilon(1e-9));
  }
}

TEST_CASE("samples are uniform in the space and inside it") {
  const Space s = Space::product(Space::box({-1}, {3}), Space::circle());
  csl::Rng rng(3);
  int left = 0, upper_angle = 0;
  constexpr int kN = 40000;
  for (int i = 0; i < kN; ++i) {
    const auto q = s.sample(rng);
    REQUIRE(s.contains(q));
    REQUIRE(q[1] >= -kPi);
    REQUIRE(q[1] < kPi);
    left += q[0] < 1.0;
    upper_angle += q[1] > 0.0;
  }
  // Binomial(40000, 1/2): sd = 100; 5 sd.
  CHECK(std::abs(left - kN / 2) < 500);
  CHECK(std::abs(upper_angle - kN / 2) < 500);
}

TEST_CASE("bad space constructions are refused") {
  CHECK_THROWS_AS(Space::box({1}, {0}), std::invalid_argument);
  CHECK_THROWS_AS(Space::torus(0), std::invalid_argument);
  CHECK_THROWS_AS(Space::product(Space::torus(5), Space::torus(5)), std::invalid_argument);
}

TEST_CASE("P10: the S^1 distance by modulus and by rotation matrices agree") {
  CHECK(csl::s1_distance_rotation(0.1, 0.4) == doctest::Approx(0.3).epsilon(1e-14));
  CHECK(csl::s1_distance_rotation(3.0, -3.0) == doctest::Approx(csl::kTwoPi - 6.0).epsilon(1e-12));
  CHECK(csl::s1_distance_rotation(0.0, kPi) == doctest::Approx(kPi).epsilon(1e-15));
  csl::Rng rng(10);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double a = rng.uniform(-20, 20), b = rng.uniform(-20, 20);
    worst = std::fmax(worst, std::fabs(csl::s1_distance(a, b) - csl::s1_distance_rotation(a, b)));
  }
  // Both are exact up to rounding in the arguments' reduction (|angles| <= 20).
  CHECK(worst < 1e-13);
}
