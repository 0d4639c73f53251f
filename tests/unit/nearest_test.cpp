// The k-d tree answers exactly what brute force answers, in the same order, on every kind of
// space: plain boxes, tori (wrap-around) and weighted SE(2).
#include <doctest/doctest.h>

#include "core/nearest.hpp"

using csl::Config;
using csl::Space;

namespace {
void compare_with_brute_force(const Space& space, int n, std::uint64_t seed, bool with_duplicates) {
  csl::Rng rng(seed);
  std::vector<Config> points;
  for (int i = 0; i < n; ++i) {
    // Duplicates and exact ties must come out in index order.
    if (with_duplicates && i > 0 && i % 7 == 0) points.push_back(points[static_cast<std::size_t>(i / 2)]);
    else points.push_back(space.sample(rng));
  }
  csl::NeighborIndex index(space);
  index.build(points);
  std::vector<csl::Neighbor> got;
  for (int trial = 0; trial < 300; ++trial) {
    const bool from_point = trial % 2 == 0;
    const int exclude = from_point ? static_cast<int>(rng.below(static_cast<std::uint64_t>(n))) : -1;
    const Config q = from_point ? points[static_cast<std::size_t>(exclude)] : space.sample(rng);
    for (int k : {1, 5, 10, 41}) {
      index.k_nearest(q, k, exclude, got);
      const auto want = csl::brute_force_k_nearest(space, points, q, k, exclude);
      REQUIRE(got.size() == want.size());
      for (std::size_t i = 0; i < got.size(); ++i) {
        REQUIRE(got[i].index == want[i].index);
        REQUIRE(got[i].squared_distance == want[i].squared_distance);
      }
    }
    const double r = 0.05 + 0.3 * rng.uniform01();
    index.within(q, r, exclude, got);
    auto want = csl::brute_force_k_nearest(space, points, q, n, exclude);
    while (!want.empty() && want.back().squared_distance > r * r) want.pop_back();
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) REQUIRE(got[i].index == want[i].index);
  }
}
}  // namespace

TEST_CASE("k-d tree = brute force on R^2") { compare_with_brute_force(Space::box({0, 0}, {1, 1}), 2000, 1, false); }

TEST_CASE("k-d tree = brute force on the torus T^2, across the seams") {
  compare_with_brute_force(Space::torus(2), 2000, 2, false);
}

TEST_CASE("k-d tree = brute force on weighted SE(2) and on T^3") {
  compare_with_brute_force(Space::se2(0, 0, 2, 1, 0.3), 1500, 3, false);
  compare_with_brute_force(Space::torus(3), 1500, 4, false);
}

TEST_CASE("duplicate points and exact ties come out by index") {
  compare_with_brute_force(Space::box({0, 0}, {1, 1}), 700, 5, true);
  compare_with_brute_force(Space::torus(2), 700, 6, true);
}

TEST_CASE("wrap-around: the nearest point can be on the other side of the chart") {
  const Space t2 = Space::torus(2);
  const std::vector<Config> points = {csl::config({-3.1, 0.0}), csl::config({2.0, 0.0}), csl::config({0.0, 0.0})};
  csl::NeighborIndex index(t2);
  index.build(points);
  std::vector<csl::Neighbor> got;
  index.k_nearest(csl::config({3.1, 0.0}), 1, -1, got);
  REQUIRE(got.size() == 1);
  CHECK(got[0].index == 0);  // 2 pi - 6.2 = 0.083 away across the seam, not 1.1 away
  index.k_nearest(csl::config({3.1, 0.0}), 5, -1, got);
  CHECK(got.size() == 3);  // only three points to give
  index.within(csl::config({0, 0}), 10.0, 2, got);
  CHECK(got.size() == 2);
}

TEST_CASE("an empty index answers nothing") {
  csl::NeighborIndex index(Space::box({0}, {1}));
  index.build({});
  std::vector<csl::Neighbor> got{{1, 1.0}};
  index.k_nearest(csl::config({0.5}), 3, -1, got);
  CHECK(got.empty());
}
