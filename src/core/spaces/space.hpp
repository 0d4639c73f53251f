#pragma once
// Configuration spaces as products of factors: R^d boxes, S^1, T^n = (S^1)^n, SE(2) = R^2 x S^1.
// Each coordinate is either linear (an interval of R) or angular (S^1 in the chart [-pi, pi)).
//
// The metric is Euclidean in weighted coordinate differences, where the difference of two
// angles is the shortest way round: d(p, q)^2 = sum_i (w_i * delta_i)^2. On T^n this is the flat
// torus metric; on SE(2) the weight of the angle converts radians into a length (the polygon
// robot uses its radius, so that a turn costs what its farthest point travels).
#include <cmath>
#include <string>
#include <vector>

#include "core/base/angles.hpp"
#include "core/base/config.hpp"
#include "core/base/rng.hpp"

namespace csl {

/// mu(B_1): volume of the unit ball in R^d, pi^(d/2) / Gamma(d/2 + 1) (d >= 1). (The bounds of
/// core/teaching/analysis.hpp and PRM's neighbour budgets both measure balls against a space's volume.)
double unit_ball_volume(int d);

struct Coordinate {
  bool angular = false;  ///< S^1 (wraps at +-pi) or an interval of R
  double lo = 0.0;       ///< bounds of a linear coordinate (angular: -pi)
  double hi = 1.0;       ///< (angular: pi)
  double weight = 1.0;   ///< metric weight
  /// b - a along this coordinate (the shorter way round for an angle).
  double delta(double a, double b) const { return angular ? angle_difference(a, b) : b - a; }
};

/// A named factor of the product, e.g. "SE(2)" over coordinates [first, first + size).
struct SpaceFactor {
  std::string name;
  int first = 0;
  int size = 0;
};

class Space {
 public:
  /// The box [lo, hi] in R^d (d = lo.size()).
  static Space box(const std::vector<double>& lo, const std::vector<double>& hi);
  /// S^1 = SO(2).
  static Space circle(double weight = 1.0);
  /// T^n = S^1 x ... x S^1 (n >= 1; T^1 is written S^1).
  static Space torus(int n);
  /// SE(2) = R^2 x S^1 with (x, y) in [lo, hi] and the angle weighted by `angular_weight`.
  static Space se2(double x_lo, double y_lo, double x_hi, double y_hi, double angular_weight);
  /// The product A x B (coordinates of A first).
  static Space product(const Space& a, const Space& b);

  int dim() const { return static_cast<int>(coords_.size()); }
  const Coordinate& coordinate(int i) const { return coords_[static_cast<std::size_t>(i)]; }
  const std::vector<SpaceFactor>& factors() const { return factors_; }
  /// The space in the homework's notation, e.g. "R^2", "T^2", "SE(2) x T^2".
  std::string notation() const;

  /// Per-coordinate difference q - p, angles the shortest way round (in [-pi, pi)).
  Config difference(const Config& p, const Config& q) const;
  /// Squared distance (weighted, wrapped); summed in coordinate order.
  double squared_distance(const Config& p, const Config& q) const { return squared_distance(p.data(), q.data()); }
  /// The same on raw coordinate arrays of dim() numbers (for spatial indexes).
  double squared_distance(const double* p, const double* q) const {
    double sum = 0.0;
    if (unit_linear_) {  // R^d: the loop below, without the angle test and the weight of 1
      for (std::size_t i = 0; i < coords_.size(); ++i) {
        const double delta = q[i] - p[i];
        sum += delta * delta;
      }
      return sum;
    }
    for (std::size_t i = 0; i < coords_.size(); ++i) {
      const double delta = coords_[i].delta(p[i], q[i]) * coords_[i].weight;
      sum += delta * delta;
    }
    return sum;
  }
  double distance(const Config& p, const Config& q) const;
  /// The length of a difference vector (from difference()): distance(p, q) == norm(difference(p, q)).
  double norm(const Config& delta) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < coords_.size(); ++i) {
      const double d = delta[static_cast<Eigen::Index>(i)] * coords_[i].weight;
      sum += d * d;
    }
    return std::sqrt(sum);
  }
  /// The point a fraction t of the way from p to q along the shortest path; angles wrapped.
  Config interpolate(const Config& p, const Config& q, double t) const { return along(p, difference(p, q), t); }
  /// p + t * delta, angles wrapped: interpolate() with the difference computed once, for many t.
  Config along(const Config& p, const Config& delta, double t) const;
  /// Angles into [-pi, pi); linear coordinates unchanged.
  Config wrap(const Config& q) const;
  /// Whether q has dim() finite coordinates within the bounds (angles anything finite).
  bool contains(const Config& q) const;
  /// A uniform random configuration (one rng draw per coordinate, in coordinate order).
  Config sample(Rng& rng) const;
  /// Volume in weighted coordinates: prod (hi - lo) * w over linear, 2 pi * w over angular.
  double volume() const;

 private:
  // The factories end here: derived facts of coords_.
  Space& classify();

  std::vector<Coordinate> coords_;
  std::vector<SpaceFactor> factors_;
  // Every coordinate linear with weight 1. Distances are then plain sums of squared
  // differences: the general formula's bits (x * 1.0 is x), with no angle to test per
  // coordinate (PRM measures every candidate pair of the point robot).
  bool unit_linear_ = false;
};

}  // namespace csl
