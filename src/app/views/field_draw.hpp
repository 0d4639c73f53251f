#pragma once
// Drawing scalar fields and forces on a WorkspaceView: a heat map of a sampled grid, its level
// lines, force arrows, and the 2-link arm's exact C-obstacles in the torus square (columns one
// device pixel wide, from the analytic map).
#include <vector>

#include "app/views/workspace_view.hpp"
#include "core/fields/scalar_grid.hpp"
#include "core/teaching/cspace_map.hpp"

namespace csl::app {

/// Colour scale of a heat map: `lo` light, `hi` and above dark; infinite values (on an
/// obstacle) in the obstacle grey.
struct HeatScale {
  double lo = 0.0, hi = 1.0;
  /// lo = the finite minimum, hi = the `quantile` quantile of the finite values (a few huge
  /// values next to obstacles would otherwise wash out the rest).
  static HeatScale of(const ScalarGrid& grid, double quantile = 0.95);
  ImU32 color(double value) const;
};

/// A grid ready to draw: its colour scale, the colour of every node and its level lines,
/// computed once when the grid changes (a frame then only emits the cells).
struct HeatMap {
  ScalarGrid grid;
  HeatScale scale;
  std::vector<ImU32> colors;           ///< per node, as grid.values
  std::vector<LevelSegment> levels;    ///< `level_count` level lines, all segments together
  int level_count = 0;
};
/// `covered`: the caller draws the obstacles exactly over the map, so an infinite node (on an
/// obstacle) takes the scale's darkest colour, the highest potential, rather than the grey:
/// cells across an obstacle's edge then shade into dark, and the exact edge drawn over them is
/// the only one seen (grey nodes would show the grid's blocks around it).
HeatMap make_heat_map(ScalarGrid grid, int level_count, bool covered = false);

/// The grid as smoothly shaded cells (corner colours interpolated).
void draw_heat_map(const WorkspaceView& view, const HeatMap& map);
void draw_level_set(const WorkspaceView& view, const std::vector<LevelSegment>& segments, ImU32 color, float thickness);

/// An arrow from world point `at` along `force`, `pixels_per_unit` long per unit of force and at
/// most `max_pixels` (longer ones get a second head: "more than shown"). Nothing for a zero or
/// non-finite force.
void draw_force(const WorkspaceView& view, const Vec2& at, const Vec2& force, ImU32 color, float pixels_per_unit,
                float max_pixels = 110.0f, float thickness = 2.5f);

/// The arm's C-obstacles in the square [-pi, pi]^2 of `view`: exact horizontal edges.
void draw_arm_cobstacles(const WorkspaceView& view, const ArmCSpaceMap& map, ImU32 color);

}  // namespace csl::app
