// The analysis of PRM: the failure bounds of section 2.1 and P8, P9's visibility probability
// (exact, every case, against Monte Carlo), and the Wilson interval.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "core/analysis.hpp"
#include "core/angles.hpp"

using doctest::Approx;

TEST_CASE("unit ball volumes") {
  CHECK(csl::unit_ball_volume(1) == 2.0);
  CHECK(csl::unit_ball_volume(2) == Approx(csl::kPi));
  CHECK(csl::unit_ball_volume(3) == Approx(4.0 / 3.0 * csl::kPi));
  CHECK(csl::unit_ball_volume(4) == Approx(csl::kPi * csl::kPi / 2));
  CHECK(csl::unit_ball_volume(5) == Approx(8.0 / 15.0 * csl::kPi * csl::kPi));
}

TEST_CASE("the path-tiling bound: m = ceil(L/(r/2)), sigma = mu(B1)/(2^d mu(F))") {
  const auto b = csl::path_tiling_bound(1.0, 0.1, 2, 0.9, 1000);
  CHECK(b.balls == 20);
  CHECK(b.sigma == Approx(csl::kPi / (4 * 0.9)));
  CHECK(b.exponent == Approx(csl::kPi / 3.6 * 0.01 * 1000));
  CHECK(b.bound == Approx(20 * std::exp(-csl::kPi / 3.6 * 10)));
  CHECK_FALSE(b.vacuous);
  // Few samples: the bound exceeds 1 and says nothing.
  CHECK(csl::path_tiling_bound(1.0, 0.1, 2, 0.9, 10).vacuous);
  // m is a ceiling: L = 1.01 needs 21 balls.
  CHECK(csl::path_tiling_bound(1.01, 0.1, 2, 0.9, 0).balls == 21);
  // Exponential decay in n: doubling n squares exp(-...).
  const double b1 = csl::path_tiling_bound(2.0, 0.2, 3, 1.0, 500).bound / 20;
  const double b2 = csl::path_tiling_bound(2.0, 0.2, 3, 1.0, 1000).bound / 20;
  CHECK(b2 == Approx(b1 * b1));
  // Samples needed for a 1% bound, and the bound there is 1%.
  const auto need = csl::path_tiling_bound(1.0, 0.1, 2, 0.9, 0).samples_for(0.01);
  CHECK(csl::path_tiling_bound(1.0, 0.1, 2, 0.9, need).bound == Approx(0.01));
  CHECK_THROWS_AS(csl::path_tiling_bound(1.0, 0.0, 2, 1.0, 10), std::invalid_argument);
  CHECK_THROWS_AS(csl::path_tiling_bound(1.0, 0.1, 0, 1.0, 10), std::invalid_argument);
  CHECK_THROWS_AS(csl::path_tiling_bound(std::nan(""), 0.1, 2, 1.0, 10), std::invalid_argument);
}

TEST_CASE("P8: tiling all of [0,1]^d costs ceil(2/r)^d balls") {
  const auto t = csl::whole_space_tiling_bound(0.1, 2, 1000);
  CHECK(t.balls == 400);
  CHECK(t.sigma == Approx(csl::kPi / 4));
  CHECK(t.bound == Approx(400 * std::exp(-csl::kPi / 4 * 0.01 * 1000)));
  // Scaling: the prefactor grows geometrically with d and like r^-d.
  for (int d = 1; d <= 6; ++d) {
    CHECK(csl::whole_space_tiling_bound(0.1, d, 0).balls == Approx(std::pow(20.0, d)));
    CHECK(csl::whole_space_tiling_bound(0.05, d, 0).balls == Approx(std::pow(40.0, d)));
  }
  // A strict covering needs more balls once d > 4 (the grid's cells outgrow the balls).
  CHECK(csl::whole_space_tiling_bound(0.1, 2, 0).covering_balls <= csl::whole_space_tiling_bound(0.1, 2, 0).balls);
  CHECK(csl::whole_space_tiling_bound(0.1, 6, 0).covering_balls > csl::whole_space_tiling_bound(0.1, 6, 0).balls);
  // Reaching 1% costs about (d-1) ln(2/r) / (sigma r^d) more samples than for one path.
  for (int d = 2; d <= 4; ++d) {
    const double extra = csl::whole_space_tiling_bound(0.1, d, 0).samples_for(0.01) -
                         csl::path_tiling_bound(1.0, 0.1, d, 1.0, 0).samples_for(0.01);
    const double rate = csl::whole_space_tiling_bound(0.1, d, 0).rate;
    CHECK(extra == Approx((d - 1) * std::log(20.0) / rate));
  }
  // Compared with the path bound for a path of length 1 in the same cube: same decay in n, a
  // far larger factor in front, increasingly so with d.
  for (int d = 1; d <= 5; ++d) {
    const auto whole = csl::whole_space_tiling_bound(0.1, d, 2000);
    const auto path = csl::path_tiling_bound(1.0, 0.1, d, 1.0, 2000);
    CHECK(whole.sigma == Approx(path.sigma));
    CHECK(whole.bound / path.bound == Approx(std::pow(20.0, d) / 20.0));
  }
}

TEST_CASE("P9: the visibility probability in every case of the cone") {
  // No opening: just the left half.
  CHECK(csl::visibility_probability(0.2, 0.3, 0.0) == Approx(0.5));
  // The wall fully open: the whole square.
  CHECK(csl::visibility_probability(0.2, 0.3, 1.0) == Approx(1.0));
  // Level with a small opening, close to the wall: the cone leaves through the right edge.
  // At x = 1/2 + t the cone spans gap * (1 + t / run): area = gap * (1/2 + 1/8 / run).
  {
    const double x1 = 0.4, gap = 0.1, run = 0.1;
    const double area = gap * (0.5 + 0.125 / run);  // 0.1 * 1.75 = 0.175 < 1: within the square
    CHECK(csl::visibility_probability(x1, 0.5, gap) == Approx(0.5 + area));
  }
  // Right against the wall, level: the cone opens to the full right half (through top and bottom).
  CHECK(csl::visibility_probability(0.4999999, 0.5, 0.2) == Approx(1.0).epsilon(1e-4));
  // From low down, the cone goes up through the top edge: the clipped area is less than the
  // unclipped trapezoid would be.
  {
    const double x1 = 0.3, y1 = 0.05, gap = 0.2;
    const double p = csl::visibility_probability(x1, y1, gap);
    const double run = 0.5 - x1, lo = 0.4, hi = 0.6;
    const double unclipped = 0.5 * (hi - lo) + 0.5 * 0.5 * 0.5 * ((hi - y1) / run - (lo - y1) / run);
    CHECK(p < 0.5 + unclipped);
    CHECK(p > 0.5);
  }
  // Symmetry: mirroring y1 about 1/2 sees the same area.
  CHECK(csl::visibility_probability(0.1, 0.2, 0.15) == Approx(csl::visibility_probability(0.1, 0.8, 0.15)));
  // Far from the wall the cone is narrow; nearer it is wider (same height, level with the gap).
  CHECK(csl::visibility_probability(0.05, 0.5, 0.1) < csl::visibility_probability(0.45, 0.5, 0.1));
  CHECK_THROWS_AS(csl::visibility_probability(0.5, 0.5, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(csl::visibility_probability(0.2, 1.5, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(csl::visibility_probability(0.2, 0.5, -0.1), std::invalid_argument);
}

TEST_CASE("P9: exact probability and Monte Carlo agree within the interval, all over the square") {
  csl::Rng rng(2025);
  int outside = 0, cases = 0;
  for (double x1 : {0.0, 0.1, 0.25, 0.4, 0.49}) {
    for (double y1 : {0.0, 0.05, 0.3, 0.5, 0.7, 0.95, 1.0}) {
      for (double gap : {0.02, 0.1, 0.3, 0.8}) {
        const double exact = csl::visibility_probability(x1, y1, gap);
        const auto mc = csl::visibility_monte_carlo(x1, y1, gap, 20000, rng);
        ++cases;
        outside += exact < mc.low || exact > mc.high;
        // Far outside the 95% interval would be a bug, not chance: 5 standard errors.
        const double se = std::sqrt(exact * (1 - exact) / 20000) + 1e-12;
        REQUIRE(std::fabs(mc.estimate - exact) < 5 * se + 1e-9);
      }
    }
  }
  // About 5% of 95% intervals miss; far more would mean a biased formula.
  CHECK(outside <= cases / 8);
  MESSAGE(outside << " of " << cases << " exact values outside their 95% interval");
}

TEST_CASE("Wilson intervals") {
  const auto p = csl::wilson_interval(50, 100);
  CHECK(p.estimate == 0.5);
  CHECK(p.low == Approx(0.4038).epsilon(1e-3));
  CHECK(p.high == Approx(0.5962).epsilon(1e-3));
  const auto zero = csl::wilson_interval(0, 20);
  CHECK(zero.low == 0.0);
  CHECK(zero.high == Approx(0.1611).epsilon(1e-3));  // not the degenerate [0, 0] of the Wald interval
  CHECK(csl::wilson_interval(0, 0).high == 1.0);
}
