// Heat-map grids and their level sets (marching squares): exact on linear functions, close to a
// circle for x^2 + y^2, both readings of a saddle, infinite values kept out of the level lines.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/fields/scalar_grid.hpp"

using csl::Vec2;

namespace {

double total_length(const std::vector<csl::LevelSegment>& s) {
  double l = 0.0;
  for (const auto& seg : s) l += (seg.b - seg.a).norm();
  return l;
}

}  // namespace

TEST_CASE("sample_grid: nodes from corner to corner, row by row from the bottom") {
  const auto g = csl::sample_grid(3, 2, Vec2(0, 0), Vec2(1, 2), [](const Vec2& p) { return p.x() + 10 * p.y(); });
  REQUIRE(g.values.size() == 6);
  CHECK(g.value(0, 0) == 0.0);
  CHECK(g.value(1, 0) == 0.5);
  CHECK(g.value(2, 1) == 21.0);
  CHECK(g.node(2, 1) == Vec2(1, 2));
  CHECK_THROWS_AS(csl::sample_grid(1, 5, Vec2(0, 0), Vec2(1, 1), [](const Vec2&) { return 0.0; }), std::invalid_argument);
  CHECK_THROWS_AS(csl::sample_grid(5, 5, Vec2(1, 0), Vec2(1, 1), [](const Vec2&) { return 0.0; }), std::invalid_argument);
}

TEST_CASE("level_set of a linear function is exact: a straight line across the rectangle") {
  const auto g = csl::sample_grid(17, 9, Vec2(0, 0), Vec2(1, 1), [](const Vec2& p) { return p.x(); });
  const auto s = csl::level_set(g, 0.3);
  REQUIRE(!s.empty());
  for (const auto& seg : s) {
    CHECK(seg.a.x() == doctest::Approx(0.3).epsilon(1e-12));
    CHECK(seg.b.x() == doctest::Approx(0.3).epsilon(1e-12));
  }
  CHECK(total_length(s) == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(csl::level_set(g, 2.0).empty());  // nowhere that high
}

TEST_CASE("level_set of x^2 + y^2 follows the circle to within the grid's interpolation error") {
  const int n = 65;
  const auto g = csl::sample_grid(n, n, Vec2(-1, -1), Vec2(1, 1), [](const Vec2& p) { return p.squaredNorm(); });
  const double r = 0.6, h = 2.0 / (n - 1);
  const auto s = csl::level_set(g, r * r);
  for (const auto& seg : s) {
    // Linear interpolation of a quadratic along an edge of length h errs by at most h^2 / 4.
    CHECK(std::fabs(seg.a.norm() - r) <= h * h);
    CHECK(std::fabs(seg.b.norm() - r) <= h * h);
  }
  CHECK(total_length(s) == doctest::Approx(2 * M_PI * r).epsilon(0.01));
}

TEST_CASE("a saddle cell is resolved by its centre") {
  // f = x y on one cell: corners (-1,-1) and (1,1) are +1, the others -1; the centre is 0.
  const auto g = csl::sample_grid(2, 2, Vec2(-1, -1), Vec2(1, 1), [](const Vec2& p) { return p.x() * p.y(); });
  const auto high = csl::level_set(g, 0.5);  // centre below: the level cuts off the two high corners
  REQUIRE(high.size() == 2);
  for (const auto& seg : high) CHECK(seg.a.x() * seg.b.x() > 0);  // each piece stays near one corner
  CHECK(high[0].a.isApprox(Vec2(-1, -0.5)));  // on the left edge, where x y = 0.5 by interpolation
  CHECK(high[0].b.isApprox(Vec2(-0.5, -1)));
  // The other diagonal (mask 10: corners 1 and 3 above), f = -x y: centre 0 is below 0.5, so
  // the level cuts off corners 1 and 3.
  const auto g2 = csl::sample_grid(2, 2, Vec2(-1, -1), Vec2(1, 1), [](const Vec2& p) { return -p.x() * p.y(); });
  const auto other = csl::level_set(g2, 0.5);
  REQUIRE(other.size() == 2);
  CHECK(other[0].a.isApprox(Vec2(0.5, -1)));  // edge 0, near corner 1 = (1, -1)
  CHECK(other[0].b.isApprox(Vec2(1, -0.5)));  // edge 1
  CHECK(other[1].a.isApprox(Vec2(-0.5, 1)));  // edge 2, near corner 3 = (-1, 1)
  CHECK(other[1].b.isApprox(Vec2(-1, 0.5)));  // edge 3
  const auto low = csl::level_set(g, -0.5);  // centre above: it cuts off the two low corners
  REQUIRE(low.size() == 2);
  CHECK(low[0].a.isApprox(Vec2(0.5, -1)));
  CHECK(low[0].b.isApprox(Vec2(1, -0.5)));
}

TEST_CASE("infinite values (inside an obstacle) stop level lines at the last finite node") {
  const double inf = std::numeric_limits<double>::infinity();
  const auto f = [&](const Vec2& p) { return p.norm() <= 0.3 ? inf : 1.0 / p.norm(); };
  const auto g = csl::sample_grid(41, 41, Vec2(-1, -1), Vec2(1, 1), f);
  for (double level : {2.0, 3.0, 3.3}) {
    const auto segs = csl::level_set(g, level);
    REQUIRE(!segs.empty());
    for (const auto& seg : segs) {
      CHECK(seg.a.allFinite());
      CHECK(seg.b.allFinite());
      CHECK(seg.a.norm() > 0.3 - 1e-12);
      CHECK(seg.b.norm() > 0.3 - 1e-12);
    }
  }
  const auto levels = csl::contour_levels(g, 5);
  REQUIRE(levels.size() == 5);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    CHECK(std::isfinite(levels[i]));
    if (i > 0) CHECK(levels[i] > levels[i - 1]);
  }
  CHECK(levels.front() > 1.0 / std::sqrt(2.0));  // above the finite minimum, at the corners
  const auto flat = csl::sample_grid(3, 3, Vec2(0, 0), Vec2(1, 1), [](const Vec2&) { return 1.0; });
  CHECK(csl::contour_levels(flat, 4).empty());
}
