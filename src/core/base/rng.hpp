#pragma once
// The lab's own random numbers: xoshiro256** seeded through splitmix64, and our own mapping to
// doubles. std::*_distribution differ between libstdc++ (native) and libc++ (wasm); these do not,
// so a seed gives the same roadmap in both builds.
#include <cstdint>

namespace csl {

class Rng {
 public:
  /// Any seed is fine, including 0: splitmix64 spreads it over the 256-bit state.
  explicit Rng(std::uint64_t seed = 0) { reseed(seed); }

  void reseed(std::uint64_t seed) {
    for (std::uint64_t& word : s_) {
      seed += 0x9E3779B97F4A7C15ull;  // splitmix64 (Steele, Lea, Flood 2014)
      std::uint64_t z = seed;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      word = z ^ (z >> 31);
    }
  }

  /// The next 64 random bits (xoshiro256**, Blackman and Vigna 2018).
  std::uint64_t next_u64() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform in [0, 1): the top 53 bits scaled by 2^-53 (exact, no rounding).
  double uniform01() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

  /// Uniform in [lo, hi] (hi itself only through rounding); lo + (hi - lo) * u.
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

  /// Uniform integer in [0, n), n > 0, without bias (Lemire's multiply-and-reject).
  std::uint64_t below(std::uint64_t n) {
    for (;;) {
      const std::uint64_t x = next_u64();
      const u128 m = static_cast<u128>(x) * n;
      const auto low = static_cast<std::uint64_t>(m);
      if (low >= n || low >= (0 - n) % n) return static_cast<std::uint64_t>(m >> 64);
    }
  }

 private:
  __extension__ typedef unsigned __int128 u128;  // GCC and Clang (wasm32 too) have it
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
};

}  // namespace csl
