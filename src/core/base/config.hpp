#pragma once
// A configuration q of a robot: a short vector of coordinates (positions and angles), stored
// inline (no heap) so roadmaps of many thousands of them stay fast.
#include <Eigen/Core>

#include <string>

namespace csl {

/// The most coordinates a configuration can have (SE(2) x T^6 needs 9).
inline constexpr int kMaxDim = 9;

using Config = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxDim, 1>;

/// A configuration from a list of numbers: config({0.5, 1.0}).
inline Config config(std::initializer_list<double> values) {
  Config q(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double v : values) q[i++] = v;
  return q;
}

/// A configuration as "(0.410, 0.770)", for the event logs.
std::string format_config(const Config& q);

}  // namespace csl
