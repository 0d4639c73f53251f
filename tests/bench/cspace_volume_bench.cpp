// The 3-D C-space volumes: time of a 128 x 128 x 64 SE(2) volume (an L-shaped polygon robot,
// concave) and a 96^3 T^3 volume (a 3-link arm), each among 20 obstacles (disks, polygons,
// some concave, and walls), from scratch (cutting the pieces included), as the app would
// recompute them after an edit; against brute force (CollisionWorld::is_free at every cell
// centre) in the same run, and their agreement.
//
//   cspacelab_bench_volume [--quick] [--json]
//
// The goal (issue 25): each in <= 100 ms in wasm. tests/bench/compare_wasm.mjs volume runs it
// natively and as wasm and prints the ratio.
#include <cstdio>

#include "bench_common.hpp"
#include "core/base/angles.hpp"
#include "core/teaching/cspace_volume.hpp"

namespace {

// 20 obstacles at distances r_lo to r_hi from `centre`: a quarter disks, a quarter walls 0.12
// long, half polygons of 4 to 6 vertices (some concave).
std::vector<csl::Obstacle> obstacles_around(const csl::Vec2& centre, double r_lo, double r_hi, std::uint64_t seed) {
  csl::Rng rng(seed);
  std::vector<csl::Obstacle> out;
  for (int k = 0; k < 20; ++k) {
    const double a = rng.uniform(-csl::kPi, csl::kPi);
    const double r = rng.uniform(r_lo, r_hi);
    const csl::Vec2 c = centre + r * csl::Vec2(csl::det::cos(a), csl::det::sin(a));
    if (k % 4 == 0) {
      out.push_back(csl::Disk{c, rng.uniform(0.02, 0.06)});
    } else if (k % 4 == 1) {
      const double t = rng.uniform(0.0, csl::kTwoPi);
      const csl::Vec2 d = 0.06 * csl::Vec2(csl::det::cos(t), csl::det::sin(t));
      out.push_back(csl::Wall{c - d, c + d});
    } else {
      const int n = 4 + static_cast<int>(rng.below(3));
      const double size = rng.uniform(0.03, 0.08), turn = rng.uniform(0.0, csl::kTwoPi);
      csl::Polygon poly;
      for (int v = 0; v < n; ++v) {
        const double t = turn + csl::kTwoPi * v / n, rv = size * (v % 2 == 1 && n > 4 ? 0.5 : 1.0);  // dents
        poly.push_back(c + rv * csl::Vec2(csl::det::cos(t), csl::det::sin(t)));
      }
      out.push_back(csl::PolygonObstacle{poly});
    }
  }
  return out;
}

long long differ(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  long long n = 0;
  for (std::size_t k = 0; k < a.size(); ++k) n += a[k] != b[k];
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = bench::quick(argc, argv);
  bool json = false;
  for (int i = 1; i < argc; ++i) json = json || std::string(argv[i]) == "--json";
  const int se2_side = quick ? 32 : 128, se2_slices = quick ? 16 : 64, t3_side = quick ? 24 : 96;
  const int repeats = quick ? 2 : 10;

  const csl::PolygonRobot robot =
      csl::make_polygon_robot({{-0.05, -0.05}, {0.1, -0.05}, {0.1, 0.0}, {0.0, 0.0}, {0.0, 0.08}, {-0.05, 0.08}});
  const std::vector<csl::Obstacle> field = obstacles_around({0.5, 0.5}, 0.05, 0.5, 5);
  const csl::ArmRobot arm({0.5, 0.5}, std::vector<double>{0.2, 0.15, 0.12});
  // Most beyond link 1's reach of 0.2 (where link 1 collides, a whole slice is blocked at once:
  // the cheap case), all within the arm's 0.47.
  const std::vector<csl::Obstacle> around_arm = obstacles_around(arm.base, 0.16, 0.47, 11);

  csl::CSpaceVolume se2, t3;
  const double se2_seconds = bench::best_of(repeats, [&] {
    se2 = csl::se2_volume(csl::Se2CObstacles(robot, field), {0, 0}, {1, 1}, se2_side, se2_side, se2_slices);
  });
  const double t3_seconds =
      bench::best_of(repeats, [&] { t3 = csl::arm3_volume(csl::Arm3Slices(arm, around_arm), t3_side, t3_side); });

  // Brute force: the checker at every cell centre, in the volumes' layout.
  std::vector<std::uint8_t> se2_brute(se2.cells.size()), t3_brute(t3.cells.size());
  bench::Timer se2_timer;
  {
    const csl::CollisionWorld world(robot, field, {0, 0}, {1, 1});
    std::size_t c = 0;
    for (int k = 0; k < se2_slices; ++k)
      for (int j = 0; j < se2_side; ++j)
        for (int i = 0; i < se2_side; ++i, ++c)
          se2_brute[c] = world.is_free(csl::config({csl::volume_cell_centre(0, 1, i, se2_side),
                                                    csl::volume_cell_centre(0, 1, j, se2_side),
                                                    csl::cspace_pixel_angle(k, se2_slices)}))
                             ? 255
                             : 0;
  }
  const double se2_brute_seconds = se2_timer.seconds();
  bench::Timer t3_timer;
  {
    const csl::CollisionWorld world(arm, around_arm, {0, 0}, {1, 1});
    std::size_t c = 0;
    for (int k = 0; k < t3_side; ++k)
      for (int j = 0; j < t3_side; ++j)
        for (int i = 0; i < t3_side; ++i, ++c)
          t3_brute[c] = world.is_free(csl::config({csl::cspace_pixel_angle(k, t3_side), csl::cspace_pixel_angle(i, t3_side),
                                                   csl::cspace_pixel_angle(j, t3_side)}))
                            ? 255
                            : 0;
  }
  const double t3_brute_seconds = t3_timer.seconds();
  const long long se2_differ = differ(se2.cells, se2_brute), t3_differ = differ(t3.cells, t3_brute);

  if (json) {
    std::printf("[{\"scene\": \"SE(2) %dx%dx%d\", \"ms\": %.4f, \"brute_ms\": %.4f, \"free\": %.6f, \"differ\": %lld},"
                " {\"scene\": \"T^3 %d^3\", \"ms\": %.4f, \"brute_ms\": %.4f, \"free\": %.6f, \"differ\": %lld}]\n",
                se2_side, se2_side, se2_slices, 1e3 * se2_seconds, 1e3 * se2_brute_seconds, se2.free_fraction, se2_differ,
                t3_side, 1e3 * t3_seconds, 1e3 * t3_brute_seconds, t3.free_fraction, t3_differ);
  } else {
    std::printf("SE(2) volume %dx%dx%d, L-shaped robot, 20 obstacles: best of %d %8.3f ms; brute force %8.3f ms;"
                " free %.4f; %lld of %zu cells differ\n",
                se2_side, se2_side, se2_slices, repeats, 1e3 * se2_seconds, 1e3 * se2_brute_seconds, se2.free_fraction,
                se2_differ, se2.cells.size());
    std::printf("T^3 volume %d^3, 3-link arm, 20 obstacles:            best of %d %8.3f ms; brute force %8.3f ms;"
                " free %.4f; %lld of %zu cells differ\n",
                t3_side, repeats, 1e3 * t3_seconds, 1e3 * t3_brute_seconds, t3.free_fraction, t3_differ, t3.cells.size());
  }
  // Cells differ only on boundaries, where rounding decides: far fewer than 0.1 %.
  if (se2_differ * 1000 > static_cast<long long>(se2.cells.size()) || t3_differ * 1000 > static_cast<long long>(t3.cells.size())) {
    std::printf("MISMATCH: a volume and brute force disagree on more than 0.1%% of cells\n");
    return 1;
  }
  return 0;
}
