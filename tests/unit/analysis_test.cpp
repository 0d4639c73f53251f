// The analysis of PRM: the failure bounds of section 2.1 and P8, P9's visibility probability
// (exact, every case, against Monte Carlo), and the Wilson interval.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/base/angles.hpp"
#include "core/teaching/analysis.hpp"

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
  // ... of L / (r/2) as the decimals typed mean it: 0.07 / 0.01 is 7.000000000000001 in binary.
  CHECK(0.07 / (0.02 / 2) > 7.0);
  CHECK(csl::path_tiling_bound(0.07, 0.02, 2, 1.0, 0).balls == 7);
  CHECK(csl::path_tiling_bound(0.27, 0.18, 2, 1.0, 0).balls == 3);
  CHECK(csl::path_tiling_bound(0.0700001, 0.02, 2, 1.0, 0).balls == 8);
  // More balls than a double holds: an error, not a bound of infinity said to be not vacuous.
  CHECK_THROWS_AS(csl::path_tiling_bound(1e308, 1e-300, 1, 1.0, 1e303), std::invalid_argument);
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

namespace {
// Volume of {x in [0,1]^d : |x - c| <= rho}, d = 1 or 2: exact in 1-D, by a fine midpoint
// rule over x in 2-D (the chord at each x is exact).
double inside_volume(int d, const double* c, double rho) {
  if (d == 1) return std::min(1.0, c[0] + rho) - std::max(0.0, c[0] - rho);
  const int steps = 20000;
  double area = 0;
  for (int i = 0; i < steps; ++i) {
    const double x = (i + 0.5) / steps, dx = x - c[0];
    if (std::fabs(dx) >= rho) continue;
    const double h = std::sqrt(rho * rho - dx * dx);
    area += std::max(0.0, std::min(1.0, c[1] + h) - std::max(0.0, c[1] - h)) / steps;
  }
  return area;
}
// Prob(some ball of the P8 grid gets no sample) <= the union over the balls of their exact
// (1 - mu(B_i cap F))^n: the sharpest union bound, which a sound failure bound must not undercut.
double exact_union(int d, double r, double n) {
  const int per_axis = static_cast<int>(std::ceil(std::max(2.0, std::sqrt(d)) / r));
  double sum = 0;
  for (int i = 0; i < per_axis; ++i)
    for (int j = 0; j < (d == 2 ? per_axis : 1); ++j) {
      const double c[2] = {(i + 0.5) / per_axis, (j + 0.5) / per_axis};
      sum += std::pow(1.0 - inside_volume(d, c, r / 2), n);
    }
  return sum;
}
}  // namespace

TEST_CASE("P8: tiling all of [0,1]^d, boundary balls included") {
  const auto t = csl::whole_space_tiling_bound(0.1, 2, 1000);
  CHECK(t.balls == 400);
  CHECK(t.per_axis == 20);
  CHECK(t.sigma == Approx(csl::kPi / 4));
  CHECK(t.interior_bound == Approx(400 * std::exp(-csl::kPi / 4 * 0.01 * 1000)));
  // Centres at (i + 1/2) / 20: the first and last of each axis are within r/2 = 0.05 of a face.
  CHECK(t.edge_per_axis == 2);
  CHECK(t.boundary_balls == 400 - 18 * 18);
  const double e = csl::kPi / 4 * 0.01 * 1000;
  CHECK(t.bound == Approx(18 * 18 * std::exp(-e) + 2 * 2 * 18 * std::exp(-e / 2) + 4 * std::exp(-e / 4)));
  // The counts: ceil(2/r) per axis up to d = 4, then ceil(sqrt(d)/r), so that the balls cover
  // every point (the cells' half-diagonal within r/2) and neighbours stay r/2 apart.
  for (int d = 1; d <= 4; ++d) {
    CHECK(csl::whole_space_tiling_bound(0.1, d, 0).balls == Approx(std::pow(20.0, d)));
    CHECK(csl::whole_space_tiling_bound(0.05, d, 0).balls == Approx(std::pow(40.0, d)));
  }
  CHECK(csl::whole_space_tiling_bound(0.1, 6, 0).per_axis == 25);
  CHECK(csl::whole_space_tiling_bound(0.1, 6, 0).balls == csl::whole_space_tiling_bound(0.1, 6, 0).covering_balls);
  for (int d = 1; d <= 8; ++d) {
    const auto w = csl::whole_space_tiling_bound(0.1, d, 0);
    CHECK(std::sqrt(d) / (2 * w.per_axis) <= 0.05 + 1e-15);  // covered
    CHECK(1 / w.per_axis <= 0.05 + 1e-15);                   // neighbours r/2 apart
  }
  // Sound: never below the exact union bound, which the interior bound (the path argument's
  // step taken as is) undercuts by orders of magnitude at the faces.
  for (double r : {0.5, 0.3, 0.1})
    for (double n : {10.0, 100.0, 1000.0, 10000.0}) {
      const double exact1 = exact_union(1, r, n), exact2 = exact_union(2, r, n);
      CHECK(csl::whole_space_tiling_bound(r, 1, n).bound >= exact1 * (1 - 1e-9));
      CHECK(csl::whole_space_tiling_bound(r, 2, n).bound >= exact2 * (1 - 1e-6));
    }
  CHECK(csl::whole_space_tiling_bound(0.5, 1, 100).interior_bound < exact_union(1, 0.5, 100) / 5);
  CHECK(csl::whole_space_tiling_bound(0.1, 2, 10000).interior_bound < exact_union(2, 0.1, 10000) * 1e-9);
  // A clearance beyond the cube: the balls are counted at radius 1/2.
  const auto big = csl::whole_space_tiling_bound(3.0, 2, 50);
  CHECK(big.balls == 1);
  CHECK(big.bound >= std::pow(1.0 - csl::kPi / 4, 50));
  // Samples for a 1% bound, and the bound there is 1%; more than for the interior bound alone.
  for (int d = 1; d <= 5; ++d) {
    const auto w = csl::whole_space_tiling_bound(0.1, d, 0);
    const double need = w.samples_for(0.01);
    CHECK(w.bound_at(need) == Approx(0.01).epsilon(1e-6));
    CHECK(need > csl::FailureBound::samples_to_reach(w.balls, w.rate, 0.01));
    // ... and far more than for one path of length 1 in the same cube, increasingly with d.
    const double path = csl::path_tiling_bound(1.0, 0.1, d, 1.0, 0).samples_for(0.01);
    CHECK(need >= path);
    if (d > 1) CHECK(need / path > csl::whole_space_tiling_bound(0.1, d - 1, 0).samples_for(0.01) /
                                       csl::path_tiling_bound(1.0, 0.1, d - 1, 1.0, 0).samples_for(0.01));
  }
  CHECK_THROWS_AS(csl::whole_space_tiling_bound(1e-10, 64, 10), std::invalid_argument);  // > 1e308 balls
  CHECK_THROWS_AS(csl::whole_space_tiling_bound(0.1, 2, -1), std::invalid_argument);
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

TEST_CASE("P8 as the handout has it: m = N^d balls in the path bound, and the n it needs") {
  // r = 0.042 in the plane (about the wall-gap scene's clearance): N = ceil(2 / 0.042) = 48.
  const auto t = csl::whole_space_tiling_bound(0.042, 2, 1000);
  CHECK(t.per_axis == 48);
  CHECK(t.balls == 48 * 48);
  const double rate = csl::kPi / 4 * 0.042 * 0.042;
  CHECK(t.rate == Approx(rate).epsilon(1e-14));
  CHECK(t.interior_bound_at(1000) == Approx(2304 * std::exp(-rate * 1000)).epsilon(1e-13));
  CHECK(t.interior_bound_at(1000) == t.interior_bound);
  // n = ln(m / p) / (sigma r^d), solved by hand, and the bound there is p.
  for (double p : {0.5, 0.01, 1e-6}) {
    const double n = t.interior_samples_for(p);
    CHECK(n == Approx(std::log(2304 / p) / rate).epsilon(1e-13));
    CHECK(t.interior_bound_at(n) == Approx(p).epsilon(1e-12));
    // The refined bound counts the faces' balls as hit less often: it needs more samples.
    CHECK(t.samples_for(p) > n);
  }
  CHECK_THROWS_AS(t.interior_samples_for(0.0), std::invalid_argument);
  CHECK_THROWS_AS(t.interior_samples_for(1.0), std::invalid_argument);
}

namespace {
// P9's oracle, written apart from analysis.cpp: the right half [1/2, 1] x [0, 1] as a polygon,
// clipped (Sutherland-Hodgman) to the wedge between the two lines from (x1, y1) through the
// opening's ends, in implicit form (no slopes); the shoelace area of what is left.
using Pt = std::array<double, 2>;
std::vector<Pt> clip(const std::vector<Pt>& poly, Pt from, Pt through, double keep_sign) {
  // side(v) > 0 on the kept side of the line from `from` through `through`.
  const auto side = [&](const Pt& v) {
    return keep_sign * ((through[0] - from[0]) * (v[1] - from[1]) - (through[1] - from[1]) * (v[0] - from[0]));
  };
  std::vector<Pt> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Pt a = poly[i], b = poly[(i + 1) % poly.size()];
    const double sa = side(a), sb = side(b);
    if (sa >= 0) out.push_back(a);
    if ((sa > 0 && sb < 0) || (sa < 0 && sb > 0)) {
      const double u = sa / (sa - sb);
      out.push_back({a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])});
    }
  }
  return out;
}
double polygon_area(const std::vector<Pt>& poly) {
  double twice = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Pt a = poly[i], b = poly[(i + 1) % poly.size()];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return std::fabs(twice) / 2;
}
double p9_oracle(double x1, double y1, double gap) {
  std::vector<Pt> right = {{0.5, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.5, 1.0}};
  const Pt eye{x1, y1};
  // Below the line through the top of the opening (clockwise of it, seen from the eye), above
  // the one through its bottom.
  right = clip(right, eye, {0.5, 0.5 + gap / 2}, -1.0);
  right = clip(right, eye, {0.5, 0.5 - gap / 2}, +1.0);
  return 0.5 + polygon_area(right);
}
// A coarse second opinion, by counting: cell centres of a k x k grid over the right half seen
// through the opening (the segment crosses x = 1/2 within it).
double p9_grid_count(double x1, double y1, double gap, int k) {
  long seen = 0;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const double x2 = 0.5 + (i + 0.5) / (2.0 * k), y2 = (j + 0.5) / k;
      const double y = y1 + (y2 - y1) * (0.5 - x1) / (x2 - x1);
      seen += std::fabs(y - 0.5) <= gap / 2;
    }
  return 0.5 + 0.5 * static_cast<double>(seen) / (static_cast<double>(k) * k);
}
}  // namespace

TEST_CASE("P9 by cases: the rays' exits and areas, against polygon clipping, every case") {
  // By hand: from (0.3, 0.2) through a gap of 0.2 (0.4 to 0.6), run 0.2: the upper ray has
  // slope 2 and leaves through the top at x = 0.7; the lower slope 1, the right edge at 0.9.
  {
    const auto b = csl::p9_breakdown(0.3, 0.2, 0.2);
    CHECK(b.case_name == "top/right edge");
    CHECK(b.upper.exit == csl::P9Ray::Exit::Top);
    CHECK(b.upper.slope == Approx(2.0));
    CHECK(b.upper.exit_x == Approx(0.7));
    CHECK(b.upper.area_under == Approx(0.5 - 0.16 / 4));  // 1/2 - (1 - 0.6)^2 / (2 * 2)
    CHECK(b.lower.exit == csl::P9Ray::Exit::Right);
    CHECK(b.lower.exit_y == Approx(0.9));
    CHECK(b.lower.area_under == Approx((0.4 + 0.9) / 4));
    CHECK(b.probability == Approx(0.5 + 0.46 - 0.325));
  }
  // Level with the opening, near the wall: both rays leave at once, the upper through the top,
  // the lower through the bottom.
  CHECK(csl::p9_breakdown(0.45, 0.5, 0.2).case_name == "top/bottom");
  // High up: both fall through the bottom; the lower one's triangle a^2 / (2|s|).
  {
    const auto b = csl::p9_breakdown(0.45, 0.95, 0.1);
    CHECK(b.case_name == "bottom/bottom");
    CHECK(b.lower.area_under == Approx(0.45 * 0.45 / (2 * 10.0)));
  }
  CHECK(csl::p9_breakdown(0.1, 0.5, 0.1).case_name == "right edge/right edge");
  CHECK(csl::p9_exit_name(csl::P9Ray::Exit::Right) == std::string("right edge"));
  CHECK_THROWS_AS(csl::p9_breakdown(0.5, 0.5, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(csl::p9_breakdown(0.2, 0.5, 1.5), std::invalid_argument);

  // Random points and gaps, many near the wall and with small gaps so that every pair of
  // exits comes up: the breakdown is the oracle's area and visibility_probability().
  csl::Rng rng(99);
  std::map<std::string, int> seen;
  for (int i = 0; i < 20000; ++i) {
    const double x1 = i % 3 == 0 ? 0.5 - std::pow(rng.uniform01(), 3) * 0.5 : rng.uniform(0.0, 0.5);
    if (!(x1 < 0.5)) continue;
    const double y1 = rng.uniform01(), gap = i % 2 ? rng.uniform01() : std::pow(rng.uniform01(), 3);
    const auto b = csl::p9_breakdown(x1, y1, gap);
    CAPTURE(x1);
    CAPTURE(y1);
    CAPTURE(gap);
    REQUIRE(std::fabs(b.probability - csl::visibility_probability(x1, y1, gap)) <= 1e-12);
    REQUIRE(std::fabs(b.probability - p9_oracle(x1, y1, gap)) <= 1e-12);
    REQUIRE(b.probability == Approx(b.left_area + b.upper.area_under - b.lower.area_under));
    // Each ray's exit lies on the edge its case names, on its line.
    for (const auto* r : {&b.upper, &b.lower}) {
      REQUIRE(r->exit_x >= 0.5 - 1e-12);
      REQUIRE(r->exit_x <= 1.0 + 1e-12);
      REQUIRE(std::fabs(r->exit_y - (r->start + r->slope * (r->exit_x - 0.5))) <= 1e-9 * (1 + std::fabs(r->slope)));
      if (r->exit == csl::P9Ray::Exit::Top) REQUIRE(r->exit_y == 1.0);
      if (r->exit == csl::P9Ray::Exit::Bottom) REQUIRE(r->exit_y == 0.0);
      if (r->exit == csl::P9Ray::Exit::Right) REQUIRE(r->exit_x == 1.0);
    }
    ++seen[b.case_name];
  }
  // The six pairs that can happen (the upper ray is never below the lower one).
  for (const char* c : {"top/top", "top/right edge", "top/bottom", "right edge/right edge", "right edge/bottom",
                        "bottom/bottom"}) {
    CAPTURE(c);
    CHECK(seen[c] > 200);
  }
  CHECK(seen.size() == 6);
  // And the counting oracle, coarser, on a few of them.
  for (const std::array<double, 3>& c : {std::array<double, 3>{0.3, 0.2, 0.2}, {0.45, 0.5, 0.2}, {0.45, 0.95, 0.1},
                                        {0.1, 0.5, 0.1}, {0.25, 0.3, 0.1}, {0.05, 0.02, 0.6}}) {
    CAPTURE(c[0]);  // clang 14 cannot capture a structured binding in CAPTURE's lambda
    CHECK(std::fabs(csl::p9_breakdown(c[0], c[1], c[2]).probability - p9_grid_count(c[0], c[1], c[2], 1500)) < 2e-3);
  }
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
