#pragma once
// Why PRM works, in numbers (homework section 2.1, P8, P9): the failure bound of the path
// tiling argument, the whole-space tiling bound, the visibility probability of the
// wall-with-a-gap square, and confidence intervals for measured failure rates.
#include <cstdint>
#include <string>

#include "core/base/rng.hpp"
#include "core/spaces/space.hpp"  // unit_ball_volume

namespace csl {

/// The path-tiling bound of section 2.1. A free path of length L with clearance r is tiled by
/// m = ceil(L / (r/2)) balls of radius r/2; PRM fails only if some ball gets no sample, so
///   Prob(failure) <= m * exp(-sigma r^d n),  sigma = mu(B_1) / (2^d mu(F)).
struct FailureBound {
  double balls = 0;      ///< m (a double: it can exceed the range of integers)
  double sigma = 0;      ///< sigma
  double rate = 0;       ///< sigma r^d: the bound falls by e^-rate per sample
  double exponent = 0;   ///< sigma r^d n
  double bound = 0;      ///< m exp(-sigma r^d n), not clamped
  bool vacuous = false;  ///< bound >= 1: it says nothing
  /// Samples for the bound to reach `target` in (0, 1): n = ln(m / target) / (sigma r^d).
  double samples_for(double target) const { return samples_to_reach(balls, rate, target); }
  static double samples_to_reach(double balls, double rate, double target);
};
/// The bound for path length L > 0, clearance r > 0, dimension d >= 1, free volume mu(F) > 0,
/// n >= 0 samples. Throws std::invalid_argument for values outside those ranges.
FailureBound path_tiling_bound(double length, double clearance, int d, double free_volume, double samples);

/// P8: tile all of F = [0,1]^d instead of one path (see the derivation in analysis.cpp).
struct TilingBound {
  int dim = 0;
  double per_axis = 0;        ///< N = ceil(max(2, sqrt(d)) / r): balls per axis, 1/N apart
  double balls = 0;           ///< m = N^d: neighbours r/2 apart at most, and every point covered
  double covering_balls = 0;  ///< ceil(sqrt(d)/r)^d: enough for the balls to cover every point
  double boundary_balls = 0;  ///< of the m, those that stick out of the cube
  double sigma = 0;           ///< mu(B_1) / 2^d (mu(F) = 1)
  double rate = 0;            ///< sigma r^d
  /// m exp(-sigma r^d n): the path argument with m in place of ceil(L / (r/2)), as if every
  /// ball lay in F. Not a bound on its own: a ball sticking out of the cube is hit less often.
  double interior_bound = 0;
  double bound = 0;           ///< the failure bound, boundary balls included (the derivation)
  bool vacuous = false;       ///< bound >= 1
  /// Samples for the bound to reach `target` in (0, 1).
  double samples_for(double target) const;
  /// The bound after n samples (what `bound` holds for the n it was made with).
  double bound_at(double n) const;
  /// The handout's version (interior_bound): samples for m exp(-sigma r^d n) to reach
  /// `target` in (0, 1), n = ln(m / target) / (sigma r^d). Fewer than samples_for(target).
  double interior_samples_for(double target) const { return FailureBound::samples_to_reach(balls, rate, target); }
  /// interior_bound after n samples.
  double interior_bound_at(double n) const;

  // Per axis, the balls within reach of a face (`edge_per_axis`) and the rate a ball reaching
  // out along j axes is at least hit with, `hit_rate` / 2^j (see the derivation).
  double edge_per_axis = 0;
  double hit_rate = 0;
};
TilingBound whole_space_tiling_bound(double clearance, int d, double samples);

/// P9: Q = [0,1]^2, a wall of zero thickness at x = 1/2 with an opening of height `gap`
/// centred at y = 1/2. The probability that a uniform random configuration is visible from
/// (x1, y1), x1 < 1/2: the whole left half (convex, so all of it is seen) plus the part of the
/// right half inside the cone through the opening, clipped to the square.
double visibility_probability(double x1, double y1, double gap);

/// One ray of P9's cone, from (x1, y1) through an end of the opening, over the right half
/// x = 1/2 + t, t in [0, 1/2]: y = start + slope t, until it leaves through an edge.
struct P9Ray {
  enum class Exit { Top, Right, Bottom };
  double start = 0;        ///< a: where it crosses the wall, 1/2 -+ gap/2
  double slope = 0;        ///< s = (a - y1) / (1/2 - x1)
  Exit exit = Exit::Right; ///< the edge of the right half it leaves through (a corner: Right)
  double exit_x = 1, exit_y = 0;  ///< where
  /// The area of the right half below it (the ray clamped to [0, 1]), by the exit's formula:
  ///   Right (a + s/2 in [0, 1]):  (a + e) / 4,  e = a + s/2 (a trapezoid)
  ///   Top (a + s/2 > 1):          1/2 - (1 - a)^2 / (2 s)  (the half minus the triangle above)
  ///   Bottom (a + s/2 < 0):       a^2 / (2 |s|)  (a triangle)
  double area_under = 0;
};
/// "top", "right edge" or "bottom".
const char* p9_exit_name(P9Ray::Exit exit);

/// P9 worked out by cases: which edges the cone's two rays leave the right half through,
/// and the areas that give the probability, p = 1/2 + (area under the upper ray - area under
/// the lower one). Equals visibility_probability() (up to rounding); throws as it does.
struct P9Breakdown {
  P9Ray upper, lower;       ///< through (1/2, 1/2 + gap/2) and (1/2, 1/2 - gap/2)
  double left_area = 0.5;   ///< all of the left half is visible (it is convex)
  double right_area = 0;    ///< the visible part of the right half: upper - lower area_under
  double probability = 0;   ///< left_area + right_area
  std::string case_name;    ///< "<upper exit>/<lower exit>", e.g. "top/right edge"
};
P9Breakdown p9_breakdown(double x1, double y1, double gap);

/// Whether (x2, y2) is visible from (x1, y1) in the P9 square (x1 < 1/2).
bool visible_in_p9(double x1, double y1, double gap, double x2, double y2);

/// A proportion measured from trials, with its 95% Wilson score interval.
struct Proportion {
  double estimate = 0;
  double low = 0, high = 0;
  long long successes = 0, trials = 0;
};
/// The Wilson score interval (Wilson 1927) at z = 1.959964 (95%); sensible also near 0 and 1.
Proportion wilson_interval(long long successes, long long trials);

/// P9 by Monte Carlo: the fraction of `trials` uniform samples visible from (x1, y1).
Proportion visibility_monte_carlo(double x1, double y1, double gap, long long trials, Rng& rng);

}  // namespace csl
