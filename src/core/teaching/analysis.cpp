#include "core/teaching/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>

#include "core/base/angles.hpp"

namespace csl {

namespace {
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}
}  // namespace

FailureBound path_tiling_bound(double length, double clearance, int d, double free_volume, double samples) {
  require(std::isfinite(length) && length > 0, "path length must be a finite number > 0");
  require(std::isfinite(clearance) && clearance > 0, "clearance must be a finite number > 0");
  require(d >= 1 && d <= 64, "dimension must be in 1..64");
  require(std::isfinite(free_volume) && free_volume > 0, "free volume must be a finite number > 0");
  require(std::isfinite(samples) && samples >= 0, "samples must be a finite number >= 0");
  FailureBound b;
  // Section 2.1: m = ceil(L / (r/2)) balls along the path, sigma = mu(B_1) / (2^d mu(F)).
  // A quotient a few ulps above an integer is that integer: L and r are typed as decimals, and
  // 0.07 / 0.01 is 7.000000000000001 in binary, where a student counts 7 balls, not 8.
  const double quotient = length / (clearance / 2);
  require(std::isfinite(quotient), "more than 1e308 balls: take a shorter path or a larger clearance");
  b.balls = std::ceil(quotient);
  if (b.balls > 1 && b.balls != quotient && quotient - (b.balls - 1) <= 8 * kEpsilon * quotient) b.balls -= 1;
  b.sigma = unit_ball_volume(d) / (std::pow(2.0, d) * free_volume);
  b.rate = b.sigma * std::pow(clearance, d);
  require(std::isfinite(b.rate), "clearance^d overflows a double: take a smaller clearance");
  b.exponent = b.rate * samples;
  b.bound = b.balls * std::exp(-b.exponent);
  b.vacuous = b.bound >= 1.0;
  return b;
}

// P8, derived. Take F = [0,1]^d, so mu(F) = 1 and sigma = mu(B_1) / 2^d. The path argument
// needs balls of radius r/2 whose neighbours' centres are at most r/2 apart, so that samples
// in neighbouring balls both lie in the ball of radius r around one centre, which is free (F
// is convex here, so any straight line in it is free anyway). Tiling the whole cube: a grid
// of N balls per axis, centred in the cells of width 1/N. Neighbours r/2 apart needs
// 1/N <= r/2; for the balls to cover every point the cell's half-diagonal must be within a
// ball, sqrt(d) / (2N) <= r/2, i.e. 1/N <= r/sqrt(d) (the stronger condition once d > 4). So
//   N = ceil(max(2, sqrt(d)) / r),  m = N^d  (ceil(2/r)^d for d <= 4).
// The "very slight" modification puts m where the path had ceil(L / (r/2)):
//   m exp(-sigma r^d n)   (interior_bound).
// That step assumed each ball lies in F, so that a sample hits it with probability sigma r^d.
// The path's balls do (their centres have clearance r); the grid's balls at the faces do not:
// a corner ball of radius 0.05 in the unit square has only 63% of its area inside. So, for a
// sound bound: a ball whose centre is within rho = min(r/2, 1/2) of the faces along j axes
// still holds, inside F, one of the 2^j equal pieces into which the coordinate reflections
// through its centre cut B(c, rho): the one on the inner side along each of those axes, which
// stays in F because rho <= 1/2 (and along the other axes the ball stays in F anyway). So it is
// hit with probability at least sigma min(r, 1)^d / 2^j, and with E per axis of the N balls
// within rho of a face,
//   Prob(failure) <= sum_j C(d, j) E^j (N - E)^(d-j) exp(-sigma min(r,1)^d n / 2^j)   (bound).
// Against the path bound ceil(2L/r) exp(-sigma r^d n): the factor in front grows like
// (2/r)^d instead of 2L/r, which costs about (d - 1) ln(2/r) / (sigma r^d) more samples for the
// same failure probability (interior balls); the corner balls, hit up to 2^d times less often,
// cost more still. Much worse, and the more so in high dimension: it pays for every region of
// the space, faces and corners included, rather than for one corridor.
TilingBound whole_space_tiling_bound(double clearance, int d, double samples) {
  require(std::isfinite(clearance) && clearance > 0, "clearance must be a finite number > 0");
  require(d >= 1 && d <= 64, "dimension must be in 1..64");
  require(std::isfinite(samples) && samples >= 0, "samples must be a finite number >= 0");
  TilingBound t;
  t.dim = d;
  const double root_d = std::sqrt(static_cast<double>(d));
  t.per_axis = std::ceil(std::max(2.0, root_d) / clearance);
  t.balls = std::pow(t.per_axis, d);
  t.covering_balls = std::pow(std::ceil(root_d / clearance), d);
  require(std::isfinite(t.balls), "more than 1e308 balls: take a larger clearance or a smaller dimension");
  t.sigma = unit_ball_volume(d) / std::pow(2.0, d);
  t.rate = t.sigma * std::pow(clearance, d);
  require(std::isfinite(t.rate), "clearance^d overflows a double: take a smaller clearance");
  // Cells along an axis whose centre (i + 1/2) / N is within rho of face 0 (as many at face
  // 1); a hair more rather than less, so rounding can only count a ball as reaching out.
  const double rho = std::min(clearance, 1.0) / 2;
  const double near = std::ceil(rho * t.per_axis * (1.0 + 1e-12) - 0.5);
  t.edge_per_axis = std::min(t.per_axis, 2.0 * std::max(0.0, near));
  // The balls reaching out along at least one axis, summed by j (N^d - (N - E)^d cancels).
  double choose = 1.0;
  for (int j = 1; j <= d; ++j) {
    choose = choose * (d - j + 1) / j;
    t.boundary_balls += choose * std::pow(t.edge_per_axis, j) * std::pow(t.per_axis - t.edge_per_axis, d - j);
  }
  t.hit_rate = t.sigma * std::pow(std::min(clearance, 1.0), d);
  t.interior_bound = t.balls * std::exp(-t.rate * samples);
  t.bound = t.bound_at(samples);
  t.vacuous = t.bound >= 1.0;
  return t;
}

double TilingBound::bound_at(double n) const {
  // The sum over j, in logarithms: its terms can be far beyond a double while the sum is small.
  const double inner = per_axis - edge_per_axis;
  double logs[65];
  int count = 0;
  double top = -std::numeric_limits<double>::infinity();
  double choose = 1.0;  // C(d, j), exact enough in a double for d <= 64
  for (int j = 0; j <= dim; ++j) {
    if (j > 0) choose = choose * (dim - j + 1) / j;
    if ((j > 0 && edge_per_axis == 0) || (j < dim && inner == 0)) continue;  // no such balls
    const double l = std::log(choose) + (j > 0 ? j * std::log(edge_per_axis) : 0.0) +
                     (j < dim ? (dim - j) * std::log(inner) : 0.0) - hit_rate * n / std::ldexp(1.0, j);
    logs[count++] = l;
    top = std::max(top, l);
  }
  double sum = 0.0;
  for (int i = 0; i < count; ++i) sum += std::exp(logs[i] - top);
  return std::exp(top + std::log(sum));
}

double TilingBound::interior_bound_at(double n) const { return balls * std::exp(-rate * n); }

double TilingBound::samples_for(double target) const {
  require(target > 0.0 && target < 1.0, "target probability must be in (0, 1)");
  if (bound_at(0.0) <= target) return 0.0;
  // The bound falls with n; all m balls at the slowest rate reach the target by hi.
  double lo = 0.0, hi = std::log(balls / target) * std::ldexp(1.0, dim) / hit_rate;
  for (int i = 0; i < 200 && hi - lo > 1e-9 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (bound_at(mid) > target ? lo : hi) = mid;
  }
  return hi;
}

double FailureBound::samples_to_reach(double balls, double rate, double target) {
  // balls * exp(-rate n) = target  <=>  n = ln(balls / target) / rate (0 if already below).
  require(target > 0.0 && target < 1.0, "target probability must be in (0, 1)");
  return std::fmax(0.0, std::log(balls / target) / rate);
}

namespace {

// Integral over t in [0, T] of clamp(a + s t, 0, 1): a linear function clipped to the square's
// height. Exact: split [0, T] where a + s t crosses 0 and 1, integrate each linear piece.
double clamped_linear_integral(double a, double s, double T) {
  double cuts[4] = {0.0, T, T, T};
  int n = 1;
  if (s != 0.0) {
    for (double level : {0.0, 1.0}) {
      const double t = (level - a) / s;
      if (t > 0.0 && t < T) cuts[n++] = t;
    }
  }
  cuts[n++] = T;
  if (n == 4 && cuts[1] > cuts[2]) std::swap(cuts[1], cuts[2]);
  double total = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double t0 = cuts[i], t1 = cuts[i + 1];
    if (t1 <= t0) continue;
    // On a piece the clamp is one of 0, 1 or the line itself: decide at its middle.
    const double mid = a + s * 0.5 * (t0 + t1);
    if (mid <= 0.0) continue;
    if (mid >= 1.0) {
      total += t1 - t0;
    } else {
      total += (t1 - t0) * (a + s * 0.5 * (t0 + t1));  // trapezoid = exact for a line
    }
  }
  return total;
}

void require_p9(double x1, double y1, double gap) {
  require(std::isfinite(x1) && x1 >= 0.0 && x1 < 0.5, "x1 must be in [0, 1/2)");
  require(std::isfinite(y1) && y1 >= 0.0 && y1 <= 1.0, "y1 must be in [0, 1]");
  require(std::isfinite(gap) && gap >= 0.0 && gap <= 1.0, "the gap must be in [0, 1]");
}

}  // namespace

double visibility_probability(double x1, double y1, double gap) {
  require_p9(x1, y1, gap);
  // The cone from (x1, y1) through the opening's ends (1/2, 1/2 -+ gap/2): over the right half,
  // at x = 1/2 + t (t in [0, 1/2]) it spans from lo + s_lo t to hi + s_hi t.
  const double lo = 0.5 - 0.5 * gap, hi = 0.5 + 0.5 * gap;
  const double run = 0.5 - x1;
  const double s_lo = (lo - y1) / run, s_hi = (hi - y1) / run;
  // Its part inside the square: the area under the clipped upper ray minus under the lower.
  // Every case of the cone leaving through the right edge, the top, the bottom, or both
  // falls out of the clipping.
  const double right = clamped_linear_integral(hi, s_hi, 0.5) - clamped_linear_integral(lo, s_lo, 0.5);
  return 0.5 + right;  // the left half [0, 1/2] x [0, 1] is convex: all of it is visible
}

const char* p9_exit_name(P9Ray::Exit exit) {
  switch (exit) {
    case P9Ray::Exit::Top: return "top";
    case P9Ray::Exit::Bottom: return "bottom";
    case P9Ray::Exit::Right: break;
  }
  return "right edge";
}

namespace {

// The ray y = a + s t over t in [0, 1/2] (x = 1/2 + t), a in [0, 1]: where it leaves the right
// half and the area below it there, by the closed form of its case (see P9Ray).
P9Ray p9_ray(double a, double s) {
  P9Ray r;
  r.start = a;
  r.slope = s;
  const double end = a + 0.5 * s;  // its height at x = 1
  if (end > 1.0) {  // rises through the top first: s > 0 here
    r.exit = P9Ray::Exit::Top;
    r.exit_x = 0.5 + (1.0 - a) / s;
    r.exit_y = 1.0;
    r.area_under = 0.5 - (1.0 - a) * (1.0 - a) / (2.0 * s);
  } else if (end < 0.0) {  // falls through the bottom first: s < 0 here
    r.exit = P9Ray::Exit::Bottom;
    r.exit_x = 0.5 + a / -s;
    r.exit_y = 0.0;
    r.area_under = a * a / (2.0 * -s);
  } else {
    r.exit = P9Ray::Exit::Right;
    r.exit_x = 1.0;
    r.exit_y = end;
    r.area_under = (a + end) / 4.0;
  }
  return r;
}

}  // namespace

P9Breakdown p9_breakdown(double x1, double y1, double gap) {
  require_p9(x1, y1, gap);
  // The same rays as visibility_probability(), each integrated by the formula of its case.
  const double lo = 0.5 - 0.5 * gap, hi = 0.5 + 0.5 * gap, run = 0.5 - x1;
  P9Breakdown b;
  b.upper = p9_ray(hi, (hi - y1) / run);
  b.lower = p9_ray(lo, (lo - y1) / run);
  b.right_area = b.upper.area_under - b.lower.area_under;
  b.probability = b.left_area + b.right_area;
  b.case_name = std::string(p9_exit_name(b.upper.exit)) + "/" + p9_exit_name(b.lower.exit);
  return b;
}

bool visible_in_p9(double x1, double y1, double gap, double x2, double y2) {
  if (x2 <= 0.5) return true;
  // Where the segment crosses the wall's line x = 1/2, it must pass through the opening.
  const double y = y1 + (y2 - y1) * (0.5 - x1) / (x2 - x1);
  return std::fabs(y - 0.5) <= 0.5 * gap;
}

Proportion wilson_interval(long long successes, long long trials) {
  Proportion p;
  p.successes = successes;
  p.trials = trials;
  if (trials <= 0) {
    p.low = 0.0;
    p.high = 1.0;
    return p;
  }
  constexpr double z = 1.959963984540054;
  const double n = static_cast<double>(trials);
  const double phat = static_cast<double>(successes) / n;
  const double denom = 1.0 + z * z / n;
  const double centre = (phat + z * z / (2 * n)) / denom;
  const double half = z * std::sqrt(phat * (1 - phat) / n + z * z / (4 * n * n)) / denom;
  p.estimate = phat;
  p.low = std::fmax(0.0, centre - half);
  p.high = std::fmin(1.0, centre + half);
  return p;
}

Proportion visibility_monte_carlo(double x1, double y1, double gap, long long trials, Rng& rng) {
  require_p9(x1, y1, gap);
  long long seen = 0;
  for (long long i = 0; i < trials; ++i) {
    const double x2 = rng.uniform01(), y2 = rng.uniform01();
    seen += visible_in_p9(x1, y1, gap, x2, y2);
  }
  return wilson_interval(seen, trials);
}

}  // namespace csl
