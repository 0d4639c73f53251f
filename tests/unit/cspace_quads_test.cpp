// cspace_quads: the quads tile T^2 (strips side by side, each strip's pieces from v = 0 to 1 at
// both edges), and their blocked flags agree with the exact map everywhere but within a
// column's width of a C-obstacle's edge, and wrong at a quarter as many points as the grid of
// cells they replace, or fewer.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/base/angles.hpp"
#include "core/base/rng.hpp"
#include "core/teaching/cspace_quads.hpp"

using csl::CSpaceQuad;
using csl::kPi;
using csl::kTwoPi;

namespace {

constexpr int kColumns = 96, kRows = 40;

struct Scene {
  csl::ArmRobot arm;
  std::vector<csl::Obstacle> obstacles;
};

// The lesson's arm among random disks, a polygon and a wall (some reach link 1: whole blocked
// columns; some cross theta2 = +-pi: intervals split at the seam).
Scene random_scene(std::uint64_t seed) {
  csl::Rng rng(seed);
  Scene s{csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, {}};
  const int disks = 2 + static_cast<int>(rng.below(5));
  for (int k = 0; k < disks; ++k) {
    const double x = rng.uniform(0.05, 0.95);
    const double y = rng.uniform(0.05, 0.95);
    s.obstacles.push_back(csl::Disk{{x, y}, rng.uniform(0.02, 0.1)});
  }
  const double x = rng.uniform(0.2, 0.8);
  s.obstacles.push_back(csl::PolygonObstacle{{{x, 0.1}, {x + 0.1, 0.12}, {x + 0.02, 0.2}}});
  s.obstacles.push_back(csl::Wall{{0.9, rng.uniform(0.2, 0.8)}, {0.7, 0.95}});
  return s;
}

// The quad holding (u, v): its strip by u, then the piece whose slanted edges enclose v.
const CSpaceQuad* find(const std::vector<CSpaceQuad>& quads, double u, double v) {
  for (const CSpaceQuad& q : quads) {
    if (u < q.u0 || u >= q.u1) continue;
    const double f = (u - q.u0) / (q.u1 - q.u0);
    const double lo = q.va0 + f * (q.va1 - q.va0), hi = q.vb0 + f * (q.vb1 - q.vb0);
    if (lo <= v && v < hi) return &q;
  }
  return nullptr;
}

// Whether the exact map changes within `h` (radians, both axes) of (t1, t2).
bool near_edge(const csl::ArmCSpaceMap& map, double t1, double t2, double h) {
  const bool here = map.blocked(t1, t2);
  for (int a = -4; a <= 4; ++a)
    for (int b = -4; b <= 4; ++b)
      if (map.blocked(t1 + a * h / 4, t2 + b * h / 4) != here) return true;
  return false;
}

}  // namespace

TEST_CASE("cspace_quads tile the torus square: strips side by side, pieces from v = 0 to 1") {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const Scene s = random_scene(seed);
    const csl::ArmCSpaceMap map(s.arm, s.obstacles);
    const std::vector<CSpaceQuad> quads = csl::cspace_quads(map, kColumns, kRows);
    REQUIRE(!quads.empty());
    double u = 0.0, va = 0.0, vb = 0.0;  // where the next piece must start
    bool new_strip = true;
    int strips = 0;
    for (std::size_t k = 0; k < quads.size(); ++k) {
      const CSpaceQuad& q = quads[k];
      if (new_strip) {  // it starts where the last one ended (which ended at v = 1)
        REQUIRE(q.u0 == u);
        va = vb = 0.0;
        ++strips;
      }
      REQUIRE(q.u0 == u);
      CHECK(q.u1 > q.u0);
      CHECK(q.va0 == va);
      CHECK(q.va1 == vb);
      CHECK(q.vb0 >= q.va0);
      CHECK(q.vb1 >= q.va1);
      CHECK(std::max(q.vb0 - q.va0, q.vb1 - q.va1) <= 1.0 / kRows + 1e-12);  // round on a surface
      va = q.vb0;
      vb = q.vb1;
      new_strip = k + 1 == quads.size() || quads[k + 1].u0 != q.u0;
      if (new_strip) {
        CHECK(va == 1.0);
        CHECK(vb == 1.0);
        u = q.u1;
      }
    }
    CHECK(strips >= kColumns);  // one per column, more where a strip was halved
    CHECK(u == 1.0);
    CHECK(va == 1.0);
    CHECK(vb == 1.0);
  }
}

TEST_CASE("cspace_quads agree with the exact map but within a column of an edge, unlike a grid of cells") {
  const double column = kTwoPi / kColumns;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    CAPTURE(seed);
    const Scene s = random_scene(seed);
    const csl::ArmCSpaceMap map(s.arm, s.obstacles);
    const std::vector<CSpaceQuad> quads = csl::cspace_quads(map, kColumns, kRows);
    const int n = 300;
    long quad_wrong = 0, cell_wrong = 0, far_wrong = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u = (i + 0.5) / n, v = (j + 0.5) / n;
        const double t1 = -kPi + kTwoPi * u, t2 = -kPi + kTwoPi * v;
        const bool exact = map.blocked(t1, t2);
        const CSpaceQuad* q = find(quads, u, v);
        REQUIRE(q != nullptr);
        // The drawing this replaced: kColumns x kRows cells, each as blocked as its centre.
        const double cu = (std::floor(u * kColumns) + 0.5) / kColumns, cv = (std::floor(v * kRows) + 0.5) / kRows;
        cell_wrong += map.blocked(-kPi + kTwoPi * cu, -kPi + kTwoPi * cv) != exact;
        if (q->blocked == exact) continue;
        ++quad_wrong;
        if (!near_edge(map, t1, t2, column)) ++far_wrong;
      }
    CHECK(far_wrong == 0);
    CHECK(cell_wrong > 0);
    CHECK(quad_wrong * 4 < cell_wrong);
    MESSAGE("seed " << seed << ": quads wrong at " << quad_wrong << " points, cells at " << cell_wrong << " of " << n * n);
  }
}

TEST_CASE("cspace_quads: where link 1 starts to collide the column's edge stays upright") {
  // A disk within l1 - l2 of the base: link 1 is blocked for theta1 in about +-0.41, and just
  // outside that link 2 cannot reach the disk, so a whole blocked column meets an empty one.
  // A tip would draw that straight edge as a wedge the torus's height; halving keeps it within
  // an eighth of a column.
  const csl::ArmRobot arm{{0.5, 0.5}, 0.3, 0.2};
  const std::vector<csl::Obstacle> obstacles{csl::Disk{{0.55, 0.5}, 0.02}};
  const csl::ArmCSpaceMap map(arm, obstacles);
  REQUIRE(!map.link1_blocked().empty());
  const std::vector<CSpaceQuad> quads = csl::cspace_quads(map, kColumns, kRows);
  const double column = kTwoPi / kColumns;
  const int n = 400;
  long wrong = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      const double t1 = -kPi + kTwoPi * u, t2 = -kPi + kTwoPi * v;
      const CSpaceQuad* q = find(quads, u, v);
      REQUIRE(q != nullptr);
      if (q->blocked == map.blocked(t1, t2)) continue;
      ++wrong;
      CHECK(near_edge(map, t1, t2, column / 8));
    }
  MESSAGE("wrong at " << wrong << " of " << n * n << " points");
}

TEST_CASE("cspace_quads: bad sizes are refused") {
  const Scene s = random_scene(1);
  const csl::ArmCSpaceMap map(s.arm, s.obstacles);
  CHECK_THROWS_AS(csl::cspace_quads(map, 0, 40), std::invalid_argument);
  CHECK_THROWS_AS(csl::cspace_quads(map, 96, 0), std::invalid_argument);
}
