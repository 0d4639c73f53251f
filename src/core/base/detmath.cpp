// The slow path of detmath.hpp: argument reduction for huge |x| (>= 2^20 * pi/2), where the
// three-part Cody-Waite split of pi/2 runs out of bits. The lab never gets here with real angles,
// but sin and cos stay correct for every double, and in integer arithmetic the result is the same
// in every build by construction.
#include "core/base/detmath.hpp"

namespace csl::det::detail {
namespace {

__extension__ typedef unsigned __int128 u128;  // GCC and Clang (wasm32 too) have it

// The binary expansion of 2/pi: word i holds bits 64i+1 .. 64i+64 after the binary point
// (2/pi = 0.A2F9836E4E441529FC27...h; fdlibm's ipio2 table, repacked). 1280 bits; the largest
// double needs bits up to about 1230.
constexpr std::uint64_t kTwoOverPi[20] = {
    0xa2f9836e4e441529ull, 0xfc2757d1f534ddc0ull, 0xdb6295993c439041ull, 0xfe5163abdebbc561ull,
    0xb7246e3a424dd2e0ull, 0x06492eea09d1921cull, 0xfe1deb1cb129a73eull, 0xe88235f52ebb4484ull,
    0xe99c7026b45f7e41ull, 0x3991d639835339f4ull, 0x9c845f8bbdf9283bull, 0x1ff897ffde05980full,
    0xef2f118b5a0a6d1full, 0x6d367ecf27cb09b7ull, 0x4f463f669e5fea2dull, 0x7527bac7ebe5f17bull,
    0x3d0739f78a5292eaull, 0x6bfb5fb11f8d5d08ull, 0x56033046fc7b6babull, 0xf0cfbc209af4361dull,
};

// pi/2 * 2^127, rounded to an integer: 128 bits.
constexpr std::uint64_t kPio2FixedHi = 0xc90fdaa22168c234ull;
constexpr std::uint64_t kPio2FixedLo = 0xc4c6628b80dc1cd1ull;

// 64 bits of the little-endian multi-word number p starting at bit position pos.
std::uint64_t bits_at(const std::uint64_t* p, int pos) {
  const int word = pos / 64, shift = pos % 64;
  if (shift == 0) return p[word];
  return (p[word] >> shift) | (p[word + 1] << (64 - shift));
}

// 2^k as a double, for -1022 <= k <= 1023.
double pow2(int k) { return from_bits(static_cast<std::uint64_t>(1023 + k) << 52); }

int count_leading_zeros(u128 v) {
  const auto hi = static_cast<std::uint64_t>(v >> 64);
  if (hi != 0) return __builtin_clzll(hi);
  return 64 + __builtin_clzll(static_cast<std::uint64_t>(v));
}

}  // namespace

int rem_pio2_large(double x, double& y0, double& y1) {
  // |x| = m * 2^e with m a 53-bit integer; here e >= -32 since |x| >= 2^20.
  const std::uint64_t xb = bits_of(x);
  const std::uint64_t m = (xb & ((1ull << 52) - 1)) | (1ull << 52);
  const int e = static_cast<int>((xb >> 52) & 0x7FF) - 1075;

  // |x| * 2/pi = sum over k of m * b_k * 2^(e-k). Terms with k <= e - 2 are multiples of 4 and
  // do not change the quadrant or the remainder: start at the word holding bit e - 1 and take 256
  // bits. What is cut off at the far end adds less than m * 2^-point < 2^-138 (point below).
  const int first_bit = e - 1 > 1 ? e - 1 : 1;
  const int w0 = (first_bit - 1) / 64;
  std::uint64_t p[6] = {};  // m * (words w0 .. w0+3): 309 bits at most, little-endian
  u128 carry = 0;
  for (int i = 0; i < 4; ++i) {
    const u128 t = static_cast<u128>(m) * kTwoOverPi[w0 + 3 - i] + carry;
    p[i] = static_cast<std::uint64_t>(t);
    carry = t >> 64;
  }
  p[4] = static_cast<std::uint64_t>(carry);
  // |x| * 2/pi == p * 2^-point (mod 4), with 191 <= point <= 288.
  const int point = 64 * w0 + 256 - e;
  int n = static_cast<int>(bits_at(p, point) & 3);
  u128 f = (static_cast<u128>(bits_at(p, point - 64)) << 64) | bits_at(p, point - 128);

  // The fraction f * 2^-128 in [0, 1); take it to [-1/2, 1/2) so that |remainder| <= pi/4.
  bool negative = false;
  if ((f >> 127) != 0) {
    f = 0 - f;
    n += 1;
    negative = true;
  }
  if (f == 0) {  // cannot happen for a double (pi is irrational), but stay total
    y0 = y1 = 0.0;
  } else {
    // Normalise, multiply by pi/2 in 128-bit fixed point, keep the top 128 bits of the product:
    // remainder = f * 2^-(128+lz) * pio2 * 2^-127 ~= top * 2^-(127+lz).
    const int lz = count_leading_zeros(f);
    f <<= lz;
    const auto a1 = static_cast<std::uint64_t>(f >> 64), a0 = static_cast<std::uint64_t>(f);
    const u128 lolo = static_cast<u128>(a0) * kPio2FixedLo;
    const u128 hilo = static_cast<u128>(a1) * kPio2FixedLo;
    const u128 lohi = static_cast<u128>(a0) * kPio2FixedHi;
    const u128 hihi = static_cast<u128>(a1) * kPio2FixedHi;
    const u128 mid =
        (lolo >> 64) + static_cast<std::uint64_t>(hilo) + static_cast<std::uint64_t>(lohi);
    const u128 top = hihi + (hilo >> 64) + (lohi >> 64) + (mid >> 64);  // >= 2^126
    const auto th = static_cast<std::uint64_t>(top >> 64), tl = static_cast<std::uint64_t>(top);
    // Split into doubles, every conversion exact (integers below 2^53, powers of two): the top
    // 53 bits, then the next 64 (one rounding), then renormalise (Fast2Sum, |hi| >= |lo|).
    const double hi = static_cast<double>(th >> 11) * pow2(-52 - lz);
    const double lo = (static_cast<double>(th & 0x7FF) * 0x1p53 + static_cast<double>(tl >> 11)) *
                      pow2(-116 - lz);
    y0 = hi + lo;
    y1 = lo - (y0 - hi);
  }
  // x = sign * (n * pi/2 + r): a negative x reduces to -n and -r.
  if (negative != sign_bit(x)) {
    y0 = -y0;
    y1 = -y1;
  }
  return sign_bit(x) ? -n : n;
}

}  // namespace csl::det::detail
