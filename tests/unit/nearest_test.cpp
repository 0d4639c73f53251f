// The k-d tree answers exactly what brute force answers, in the same order, on every kind of
// space: plain boxes, tori (wrap-around) and weighted SE(2); built at once, or grown by
// inserts between queries (the trees, the buffer and their merges are all checked).
#include <doctest/doctest.h>

#include <algorithm>

#include "core/base/rng.hpp"
#include "core/planning/nearest.hpp"

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

namespace {

void require_same(const std::vector<csl::Neighbor>& got, const std::vector<csl::Neighbor>& want) {
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    REQUIRE(got[i].index == want[i].index);
    REQUIRE(got[i].squared_distance == want[i].squared_distance);
  }
}

std::vector<csl::Neighbor> brute_force_within(const Space& space, const std::vector<Config>& points, const Config& q,
                                              double r, int exclude) {
  auto all = csl::brute_force_k_nearest(space, points, q, static_cast<int>(points.size()), exclude);
  while (!all.empty() && all.back().squared_distance > r * r) all.pop_back();
  return all;
}

// A point on a lattice of 8 steps per coordinate (angles pi / 4 apart, in the chart): many
// points at exactly equal distances from a query on the lattice.
Config lattice_point(const Space& space, csl::Rng& rng) {
  Config q(space.dim());
  for (int a = 0; a < space.dim(); ++a) {
    const csl::Coordinate& c = space.coordinate(a);
    const double lo = c.angular ? -csl::kPi : c.lo, hi = c.angular ? csl::kPi : c.hi;
    q[a] = lo + (hi - lo) / 8 * static_cast<double>(rng.below(8));
  }
  return q;
}

// Builds `initial` points, then inserts `inserts` more one by one, each followed (while the
// index is small; then every third insert) by k-nearest and within queries checked against
// brute force over all points so far. Points come uniform, duplicated from earlier ones (built
// or inserted) or on the lattice, so exact ties between the trees and the buffer are common.
void grow_and_compare(const Space& space, int initial, int inserts, std::uint64_t seed) {
  csl::Rng rng(seed);
  const auto next_point = [&](const std::vector<Config>& have) {
    const std::uint64_t kind = rng.below(8);
    if (kind == 0 && !have.empty()) return have[static_cast<std::size_t>(rng.below(have.size()))];
    if (kind == 1) return lattice_point(space, rng);
    return space.sample(rng);
  };
  std::vector<Config> points;
  for (int i = 0; i < initial; ++i) points.push_back(next_point(points));
  csl::NeighborIndex index(space);
  index.build(points);
  std::vector<csl::Neighbor> got;
  for (int step = 0; step < inserts; ++step) {
    const Config p = next_point(points);
    REQUIRE(index.insert(p) == static_cast<int>(points.size()));
    points.push_back(p);
    REQUIRE(index.size() == static_cast<int>(points.size()));
    if (step > 300 && step % 3 != 0) continue;
    const int n = static_cast<int>(points.size());
    for (int trial = 0; trial < 3; ++trial) {
      // From a point (the newest, in the buffer, or any), excluded or not; or from elsewhere.
      const std::uint64_t from = rng.below(4);
      const int at = from == 0 ? n - 1 : static_cast<int>(rng.below(static_cast<std::uint64_t>(n)));
      const Config q = from == 3 ? lattice_point(space, rng) : from == 2 ? space.sample(rng) : points[static_cast<std::size_t>(at)];
      const int exclude = from < 2 && rng.below(4) != 0 ? at : -1;
      for (int k : {1, 4, 17}) {
        index.k_nearest(q, k, exclude, got);
        require_same(got, csl::brute_force_k_nearest(space, points, q, k, exclude));
      }
      const double r = 0.02 + 0.5 * rng.uniform01();
      index.within(q, r, exclude, got);
      require_same(got, brute_force_within(space, points, q, r, exclude));
    }
  }
  // Every index once in leaf_order(), trees and buffer alike.
  std::vector<int> order = index.leaf_order();
  std::sort(order.begin(), order.end());
  REQUIRE(order.size() == points.size());
  for (std::size_t i = 0; i < order.size(); ++i) REQUIRE(order[i] == static_cast<int>(i));
}

}  // namespace

TEST_CASE("inserts between queries = brute force on R^2") {
  grow_and_compare(Space::box({0, 0}, {1, 1}), 0, 1200, 11);
  grow_and_compare(Space::box({-2, 0}, {3, 0.5}), 500, 700, 12);
}

TEST_CASE("inserts between queries = brute force on the flat torus T^2") {
  grow_and_compare(Space::torus(2), 0, 1200, 13);
  grow_and_compare(Space::torus(2), 37, 700, 14);
}

TEST_CASE("inserts between queries = brute force on weighted SE(2)") {
  grow_and_compare(Space::se2(0, 0, 2, 1, 0.3), 0, 900, 15);
  grow_and_compare(Space::se2(-1, -1, 1, 1, 2.5), 300, 600, 16);
}

TEST_CASE("inserts between queries = brute force on general weighted products") {
  grow_and_compare(Space::product(Space::se2(0, 0, 1, 1, 0.7), Space::torus(2)), 100, 700, 17);
  grow_and_compare(Space::product(Space::box({-1, 0, 0}, {1, 2, 0.5}), Space::circle(2.5)), 0, 700, 18);
}

TEST_CASE("insert into an index never built, and build() replaces inserted points") {
  const Space r2 = Space::box({0, 0}, {1, 1});
  csl::NeighborIndex index(r2);
  std::vector<csl::Neighbor> got;
  index.k_nearest(csl::config({0.5, 0.5}), 3, -1, got);
  CHECK(got.empty());
  CHECK(index.insert(csl::config({0.9, 0.9})) == 0);
  CHECK(index.insert(csl::config({0.1, 0.1})) == 1);
  CHECK(index.insert(csl::config({0.1, 0.1})) == 2);  // a duplicate: the tie goes by index
  index.k_nearest(csl::config({0.2, 0.2}), 2, -1, got);
  REQUIRE(got.size() == 2);
  CHECK(got[0].index == 1);
  CHECK(got[1].index == 2);
  index.within(csl::config({0.1, 0.1}), 0.0, 1, got);  // r = 0 is inclusive
  REQUIRE(got.size() == 1);
  CHECK(got[0].index == 2);
  index.build({csl::config({0.5, 0.5})});
  CHECK(index.size() == 1);
  CHECK(index.leaf_order() == std::vector<int>{0});
  CHECK(index.insert(csl::config({0.6, 0.5})) == 1);
  index.k_nearest(csl::config({0.1, 0.1}), 5, -1, got);
  REQUIRE(got.size() == 2);
  CHECK(got[0].index == 0);
  CHECK(got[1].index == 1);
}

TEST_CASE("many inserts: merges across several tree sizes stay exact") {
  // Past a few thousand the buffer has become trees many times over and been merged into
  // larger ones; a query after each of a run of inserts sees every stage of a merge.
  const Space t2 = Space::torus(2);
  csl::Rng rng(19);
  std::vector<Config> points;
  csl::NeighborIndex index(t2);
  std::vector<csl::Neighbor> got;
  for (int i = 0; i < 5000; ++i) {
    points.push_back(t2.sample(rng));
    index.insert(points.back());
    if (i % 97 != 0 && i < 4900) continue;
    const Config q = t2.sample(rng);
    index.k_nearest(q, 25, -1, got);
    require_same(got, csl::brute_force_k_nearest(t2, points, q, 25, -1));
    const int exclude = static_cast<int>(rng.below(points.size()));
    index.within(q, 0.1, exclude, got);
    require_same(got, brute_force_within(t2, points, q, 0.1, exclude));
  }
}
