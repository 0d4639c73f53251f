#pragma once
// Random test obstacles shared by the C-space tests (cspace_map_test, cspace_slices_test).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/base/rng.hpp"
#include "core/geometry/geometry.hpp"

namespace csl::test {

/// A simple polygon star-shaped about c (often concave): 3 to 8 vertices at sorted random angles,
/// radii in [0.35, 1] * size, redrawn until it is simple with twice its area above
/// min_area * size². One draw per statement, and det:: trigonometry, so that the same seed gives
/// the same scenes natively and in wasm.
inline Polygon random_star_polygon_about(Rng& rng, const Vec2& c, double size, double min_area) {
  for (;;) {
    const int n = 3 + static_cast<int>(rng.below(6));
    std::vector<double> angles;
    for (int k = 0; k < n; ++k) angles.push_back(rng.uniform(-kPi, kPi));
    std::sort(angles.begin(), angles.end());
    Polygon poly;
    for (double a : angles) {
      const double r = size * rng.uniform(0.35, 1.0);
      poly.push_back(c + r * Vec2(det::cos(a), det::sin(a)));
    }
    if (std::string(polygon_problem(poly)).empty() && std::fabs(polygon_twice_signed_area(poly)) > min_area * size * size)
      return poly;
  }
}

}  // namespace csl::test
