#pragma once
// Three-dimensional C-spaces as voxel volumes for drawing and export: the polygon robot's SE(2)
// (x, y and a stack of theta slices) and the 3-link arm's T^3 (theta2, theta3 and a stack of
// theta1 slices). Each cell is the exact C-obstacle (se2_slice, arm3_slice) sampled at the
// cell's centre, not the sampled collision checker: a slice's pieces or intervals are computed
// once and filled in runs along x (SE(2)) or theta3 (T^3).
#include <cstdint>
#include <vector>

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

}  // namespace csl
