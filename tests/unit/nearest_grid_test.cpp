// all_k_nearest (the grid for R^2 and T^2, the k-d tree elsewhere) answers, for every point,
// exactly what brute force answers, in the same order, on the point sets a grid finds hard:
// clusters, duplicates, a line, a thin box, points on the torus's seams, tiny sets; and
// mark_pairs_seen picks each pair of its rows once.
#include <doctest/doctest.h>

#include <set>

#include "core/planning/nearest_grid.hpp"

using csl::Config;
using csl::Space;

namespace {

// mark_pairs_seen against its definition: an entry q < p of row p is seen iff q's row holds p;
// the unseen entries are the distinct pairs of all rows, once each. (The point sets below are
// full of exact ties, where the float comparison cannot decide and the rows are searched.)
void require_pairs_marked(const std::vector<csl::NearNeighbor>& rows, int k) {
  std::vector<unsigned char> seen;
  const std::size_t pairs = csl::mark_pairs_seen(rows, k, seen);
  REQUIRE(seen.size() == rows.size());
  const auto uk = static_cast<std::size_t>(k);
  std::set<std::pair<int, int>> all, unseen;
  for (std::size_t p = 0; p < rows.size() / uk; ++p)
    for (std::size_t i = 0; i < uk; ++i) {
      const int q = rows[p * uk + i].index;
      if (q < 0) {
        REQUIRE(seen[p * uk + i] == 0);
        continue;
      }
      bool in_theirs = false;
      for (std::size_t j = 0; j < uk; ++j) in_theirs = in_theirs || rows[static_cast<std::size_t>(q) * uk + j].index == static_cast<int>(p);
      REQUIRE(seen[p * uk + i] == ((static_cast<std::size_t>(q) < p && in_theirs) ? 1 : 0));
      const std::pair<int, int> pair{std::min<int>(q, static_cast<int>(p)), std::max<int>(q, static_cast<int>(p))};
      all.insert(pair);
      if (!seen[p * uk + i]) REQUIRE(unseen.insert(pair).second);
    }
  CHECK(unseen == all);
  CHECK(pairs == all.size());
}

void require_brute_force(const Space& space, const std::vector<Config>& points, int k) {
  std::vector<csl::NearNeighbor> got;
  csl::all_k_nearest(space, points, k, got);
  REQUIRE(got.size() == points.size() * static_cast<std::size_t>(k));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto want = csl::brute_force_k_nearest(space, points, points[i], k, static_cast<int>(i));
    const csl::NearNeighbor* row = &got[i * static_cast<std::size_t>(k)];
    for (std::size_t j = 0; j < static_cast<std::size_t>(k); ++j) {
      if (j < want.size()) {
        REQUIRE(row[j].index == want[j].index);
        REQUIRE(row[j].squared_distance == static_cast<float>(want[j].squared_distance));
      } else {
        REQUIRE(row[j].index == -1);  // fewer points than k: padded
      }
    }
  }
  require_pairs_marked(got, k);
}

std::vector<Config> uniform(const Space& space, int n, std::uint64_t seed) {
  csl::Rng rng(seed);
  std::vector<Config> points;
  for (int i = 0; i < n; ++i) points.push_back(space.sample(rng));
  return points;
}

}  // namespace

TEST_CASE("all_k_nearest = brute force on uniform points in R^2 and T^2") {
  for (int k : {1, 10, 27}) {
    require_brute_force(Space::box({0, 0}, {1, 1}), uniform(Space::box({0, 0}, {1, 1}), 1500, 1), k);
    require_brute_force(Space::box({-5, 2}, {7, 2.5}), uniform(Space::box({-5, 2}, {7, 2.5}), 900, 2), k);
    require_brute_force(Space::torus(2), uniform(Space::torus(2), 1500, 3), k);
  }
}

TEST_CASE("all_k_nearest: clusters, duplicates and exact ties come out by index") {
  csl::Rng rng(4);
  std::vector<Config> points;
  for (int i = 0; i < 800; ++i) {
    if (i % 5 == 0 && i > 0) {
      points.push_back(points[static_cast<std::size_t>(rng.below(points.size()))]);  // a duplicate
    } else if (i % 3 == 0) {
      points.push_back(csl::config({0.5 + 1e-3 * rng.uniform01(), 0.5 + 1e-3 * rng.uniform01()}));  // a cluster
    } else {
      // On a lattice: many exactly equal distances.
      points.push_back(csl::config({0.125 * static_cast<double>(rng.below(9)), 0.125 * static_cast<double>(rng.below(9))}));
    }
  }
  require_brute_force(Space::box({0, 0}, {1, 1}), points, 10);
  std::vector<Config> angles;
  for (const Config& q : points) angles.push_back(csl::config({q[0] * 6.0 - csl::kPi, q[1] * 6.0 - csl::kPi}));
  require_brute_force(Space::torus(2), angles, 10);
}

TEST_CASE("all_k_nearest: degenerate boxes (one point, a line, a thin strip, all equal)") {
  const Space box = Space::box({0, 0}, {1, 1});
  require_brute_force(box, {csl::config({0.3, 0.3})}, 5);
  std::vector<Config> line, strip, same(40, csl::config({0.25, 0.75}));
  csl::Rng rng(5);
  for (int i = 0; i < 300; ++i) {
    line.push_back(csl::config({rng.uniform01(), 0.5}));
    strip.push_back(csl::config({rng.uniform01(), 0.5 + 1e-9 * rng.uniform01()}));
  }
  require_brute_force(box, line, 10);
  require_brute_force(box, strip, 10);
  require_brute_force(box, same, 10);
  // Distances whose squares (1e-44 to 4e-42) are below a float's normal range: the rows compare
  // by search. (Near the origin: at 0.5 such offsets would vanish in the double.)
  std::vector<Config> tiny;
  for (int i = 0; i < 200; ++i) tiny.push_back(csl::config({1e-22 * (i % 17), 1e-22 * (i / 17)}));
  require_brute_force(box, tiny, 10);
  // A dense cluster and two far corners: the grid hands over to the tree, same answers.
  std::vector<Config> cluster = {csl::config({0, 0}), csl::config({1, 1})};
  for (int i = 0; i < 500; ++i) cluster.push_back(csl::config({0.5 + 1e-6 * rng.uniform01(), 0.5 + 1e-6 * rng.uniform01()}));
  require_brute_force(box, cluster, 10);
  require_brute_force(box, uniform(box, 7, 6), 10);  // fewer than k + 1
  require_brute_force(box, {}, 10);
  // The torus's smallest grids (3 x 3 cells, and 5 x 5): each cell visited once, none missed.
  require_brute_force(Space::torus(2), uniform(Space::torus(2), 7, 10), 10);
  require_brute_force(Space::torus(2), uniform(Space::torus(2), 17, 11), 20);
  require_brute_force(Space::torus(2), uniform(Space::torus(2), 40, 12), 39);
}

TEST_CASE("all_k_nearest on T^2: neighbours across the seams and on them") {
  std::vector<Config> points;
  csl::Rng rng(7);
  for (int i = 0; i < 600; ++i) {
    // Crowded near the chart's edges -pi and (just below) pi, and on the edges themselves.
    const double a = (i % 2 ? -csl::kPi : csl::kPi - 1e-3) + 1e-3 * rng.uniform01();
    const double b = i % 7 == 0 ? -csl::kPi : rng.uniform(-csl::kPi, csl::kPi);
    points.push_back(i % 3 ? csl::config({a, b}) : csl::config({b, a}));
  }
  require_brute_force(Space::torus(2), points, 10);
}

TEST_CASE("all_k_nearest in other spaces (the k-d tree) = brute force") {
  require_brute_force(Space::se2(0, 0, 2, 1, 0.3), uniform(Space::se2(0, 0, 2, 1, 0.3), 600, 8), 10);
  require_brute_force(Space::torus(3), uniform(Space::torus(3), 600, 9), 10);
}

TEST_CASE("all_k_nearest: the grid selects most rows, and searches those its ranks cannot order") {
  // Both ways give the rows above; this checks which one runs. On uniform points the selection
  // among the points within a radius answers (nearly) every row, in the plane and on the torus.
  for (const Space& space : {Space::box({0, 0}, {1, 1}), Space::torus(2)}) {
    const std::vector<Config> points = uniform(space, 3000, 21);
    csl::KNearestStats stats;
    std::vector<csl::NearNeighbor> rows;
    csl::all_k_nearest(space, points, 10, rows, &stats);
    CHECK(stats.selected + stats.searched == points.size());
    CHECK(stats.selected >= 2990);
    // Every point twice: the neighbours come in pairs at equal distances, which ranks by float
    // cannot order by index, so every row is searched (and still equals brute force).
    std::vector<Config> twice = points;
    twice.resize(1000);
    twice.insert(twice.end(), twice.begin(), twice.end());
    csl::all_k_nearest(space, twice, 10, rows, &stats);
    CHECK(stats.selected == 0);
    CHECK(stats.searched == twice.size());
    require_brute_force(space, twice, 10);
  }
  // The ranks' 64 bits hold the query point and 63 neighbours: k = 63 is selected (and equals
  // brute force), k = 64 is searched.
  csl::KNearestStats stats;
  std::vector<csl::NearNeighbor> rows;
  const Space box = Space::box({0, 0}, {1, 1});
  const std::vector<Config> few = uniform(box, 300, 22);
  csl::all_k_nearest(box, few, 63, rows, &stats);
  CHECK(stats.selected >= 250);
  require_brute_force(box, few, 63);
  csl::all_k_nearest(box, few, 64, rows, &stats);
  CHECK(stats.searched == 300);
  // The k-d tree searches.
  csl::all_k_nearest(Space::torus(3), uniform(Space::torus(3), 200, 23), 10, rows, &stats);
  CHECK(stats.searched == 200);
}
