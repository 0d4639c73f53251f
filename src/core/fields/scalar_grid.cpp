#include "core/fields/scalar_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace csl {

Vec2 ScalarGrid::node(int i, int j) const {
  return Vec2(lo.x() + (hi.x() - lo.x()) * i / (nx - 1), lo.y() + (hi.y() - lo.y()) * j / (ny - 1));
}

ScalarGrid sample_grid(int nx, int ny, const Vec2& lo, const Vec2& hi, const std::function<double(const Vec2&)>& f) {
  if (nx < 2 || ny < 2 || nx > 4096 || ny > 4096) throw std::invalid_argument("a grid needs 2 to 4096 nodes per side");
  if (!(lo.x() < hi.x()) || !(lo.y() < hi.y())) throw std::invalid_argument("a grid needs lo < hi");
  ScalarGrid g;
  g.nx = nx;
  g.ny = ny;
  g.lo = lo;
  g.hi = hi;
  g.values.resize(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) g.values[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)] = f(g.node(i, j));
  return g;
}

namespace {

// The point on edge p -> q where the value crosses `level` (vp < level <= vq or the reverse).
// With an infinite end the crossing sits at the finite end: nothing is known beyond it.
Vec2 crossing(const Vec2& p, const Vec2& q, double vp, double vq, double level) {
  if (!std::isfinite(vp)) return q;
  if (!std::isfinite(vq)) return p;
  const double t = (level - vp) / (vq - vp);
  return p + std::clamp(t, 0.0, 1.0) * (q - p);
}

}  // namespace

std::vector<LevelSegment> level_set(const ScalarGrid& g, double level) {
  std::vector<LevelSegment> out;
  for (int j = 0; j + 1 < g.ny; ++j) {
    for (int i = 0; i + 1 < g.nx; ++i) {
      // Corners counter-clockwise from the bottom left; edges e_k join corner k and k + 1.
      const Vec2 p[4] = {g.node(i, j), g.node(i + 1, j), g.node(i + 1, j + 1), g.node(i, j + 1)};
      const double v[4] = {g.value(i, j), g.value(i + 1, j), g.value(i + 1, j + 1), g.value(i, j + 1)};
      int mask = 0;
      for (int k = 0; k < 4; ++k) mask |= (v[k] >= level ? 1 : 0) << k;
      if (mask == 0 || mask == 15) continue;
      const auto edge = [&](int k) { return crossing(p[k], p[(k + 1) % 4], v[k], v[(k + 1) % 4], level); };
      // The crossed edges, in order round the cell: an edge is crossed when its ends differ.
      int crossed[4], n = 0;
      for (int k = 0; k < 4; ++k)
        if (((mask >> k) & 1) != ((mask >> ((k + 1) % 4)) & 1)) crossed[n++] = k;
      if (n == 2) {
        out.push_back({edge(crossed[0]), edge(crossed[1])});
        continue;
      }
      // A saddle (mask 5 or 10): all four edges are crossed. The centre decides which corners
      // are joined: if it is on the same side as corner 0, corner 0's region spans the centre,
      // so the segments cut off corners 1 and 3; otherwise they cut off corners 0 and 2.
      double centre = 0.0;
      bool finite = true;
      for (double x : v) finite = finite && std::isfinite(x), centre += x / 4;
      const bool centre_above = !finite || centre >= level;
      const bool corner0_above = (mask & 1) != 0;
      if (centre_above == corner0_above) {
        out.push_back({edge(0), edge(1)});  // around corner 1
        out.push_back({edge(2), edge(3)});  // around corner 3
      } else {
        out.push_back({edge(3), edge(0)});  // around corner 0
        out.push_back({edge(1), edge(2)});  // around corner 2
      }
    }
  }
  return out;
}

std::vector<double> contour_levels(const ScalarGrid& g, int count, double upper_quantile) {
  std::vector<double> finite;
  for (double v : g.values)
    if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty() || count <= 0) return {};
  std::sort(finite.begin(), finite.end());
  const double lo = finite.front();
  const std::size_t k = static_cast<std::size_t>(std::clamp(upper_quantile, 0.0, 1.0) * static_cast<double>(finite.size() - 1));
  const double hi = finite[k];
  if (!(hi > lo)) return {};
  std::vector<double> levels;
  for (int i = 1; i <= count; ++i) levels.push_back(lo + (hi - lo) * i / (count + 1));
  return levels;
}

}  // namespace csl
