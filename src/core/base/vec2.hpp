#pragma once
// Plane vectors for the core. Eigen's fixed-size 2-vector: no heap, no alignment traps.
#include <Eigen/Core>

namespace csl {
using Vec2 = Eigen::Vector2d;
}  // namespace csl
