#pragma once
// Three-dimensional C-spaces as voxel volumes for drawing and export: the polygon robot's SE(2)
// (x, y and a stack of theta slices) and the 3-link arm's T^3 (theta2, theta3 and a stack of
// theta1 slices). Each cell is the exact C-obstacle (se2_slice, arm3_slice) sampled at the
// cell's centre, not the sampled collision checker: a slice's pieces or intervals are computed
// once and filled in runs along x (SE(2)) or theta3 (T^3).
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene/scene.hpp"
#include "core/teaching/arm3_slice.hpp"
#include "core/teaching/se2_slice.hpp"

namespace csl {

/// nx x ny x nz bytes, x fastest: cell (i, j, k) is cells[(k * ny + j) * nx + i]; 255 = free,
/// 0 = C-obstacle.
struct CSpaceVolume {
  int nx = 0, ny = 0, nz = 0;
  std::vector<std::uint8_t> cells;
  /// The fraction of cells that are free.
  double free_fraction = 0.0;
};

/// The centre of cell `index` of `n` across [lo, hi]: lo + (index + 1/2) (hi - lo) / n.
double volume_cell_centre(double lo, double hi, int index, int n);

/// SE(2) over the workspace box [lo, hi] (the reference point's range; see se2_slice.hpp):
/// i is x, j is y (at volume_cell_centre), k is theta = cspace_pixel_angle(k, nz) over
/// [-pi, pi) (its ends glued). nx, ny, nz >= 1.
CSpaceVolume se2_volume(const Se2CObstacles& cobstacles, const Vec2& lo, const Vec2& hi, int nx, int ny, int nz);

/// T^3: i is theta2, j is theta3 (both cspace_pixel_angle(., n)), k is theta1 =
/// cspace_pixel_angle(k, slices): each k is the (theta2, theta3) slice at that theta1, laid out
/// like the 2-link arm's map (columns the first angle, rows the second). n, slices >= 1.
CSpaceVolume arm3_volume(const Arm3Slices& arm, int n, int slices);

/// The expected work of a volume or of one exact slice, priced before it runs: the sizes alone
/// do not bound it (1000 concave 256-gons make 250000 pieces a slice; one convex 256-gon
/// against another is a single piece of 65536 vertex sums). Units: one row of one piece
/// (about 22 ns natively); `text` says how the figure was made, for a refusal's message.
struct VolumeWork {
  double units = 0.0;
  std::string text;
};
/// The most work a volume or slice may take: 10 to 20 s natively at worst. Measured: 200
/// obstacles, a third of them concave, and an L-shaped robot, about 800 pieces a slice: 512 x
/// 512 x 256, 1.05e8 units, took 2.3 s (22 ns a unit); where vertex sums dominate a unit costs
/// more (100 concave 64-gons and a 32-gon robot: 1.34e8 units in 5.5 s, 41 ns). The T^3
/// estimate ignores the pruning by reach, which makes most columns far cheaper.
inline constexpr double kMaxVolumeWork = 4e8;
/// The most work the lab's "C-spaces in 3-D" lesson spends on a scene's volumes (the fine one it
/// counts the free fraction on plus the coarse one it draws), at once when the scene changes:
/// a scene past it is refused, as the page must stay responsive. About 2 s in the browser at
/// worst. Measured in headless Chromium (set_scene, both volumes): the bundled polygon-robot and
/// arm-3link scenes 3 to 7 ms; 100 concave 32-gons and the rectangle robot 0.46 s (0.24 s
/// natively for the fine volume alone); 100 concave 64-gons and a 32-gon robot (4.16e5 vertex
/// sums, 3400 pieces a slice: 1.34e8 + 5.7e7 units) 5.6 s, 29 ns a unit, where vertex sums
/// dominate and cost more than the 4 units priced (the fine volume natively 5.5 s).
inline constexpr double kLabMaxVolumeWork = 5e7;
/// SE(2) (a polygon robot): (4 x vertex sums + pieces x R) a slice x K; T^3 (a 3-link arm):
/// obstacle edges x R^2 x K (a disk 1 edge, a wall 6, a polygon its vertices). slices == 0
/// prices one slice as `cspacelab cspace --slice` makes it (SE(2): 64 units a piece for its
/// outline; T^3: edges x R columns of intervals). Other robots: 0.
VolumeWork cspace_volume_work(const Scene& scene, int resolution, int slices);

}  // namespace csl
