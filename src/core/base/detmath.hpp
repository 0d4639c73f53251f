#pragma once
// The lab's own sin, cos, atan2 and friends. std::sin, std::cos and std::atan2 come from the C
// library: glibc natively, musl in the wasm build. Both are accurate to about an ulp, but they are
// different code and disagree in the last bit for some arguments, and one flipped bit in a
// forward-kinematics angle is enough to change which PRM edge collides. The roadmap for a seed
// must be bit-identical in both builds, so the core computes these functions itself, with IEEE
// operations whose results the standard pins down exactly: + - * /, std::sqrt, std::fabs,
// comparisons and exact integer manipulation of the bits. (The build adds -ffp-contract=off, so
// no compiler may fuse a*b+c; no long double, no libm transcendental is called.)
//
// Method. The algorithms, polynomial coefficients and evaluation orders are those of fdlibm 5.3
// as revised in FreeBSD's msun (the same code musl ships): argument reduction by pi/2 in the
// Cody-Waite manner with pi/2 split into three 33-bit parts (__rem_pio2's "medium" path), minimax
// polynomial kernels on [-pi/4, pi/4] (__kernel_sin, __kernel_cos), atan by table reduction
// (s_atan.c), atan2 on top of it (e_atan2.c) and acos by a rational approximation (e_acos.c).
// Huge arguments (|x| >= 2^20 * pi/2) are reduced exactly with the Payne-Hanek method in integer
// arithmetic (detmath.cpp). One change to fdlibm: atan2 corrects for the rounding of y/x and
// evaluates pi - atan(|y/x|) with a single rounding (fdlibm's atan2 can be ~1.4 ulp off).
// Constants are hexadecimal floating literals: the intended bits exactly.
//   fdlibm: Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved. Developed at SunSoft,
//   a Sun Microsystems, Inc. business. Permission to use, copy, modify, and distribute this
//   software is freely granted, provided that this notice is preserved.
//
// Domain and accuracy. Every double is a valid argument, and results are within 1 ulp of the
// exact value (faithful; fdlibm's design bound). Measured in sweeps of 200000 arguments each
// against multi-precision references (mpmath), the largest errors were 0.76 ulp for sin and cos
// (alike for |x| <= 20, <= 1e5 and up to 2^1024), 0.81 for atan, 0.83 for atan2 and 0.87 for
// acos; tests/unit/detmath_test.cpp pins the worst points. sin and cos of NaN or +-Inf are NaN;
// atan2 treats zeros and infinities as C99 Annex F says; NaN in, NaN out.
//
// Every translation unit that includes this header must be compiled with -ffp-contract=off (the
// target cspacelab_core_deps gives it to everything that links the core): a fused a*b+c would
// round differently, and Dekker's product in division_residual relies on it.
#include <cmath>
#include <cstdint>
#include <cstring>

namespace csl::det {

namespace detail {

inline std::uint64_t bits_of(double x) {
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

inline double from_bits(std::uint64_t u) {
  double x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

/// The biased exponent field of x (0 for zeros and subnormals, 2047 for Inf and NaN).
inline int exponent_field(double x) { return static_cast<int>((bits_of(x) >> 52) & 0x7FF); }

/// True for negative numbers, -0.0 and NaNs with the sign bit set.
inline bool sign_bit(double x) { return (bits_of(x) >> 63) != 0; }

inline constexpr double kPi = 0x1.921fb54442d18p+1;      // pi rounded
inline constexpr double kPiLo = 0x1.1a62633145c07p-53;   // pi - kPi
inline constexpr double kPio2 = 0x1.921fb54442d18p+0;    // pi/2 rounded
inline constexpr double kPio2Lo = 0x1.1a62633145c07p-54; // pi/2 - kPio2
inline constexpr double kPio4 = 0x1.921fb54442d18p-1;    // pi/4 rounded
inline constexpr double k3Pio4 = 0x1.2d97c7f3321d2p+1;   // 3pi/4 rounded
inline constexpr double kMaxFinite = 0x1.fffffffffffffp+1023;

// |x| below this needs no reduction (fdlibm's test on the high word, ix <= 0x3fe921fb).
inline constexpr double kNoReduction = 0x1.921fcp-1;
// |x| below this (~2^20 * pi/2) is reduced by the three-part Cody-Waite scheme: n * kPio2_1 is
// exact while n has at most 20 bits.
inline constexpr double kMediumReduction = 0x1.921fbp+20;

/// sin(x + y) for |x + y| <~ pi/4, y the tail of x (fdlibm __kernel_sin); has_tail false: y is 0.
/// The caller handles tiny x (and -0.0, whose sign this polynomial would lose).
inline double kernel_sin(double x, double y, bool has_tail) {
  constexpr double S1 = -0x1.5555555555549p-3, S2 = 0x1.111111110f8a6p-7,
                   S3 = -0x1.a01a019c161d5p-13, S4 = 0x1.71de357b1fe7dp-19,
                   S5 = -0x1.ae5e68a2b9cebp-26, S6 = 0x1.5d93a5acfd57cp-33;
  const double z = x * x;
  const double w = z * z;
  const double r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
  const double v = z * x;
  if (!has_tail) return x + v * (S1 + z * r);
  return x - ((z * (0.5 * y - v * r) - y) - v * S1);
}

/// cos(x + y) for |x + y| <~ pi/4, y the tail of x (fdlibm __kernel_cos).
inline double kernel_cos(double x, double y) {
  constexpr double C1 = 0x1.555555555554cp-5, C2 = -0x1.6c16c16c15177p-10,
                   C3 = 0x1.a01a019cb1590p-16, C4 = -0x1.27e4f809c52adp-22,
                   C5 = 0x1.1ee9ebdb4b1c4p-29, C6 = -0x1.8fae9be8838d4p-37;
  const double z = x * x;
  const double w = z * z;
  const double r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
  const double hz = 0.5 * z;
  const double one_minus_hz = 1.0 - hz;
  // 1 - hz == one_minus_hz + ((1 - one_minus_hz) - hz) exactly; the tail goes in last.
  return one_minus_hz + (((1.0 - one_minus_hz) - hz) + (z * r - x * y));
}

/// Cody-Waite reduction (fdlibm __rem_pio2, medium path): x = n*pi/2 + y0 + y1 with
/// |y0 + y1| <~ pi/4; returns n. Needs |x| < kMediumReduction.
inline int rem_pio2_medium(double x, double& y0, double& y1) {
  constexpr double kInvPio2 = 0x1.45f306dc9c883p-1;  // 2/pi, 53 bits
  constexpr double kPio2_1 = 0x1.921fb54400000p+0;   // first 33 bits of pi/2
  constexpr double kPio2_1t = 0x1.0b4611a626331p-34; // pi/2 - kPio2_1
  constexpr double kPio2_2 = 0x1.0b4611a600000p-34;  // next 33 bits
  constexpr double kPio2_2t = 0x1.3198a2e037073p-69; // pi/2 - (kPio2_1 + kPio2_2)
  constexpr double kPio2_3 = 0x1.3198a2e000000p-69;  // next 33 bits
  constexpr double kPio2_3t = 0x1.b839a252049c1p-104;  // pi/2 - (kPio2_1 + kPio2_2 + kPio2_3)
  constexpr double kRound = 0x1.8p52;  // adding and subtracting it rounds to an integer (ties even)
  const double fn = (x * kInvPio2 + kRound) - kRound;
  const int n = static_cast<int>(fn);  // |fn| <= 2^20: exact
  double r = x - fn * kPio2_1;         // exact: the product fits in 53 bits, then Sterbenz
  double w = fn * kPio2_1t;            // first round, good to 85 bits
  y0 = r - w;
  const int ex = exponent_field(x);
  if (ex - exponent_field(y0) > 16) {  // cancellation: second round, good to 118 bits
    double t = r;
    w = fn * kPio2_2;
    r = t - w;
    w = fn * kPio2_2t - ((t - r) - w);
    y0 = r - w;
    if (ex - exponent_field(y0) > 49) {  // third round, 151 bits: enough for every double here
      t = r;
      w = fn * kPio2_3;
      r = t - w;
      w = fn * kPio2_3t - ((t - r) - w);
      y0 = r - w;
    }
  }
  y1 = (r - y0) - w;
  return n;
}

/// Payne-Hanek reduction for finite |x| >= kMediumReduction, exact integer arithmetic on the
/// bits of 2/pi (detmath.cpp). Same contract as rem_pio2_medium.
int rem_pio2_large(double x, double& y0, double& y1);

/// x = n*pi/2 + y0 + y1, |y0 + y1| <~ pi/4, for finite |x| >= kNoReduction; returns n.
inline int rem_pio2(double x, double& y0, double& y1) {
  if (std::fabs(x) < kMediumReduction) return rem_pio2_medium(x, y0, y1);
  return rem_pio2_large(x, y0, y1);
}

}  // namespace detail

/// sin(x) within 1 ulp, for every double (sin(+-0) = +-0; NaN or +-Inf gives NaN).
inline double sin(double x) {
  const double ax = std::fabs(x);
  if (ax < detail::kNoReduction) {
    if (ax < 0x1p-26) return x;  // sin x == x to double precision (keeps -0.0)
    return detail::kernel_sin(x, 0.0, false);
  }
  if (!(ax <= detail::kMaxFinite)) return x - x;  // NaN or Inf: NaN
  double y0, y1;
  switch (detail::rem_pio2(x, y0, y1) & 3) {
    case 0: return detail::kernel_sin(y0, y1, true);
    case 1: return detail::kernel_cos(y0, y1);
    case 2: return -detail::kernel_sin(y0, y1, true);
    default: return -detail::kernel_cos(y0, y1);
  }
}

/// cos(x) within 1 ulp, for every double (NaN or +-Inf gives NaN).
inline double cos(double x) {
  const double ax = std::fabs(x);
  if (ax < detail::kNoReduction) {
    if (ax < 0x1p-27) return 1.0;  // 1 - x^2/2 rounds to 1
    return detail::kernel_cos(x, 0.0);
  }
  if (!(ax <= detail::kMaxFinite)) return x - x;
  double y0, y1;
  switch (detail::rem_pio2(x, y0, y1) & 3) {
    case 0: return detail::kernel_cos(y0, y1);
    case 1: return -detail::kernel_sin(y0, y1, true);
    case 2: return -detail::kernel_cos(y0, y1);
    default: return detail::kernel_sin(y0, y1, true);
  }
}

/// s = sin(x), c = cos(x) with one argument reduction: the same bits as sin(x) and cos(x).
inline void sincos(double x, double& s, double& c) {
  const double ax = std::fabs(x);
  if (ax < detail::kNoReduction) {
    s = ax < 0x1p-26 ? x : detail::kernel_sin(x, 0.0, false);
    c = ax < 0x1p-27 ? 1.0 : detail::kernel_cos(x, 0.0);
    return;
  }
  if (!(ax <= detail::kMaxFinite)) {
    s = c = x - x;
    return;
  }
  double y0, y1;
  const int n = detail::rem_pio2(x, y0, y1);
  const double sy = detail::kernel_sin(y0, y1, true);
  const double cy = detail::kernel_cos(y0, y1);
  switch (n & 3) {
    case 0: s = sy; c = cy; break;
    case 1: s = cy; c = -sy; break;
    case 2: s = -sy; c = -cy; break;
    default: s = -cy; c = sy; break;
  }
}

namespace detail {

/// atan(x) + c for 2^-60 <~ |x| < 2^66, c a correction below an ulp of the result (0 for plain
/// atan), added before the final rounding (fdlibm s_atan.c, c folded into its tail term). With
/// mirror (x > 0 only): pi - atan(x) - c, from tables of pi - atan(k), one rounding at the end.
inline double atan_plus(double x, double c, bool mirror) {
  // atan(k) and pi - atan(k) for k = 1/2, 1, 3/2, Inf, each as hi + lo.
  constexpr double kAtanHi[4] = {0x1.dac670561bb4fp-2, 0x1.921fb54442d18p-1,
                                 0x1.f730bd281f69bp-1, 0x1.921fb54442d18p+0};
  constexpr double kAtanLo[4] = {0x1.a2b7f222f65e2p-56, 0x1.1a62633145c07p-55,
                                 0x1.007887af0cbbdp-56, 0x1.1a62633145c07p-54};
  constexpr double kMirrorHi[4] = {0x1.56c6e7397f5aep+1, 0x1.2d97c7f3321d2p+1,
                                   0x1.145385fa3af71p+1, 0x1.921fb54442d18p+0};
  constexpr double kMirrorLo[4] = {0x1.660b64ece6f4bp-53, 0x1.a79394c9e8a0ap-54,
                                   0x1.fa53523b6428fp-53, 0x1.1a62633145c07p-54};
  constexpr double aT0 = 0x1.555555555550dp-2, aT1 = -0x1.999999998ebc4p-3,
                   aT2 = 0x1.24924920083ffp-3, aT3 = -0x1.c71c6fe231671p-4,
                   aT4 = 0x1.745cdc54c206ep-4, aT5 = -0x1.3b0f2af749a6dp-4,
                   aT6 = 0x1.10d66a0d03d51p-4, aT7 = -0x1.dde2d52defd9ap-5,
                   aT8 = 0x1.97b4b24760debp-5, aT9 = -0x1.2b4442c6a6c2fp-5,
                   aT10 = 0x1.0ad3ae322da11p-6;
  const double ax = std::fabs(x);
  if (ax < 0x1p-27) {  // atan x == x to double precision
    return mirror ? kPi + ((kPiLo - c) - x) : x + c;
  }
  // Reduce to |t| <= 7/16: atan(x) = atan(k) + atan((x - k) / (1 + k x)) for k = 1/2, 1, 3/2,
  // and atan(x) = pi/2 + atan(-1/x) beyond 39/16.
  int id;
  double t;
  if (ax < 0.4375) {
    id = -1;
    t = x;
  } else if (ax < 0.6875) {
    id = 0;
    t = (2.0 * ax - 1.0) / (2.0 + ax);
  } else if (ax < 1.1875) {
    id = 1;
    t = (ax - 1.0) / (ax + 1.0);
  } else if (ax < 2.4375) {
    id = 2;
    t = (ax - 1.5) / (1.0 + 1.5 * ax);
  } else {
    id = 3;
    t = -1.0 / ax;
  }
  const double z = t * t;
  const double w = z * z;
  // The sum of aT[i] z^(i+1), split into odd and even parts: atan(t) = t - t * (s1 + s2).
  const double s1 = z * (aT0 + w * (aT2 + w * (aT4 + w * (aT6 + w * (aT8 + w * aT10)))));
  const double s2 = w * (aT1 + w * (aT3 + w * (aT5 + w * (aT7 + w * aT9))));
  const double ts = t * (s1 + s2);
  if (mirror) {  // pi - atan(k) - atan(t) - c
    const double hi = id < 0 ? kPi : kMirrorHi[id], lo = id < 0 ? kPiLo : kMirrorLo[id];
    return hi + ((ts + (lo - c)) - t);
  }
  if (id < 0) return t - (ts - c);
  // The table part works on |x|; the sign goes on last.
  const double r = kAtanHi[id] - ((ts - (kAtanLo[id] + (x < 0 ? -c : c))) - t);
  return x < 0 ? -r : r;
}

/// n - q*d for q = n/d rounded, nearly exact (Dekker's product with Veltkamp's split: IEEE
/// operations only, no FMA). Needs |q|, |d| < 2^996 and q*d far from underflow.
inline double division_residual(double n, double d, double q) {
  constexpr double kSplit = 0x1p27 + 1.0;
  const double qc = kSplit * q, dc = kSplit * d;
  const double qh = qc - (qc - q), ql = q - qh;  // q == qh + ql, 26 bits each
  const double dh = dc - (dc - d), dl = d - dh;
  const double p = q * d;
  const double p_err = ((qh * dh - p) + qh * dl + ql * dh) + ql * dl;  // q*d == p + p_err
  return (n - p) - p_err;  // n - p is exact (Sterbenz)
}

}  // namespace detail

/// atan(x) in [-pi/2, pi/2] within 1 ulp (atan(+-0) = +-0, atan(+-Inf) = +-pi/2).
inline double atan(double x) {
  const double ax = std::fabs(x);
  if (ax < 0x1p-27) return x;  // also keeps -0.0
  if (!(ax < 0x1p66)) {
    if (x != x) return x + x;
    return x > 0 ? detail::kPio2 : -detail::kPio2;  // +-(pi/2 + pi/2 lo) rounds to +-kPio2
  }
  return detail::atan_plus(x, 0.0, false);
}

/// The angle of the point (x, y) in [-pi, pi] within 1 ulp; zeros and infinities as C99 Annex F.
inline double atan2(double y, double x) {
  // fdlibm e_atan2.c, plus the correction for the rounding of y/x. Annex F: atan2(+-0, -0) =
  // +-pi, atan2(+-0, +0) = +-0, atan2(+-Inf, -Inf) = +-3pi/4, ...
  if (x != x || y != y) return x + y;
  const bool neg_y = detail::sign_bit(y), neg_x = detail::sign_bit(x);
  if (y == 0.0) {
    if (!neg_x) return y;                       // atan2(+-0, +anything) = +-0
    return neg_y ? -detail::kPi : detail::kPi;  // atan2(+-0, -anything) = +-pi
  }
  if (x == 0.0) return neg_y ? -detail::kPio2 : detail::kPio2;
  double ax = std::fabs(x), ay = std::fabs(y);
  if (!(ax <= detail::kMaxFinite)) {  // x = +-Inf
    if (!(ay <= detail::kMaxFinite)) {
      const double a = neg_x ? detail::k3Pio4 : detail::kPio4;
      return neg_y ? -a : a;
    }
    const double a = neg_x ? detail::kPi : 0.0;
    return neg_y ? -a : a;
  }
  if (!(ay <= detail::kMaxFinite)) return neg_y ? -detail::kPio2 : detail::kPio2;
  // |y/x| > 2^60: pi/2 to double precision, whatever the sign of x.
  if (ay > 0x1p60 * ax) return neg_y ? -detail::kPio2 : detail::kPio2;
  double z;
  if (ay < 0x1p-60 * ax) {
    // atan(q) == q == y/x correctly rounded for x > 0; pi - tiny rounds to pi for x < 0.
    if (neg_x) return neg_y ? -detail::kPi : detail::kPi;
    z = ay / ax;
  } else {
    // Scale by a power of two (exact) so that the residual below cannot overflow or underflow.
    if (ax > 0x1p500) {
      ax *= 0x1p-600;
      ay *= 0x1p-600;
    } else if (ax < 0x1p-500) {
      ax *= 0x1p600;
      ay *= 0x1p600;
    }
    // y/x = q + e with e = (y - q x) / x, and atan(q + e) ~= atan(q) + e / (1 + q^2): without
    // this correction the rounding of q alone can cost a whole ulp of the result. For x < 0 the
    // angle is pi - atan(|y/x|), which atan_plus evaluates with a single rounding too.
    const double q = ay / ax;
    z = detail::atan_plus(q, detail::division_residual(ay, ax, q) / (ax + q * ay), neg_x);
  }
  return neg_y ? -z : z;
}

/// acos(x) in [0, pi] within 1 ulp, x clamped to [-1, 1] first (NaN gives NaN).
inline double acos(double x) {
  // fdlibm e_acos.c. The clamp is for the angle between two unit vectors: a dot product that
  // rounding pushed just past +-1 gives 0 or pi, not NaN.
  constexpr double pS0 = 0x1.5555555555555p-3, pS1 = -0x1.4d61203eb6f7dp-2,
                   pS2 = 0x1.9c1550e884455p-3, pS3 = -0x1.48228b5688f3bp-5,
                   pS4 = 0x1.9efe07501b288p-11, pS5 = 0x1.23de10dfdf709p-15;
  constexpr double qS1 = -0x1.33a271c8a2d4bp+1, qS2 = 0x1.02ae59c598ac8p+1,
                   qS3 = -0x1.6066c1b8d0159p-1, qS4 = 0x1.3b8c5b12e9282p-4;
  // asin(s) = s + s * z * R(z) with z = s^2, R = p/q.
  const auto ratio = [&](double z) {
    const double p = z * (pS0 + z * (pS1 + z * (pS2 + z * (pS3 + z * (pS4 + z * pS5)))));
    const double q = 1.0 + z * (qS1 + z * (qS2 + z * (qS3 + z * qS4)));
    return p / q;
  };
  if (x != x) return x + x;
  if (x >= 1.0) return 0.0;
  if (x <= -1.0) return detail::kPi;
  if (std::fabs(x) < 0.5) {
    if (std::fabs(x) <= 0x1p-57) return detail::kPio2;
    const double r = ratio(x * x);
    return detail::kPio2 - (x - (detail::kPio2Lo - x * r));  // pi/2 - asin(x)
  }
  if (x < 0) {  // pi - 2 asin(sqrt((1 + x) / 2))
    const double z = (1.0 + x) * 0.5;
    const double s = std::sqrt(z);
    const double w = ratio(z) * s - detail::kPio2Lo;
    return detail::kPi - 2.0 * (s + w);
  }
  // 2 asin(sqrt((1 - x) / 2)), with sqrt split as df + c, df holding the top 21 bits exactly.
  const double z = (1.0 - x) * 0.5;
  const double s = std::sqrt(z);
  const double df = detail::from_bits(detail::bits_of(s) & 0xFFFFFFFF00000000ull);
  const double c = (z - df * df) / (s + df);
  const double w = ratio(z) * s + c;
  return 2.0 * (df + w);
}

/// The natural logarithm within 1 ulp (fdlibm e_log.c, as musl ships it): log(+-0) = -Inf,
/// log(x < 0) = NaN, log(+Inf) = +Inf, log(1) = +0. The Gaussian and bridge samplers take normal
/// deviates by Marsaglia's polar method, whose log must give the same bits in both builds.
inline double log(double x) {
  constexpr double ln2_hi = 0x1.62e42fee00000p-1, ln2_lo = 0x1.a39ef35793c76p-33;
  constexpr double Lg1 = 0x1.5555555555593p-1, Lg2 = 0x1.999999997fa04p-2, Lg3 = 0x1.2492494229359p-2,
                   Lg4 = 0x1.c71c51d8e78afp-3, Lg5 = 0x1.7466496cb03dep-3, Lg6 = 0x1.39a09d078c69fp-3,
                   Lg7 = 0x1.2f112df3e5244p-3;
  std::uint64_t u = detail::bits_of(x);
  auto hx = static_cast<std::uint32_t>(u >> 32);
  int k = 0;
  if (hx < 0x00100000u || (hx >> 31) != 0) {
    if ((u << 1) == 0) return -1.0 / (x * x);  // log(+-0) = -Inf
    if ((hx >> 31) != 0) return (x - x) / 0.0;  // log(negative) = NaN
    k -= 54;  // subnormal: scale up
    x *= 0x1p54;
    u = detail::bits_of(x);
    hx = static_cast<std::uint32_t>(u >> 32);
  } else if (hx >= 0x7ff00000u) {
    return x;  // +Inf or NaN
  } else if (hx == 0x3ff00000u && (u << 32) == 0) {
    return 0.0;
  }
  // x = 2^k (1 + f) with 1 + f in [sqrt(2)/2, sqrt(2)].
  hx += 0x3ff00000u - 0x3fe6a09eu;
  k += static_cast<int>(hx >> 20) - 0x3ff;
  hx = (hx & 0x000fffffu) + 0x3fe6a09eu;
  x = detail::from_bits((static_cast<std::uint64_t>(hx) << 32) | (u & 0xffffffffull));
  const double f = x - 1.0;
  const double hfsq = 0.5 * f * f;
  const double s = f / (2.0 + f);
  const double z = s * s;
  const double w = z * z;
  const double t1 = w * (Lg2 + w * (Lg4 + w * Lg6));
  const double t2 = z * (Lg1 + w * (Lg3 + w * (Lg5 + w * Lg7)));
  const double R = t2 + t1;
  const double dk = k;
  return s * (hfsq + R) + dk * ln2_lo - hfsq + f + dk * ln2_hi;
}

}  // namespace csl::det
