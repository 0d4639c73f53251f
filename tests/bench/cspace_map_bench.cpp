// The exact C-space map of the 2-link arm: time of a full recompute (building the map and
// rasterising 512 x 512), as the app redraws it while an obstacle is dragged, against brute
// force (CollisionWorld::is_free at every pixel centre) in the same run; and their agreement.
//
//   cspacelab_bench_cspace [--quick]
//
// The arm of assets/scenes/arm-2link.json (base (0.5, 0.5), links 0.25 and 0.2) among 20
// obstacles around it, 10 disks and 10 polygons (4 to 6 vertices, some concave), seeded.
#include <cstdio>

#include "bench_common.hpp"
#include "core/base/angles.hpp"
#include "core/teaching/cspace_map.hpp"

namespace {

std::vector<csl::Obstacle> obstacles_around(const csl::Vec2& base, std::uint64_t seed) {
  csl::Rng rng(seed);
  std::vector<csl::Obstacle> out;
  for (int k = 0; k < 20; ++k) {
    // Centres 0.12 to 0.5 from the base: most within the arm's reach of 0.45.
    const double a = rng.uniform(-csl::kPi, csl::kPi), r = rng.uniform(0.12, 0.5);
    const csl::Vec2 c = base + r * csl::Vec2(csl::det::cos(a), csl::det::sin(a));
    if (k % 2 == 0) {
      out.push_back(csl::Disk{c, rng.uniform(0.02, 0.06)});
      continue;
    }
    const int n = 4 + static_cast<int>(rng.below(3));
    const double size = rng.uniform(0.03, 0.08), turn = rng.uniform(0.0, csl::kTwoPi);
    csl::Polygon poly;
    for (int v = 0; v < n; ++v) {
      const double t = turn + csl::kTwoPi * v / n, rv = size * (v % 2 == 1 && n > 4 ? 0.5 : 1.0);  // dents
      poly.push_back(c + rv * csl::Vec2(csl::det::cos(t), csl::det::sin(t)));
    }
    out.push_back(csl::PolygonObstacle{poly});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = bench::quick(argc, argv);
  const int resolution = quick ? 128 : 512;
  const int repeats = quick ? 3 : 200;
  const int brute_repeats = quick ? 1 : 3;

  const csl::ArmRobot arm{{0.5, 0.5}, 0.25, 0.2};
  const std::vector<csl::Obstacle> obstacles = obstacles_around(arm.base, 11);

  std::vector<std::uint8_t> exact, brute;
  double free_fraction = 0.0;
  const double exact_seconds = bench::best_of(repeats, [&] {
    const csl::ArmCSpaceMap map(arm, obstacles);
    free_fraction = map.rasterize(resolution, exact);
  });
  const double rasterize_seconds = bench::best_of(repeats, [&] {
    static const csl::ArmCSpaceMap map(arm, obstacles);
    map.rasterize(resolution, exact);
  });
  const double brute_seconds = bench::best_of(brute_repeats, [&] {
    const csl::CollisionWorld world(arm, obstacles, {0, 0}, {1, 1});
    brute.assign(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution), 0);
    for (int j = 0; j < resolution; ++j) {
      const double t2 = csl::cspace_pixel_angle(j, resolution);
      for (int i = 0; i < resolution; ++i)
        if (world.is_free(csl::config({csl::cspace_pixel_angle(i, resolution), t2})))
          brute[static_cast<std::size_t>(j * resolution + i)] = 255;
    }
  });

  long long differ = 0;
  for (std::size_t k = 0; k < exact.size(); ++k) differ += exact[k] != brute[k];
  const double agreement = 1.0 - static_cast<double>(differ) / static_cast<double>(exact.size());

  std::printf("Exact C-space map of the 2-link arm, 20 obstacles (10 disks, 10 polygons), %dx%d\n", resolution,
              resolution);
  std::printf("full recompute (construct + rasterize), best of %d: %8.3f ms\n", repeats, 1e3 * exact_seconds);
  std::printf("rasterize only, best of %d:                         %8.3f ms\n", repeats, 1e3 * rasterize_seconds);
  std::printf("brute force (is_free at each pixel), best of %d:    %8.3f ms  (%.0fx the exact map's time)\n",
              brute_repeats, 1e3 * brute_seconds, brute_seconds / exact_seconds);
  std::printf("free fraction %.6f; agreement with brute force %.4f%% (%lld pixels differ)\n", free_fraction,
              100.0 * agreement, differ);
  if (agreement < 0.999) {
    std::printf("MISMATCH: the exact map and brute force disagree on more than 0.1%% of pixels\n");
    return 1;
  }
  return 0;
}
