#pragma once
// A scalar function sampled on a regular grid over a rectangle, and its level sets by marching
// squares: what the potential-fields lesson draws as a heat map with iso-lines (and the rho0
// rings, the level set rho = rho0 of the distance to the obstacles).
//
// Values are taken at the grid's nodes (nx x ny of them, corners included), row by row from
// the bottom: value(i, j) at x_i = lo.x + i (hi.x - lo.x) / (nx - 1), y_j likewise. Infinite
// values (a potential on an obstacle) are kept; contouring treats them as larger than any
// level, so a level line never runs into an obstacle's inside but is cut at the last finite
// node, which is the honest answer at this resolution.
#include <functional>
#include <vector>

#include "core/base/vec2.hpp"

namespace csl {

struct ScalarGrid {
  int nx = 0, ny = 0;
  Vec2 lo{0.0, 0.0}, hi{1.0, 1.0};
  std::vector<double> values;  ///< nx * ny, index j * nx + i

  double value(int i, int j) const { return values[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)]; }
  Vec2 node(int i, int j) const;
};

/// Samples f at every node (nx, ny >= 2; lo < hi). Throws std::invalid_argument otherwise.
ScalarGrid sample_grid(int nx, int ny, const Vec2& lo, const Vec2& hi, const std::function<double(const Vec2&)>& f);

struct LevelSegment {
  Vec2 a, b;
};

/// The level set {f = level} as segments, one or two per grid cell it crosses, with endpoints
/// linearly interpolated along the cell's edges (marching squares; a saddle cell is resolved by
/// the value at its centre, the mean of its corners). Nodes exactly at the level count as above.
std::vector<LevelSegment> level_set(const ScalarGrid& grid, double level);

/// `count` levels spread between the finite minimum and the `upper_quantile` quantile of the
/// grid's finite values, equally spaced (none if every value is infinite or all are equal).
std::vector<double> contour_levels(const ScalarGrid& grid, int count, double upper_quantile = 0.9);

}  // namespace csl
