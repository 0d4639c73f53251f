#include "app/views/field_draw.hpp"

#include <algorithm>
#include <cmath>

#include "app/shell/theme.hpp"
#include "core/base/angles.hpp"

namespace csl::app {

HeatScale HeatScale::of(const ScalarGrid& grid, double quantile) {
  std::vector<double> finite;
  for (double v : grid.values)
    if (std::isfinite(v)) finite.push_back(v);
  HeatScale s;
  if (finite.empty()) return s;
  std::sort(finite.begin(), finite.end());
  s.lo = finite.front();
  s.hi = finite[static_cast<std::size_t>(std::clamp(quantile, 0.0, 1.0) * static_cast<double>(finite.size() - 1))];
  if (!(s.hi > s.lo)) s.hi = s.lo + 1.0;
  return s;
}

ImU32 HeatScale::color(double value) const {
  if (!std::isfinite(value)) return theme::rgba(96, 96, 104);
  // A sequential scale, light yellow to dark red-brown (ColorBrewer YlOrRd): low potential
  // reads as open ground, high as a warning; the square root spreads the low end, where the
  // attractive bowl is.
  static const float stops[5][3] = {{255, 255, 229}, {254, 227, 145}, {254, 153, 41}, {217, 95, 14}, {140, 45, 4}};
  const double t = std::sqrt(std::clamp((value - lo) / (hi - lo), 0.0, 1.0)) * 4.0;
  const int k = std::min(3, static_cast<int>(t));
  const float f = static_cast<float>(t - k);
  const auto mix = [&](int c) { return static_cast<unsigned>(stops[k][c] + f * (stops[k + 1][c] - stops[k][c]) + 0.5f); };
  return theme::rgba(mix(0), mix(1), mix(2));
}

HeatMap make_heat_map(ScalarGrid grid, int level_count, bool covered) {
  HeatMap m;
  m.scale = HeatScale::of(grid);
  m.colors.resize(grid.values.size());
  for (std::size_t k = 0; k < m.colors.size(); ++k) {
    const double v = grid.values[k];
    m.colors[k] = m.scale.color(covered && !std::isfinite(v) ? m.scale.hi : v);
  }
  for (double l : contour_levels(grid, level_count)) {
    const auto segs = level_set(grid, l);
    m.levels.insert(m.levels.end(), segs.begin(), segs.end());
    ++m.level_count;
  }
  m.grid = std::move(grid);
  return m;
}

void draw_heat_map(const WorkspaceView& view, const HeatMap& map) {
  ImDrawList* dl = view.draw_list();
  const ScalarGrid& grid = map.grid;
  if (grid.nx < 2 || grid.ny < 2) return;
  const auto at = [&](int i, int j) { return map.colors[static_cast<std::size_t>(j) * static_cast<std::size_t>(grid.nx) + static_cast<std::size_t>(i)]; };
  // Screen y grows downwards: a cell's top edge is row j + 1. Node positions are computed once
  // per row and column, not per cell.
  std::vector<float> xs(static_cast<std::size_t>(grid.nx)), ys(static_cast<std::size_t>(grid.ny));
  for (int i = 0; i < grid.nx; ++i) xs[static_cast<std::size_t>(i)] = view.to_screen(grid.node(i, 0)).x;
  for (int j = 0; j < grid.ny; ++j) ys[static_cast<std::size_t>(j)] = view.to_screen(grid.node(0, j)).y;
  for (int j = 0; j + 1 < grid.ny; ++j)
    for (int i = 0; i + 1 < grid.nx; ++i)
      dl->AddRectFilledMultiColor(ImVec2(xs[static_cast<std::size_t>(i)], ys[static_cast<std::size_t>(j) + 1]),
                                  ImVec2(xs[static_cast<std::size_t>(i) + 1], ys[static_cast<std::size_t>(j)]),
                                  at(i, j + 1), at(i + 1, j + 1), at(i + 1, j), at(i, j));
}

void draw_level_set(const WorkspaceView& view, const std::vector<LevelSegment>& segments, ImU32 color, float thickness) {
  ImDrawList* dl = view.draw_list();
  for (const LevelSegment& s : segments) dl->AddLine(view.to_screen(s.a), view.to_screen(s.b), color, thickness);
}

void draw_force(const WorkspaceView& view, const Vec2& at, const Vec2& force, ImU32 color, float pixels_per_unit,
                float max_pixels, float thickness) {
  const double n = std::sqrt(force.x() * force.x() + force.y() * force.y());
  if (!(n > 0.0) || !std::isfinite(n)) return;
  const float want = static_cast<float>(n) * pixels_per_unit;
  const float len = std::min(want, max_pixels);
  if (len < 1.5f) return;
  ImDrawList* dl = view.draw_list();
  const ImVec2 a = view.to_screen(at);
  const ImVec2 dir(static_cast<float>(force.x() / n), static_cast<float>(-force.y() / n));  // screen y is down
  const ImVec2 b(a.x + dir.x * len, a.y + dir.y * len);
  dl->AddLine(a, b, color, thickness);
  const float h = std::min(9.0f, 0.5f * len + 3.0f);
  const auto head = [&](ImVec2 tip) {
    const ImVec2 back(tip.x - dir.x * h, tip.y - dir.y * h);
    const ImVec2 side(-dir.y * h * 0.5f, dir.x * h * 0.5f);
    dl->AddTriangleFilled(tip, ImVec2(back.x + side.x, back.y + side.y), ImVec2(back.x - side.x, back.y - side.y), color);
  };
  head(b);
  if (want > max_pixels) head(ImVec2(b.x - dir.x * h * 0.8f, b.y - dir.y * h * 0.8f));
}

void draw_arm_cobstacles(const WorkspaceView& v, const ArmCSpaceMap& map, ImU32 color) {
  ImDrawList* dl = v.draw_list();
  const float dpr = ImGui::GetIO().DisplayFramebufferScale.x > 0 ? ImGui::GetIO().DisplayFramebufferScale.x : 1.0f;
  const ImVec2 lo = v.to_screen(Vec2(-kPi, -kPi)), hi = v.to_screen(Vec2(kPi, kPi));
  const float x0 = std::max(lo.x, v.canvas_min().x), x1 = std::min(hi.x, v.canvas_max().x);
  const float column = 1.0f / dpr;
  std::vector<AngleInterval> blocked;
  for (float x = x0; x < x1; x += column) {
    const double theta1 = v.to_world(ImVec2(x + 0.5f * column, lo.y)).x();
    map.blocked_theta2(theta1, blocked);
    for (const AngleInterval& b : blocked) {
      const float ya = v.to_screen(Vec2(theta1, b.lo)).y, yb = v.to_screen(Vec2(theta1, b.hi)).y;
      dl->AddRectFilled(ImVec2(x, yb), ImVec2(x + column, ya), color);
    }
  }
}

}  // namespace csl::app
