#pragma once
// A control point of a robot (homework section 2.4): a point of the robot where workspace forces
// act, with its Jacobian d o / d q, through which a force becomes a configuration-space force.
// Each robot type says which points are its control points (core/robots/*_robot.hpp).
#include <Eigen/Core>

#include "core/base/config.hpp"
#include "core/base/vec2.hpp"

namespace csl {

/// d o_i / d q: 2 rows, one column per configuration coordinate.
using PointJacobian = Eigen::Matrix<double, 2, Eigen::Dynamic, Eigen::ColMajor, 2, kMaxDim>;

/// A control point at a configuration: where it is and its Jacobian there.
struct ControlPoint {
  Vec2 position{0.0, 0.0};
  PointJacobian jacobian;
};

}  // namespace csl
