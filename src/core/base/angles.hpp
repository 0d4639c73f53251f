#pragma once
// Angles on S^1, represented in the chart [-pi, pi).
#include <cmath>

#include "core/base/detmath.hpp"

namespace csl {

inline constexpr double kPi = 3.141592653589793238462643383279502884;
inline constexpr double kTwoPi = 2.0 * kPi;
/// What the double kTwoPi misses of 2*pi: added in a second step, a sum with kTwoPi rounds as
/// one with 2*pi itself would (wrap_angle, and the neighbour search's S^1 distance).
inline constexpr double kTwoPiLo = 2.44929359829470635445e-16;

/// The angle wrapped into [-pi, pi). Exact reduction steps only (fmod and rint are exact in
/// IEEE arithmetic), so the result is the same natively and in wasm.
inline double wrap_angle(double a) {
  if (a >= -kPi && a < kPi) return a;  // the common case, untouched
  // 2*pi is not a double; subtracting k * (hi + lo) in two steps is exact to ~2^-100 while
  // k * kTwoPiHi is exact (|k| <= 8: its last three bits are zero), i.e. for the few turns the
  // lab's angles make; beyond, it rounds by about |a| * 2^-53, the angle's own precision.
  constexpr double kTwoPiHi = 6.28318530717958623200e+00;  // == kTwoPi
  const double k = std::rint(a / kTwoPiHi);
  double r = (a - k * kTwoPiHi) - k * kTwoPiLo;
  if (r < -kPi) r += kTwoPi;
  if (r >= kPi) r -= kTwoPi;
  if (r >= -kPi && r < kPi) return r;
  // |a| beyond about 1e17: k * kTwoPiHi is no longer near a, and r is far outside the chart.
  // fmod is exact (the remainder by the double kTwoPiHi, whose own error times k is then more
  // than a turn: such an angle says nothing about a direction), but it lands in the chart.
  r = std::fmod(a, kTwoPiHi);
  if (r < -kPi) r += kTwoPiHi;
  if (r >= kPi) r -= kTwoPiHi;
  return r;
}

/// Signed shortest turn from a to b on S^1, in [-pi, pi) (a half turn counts as -pi).
inline double angle_difference(double a, double b) { return wrap_angle(b - a); }

/// Distance between two angles on S^1 (homework P10, by the modulus): |wrap(b - a)| in [0, pi].
inline double s1_distance(double a, double b) { return std::fabs(angle_difference(a, b)); }

/// The same distance the other way P10 suggests: as rotations R(a), R(b) in SO(2), the angle of
/// R(a)^T R(b), whose cosine is the dot product of their first columns (cos a, sin a) and
/// (cos b, sin b). atan2(|sin|, cos) instead of acos(cos) keeps full accuracy near 0 and pi.
inline double s1_distance_rotation(double a, double b) {
  double sa, ca, sb, cb;
  det::sincos(a, sa, ca);
  det::sincos(b, sb, cb);
  const double cos_d = ca * cb + sa * sb;  // (R(a)^T R(b))_11
  const double sin_d = ca * sb - sa * cb;  // (R(a)^T R(b))_21
  return det::atan2(std::fabs(sin_d), cos_d);
}

}  // namespace csl
