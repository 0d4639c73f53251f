// The RNG: pinned outputs (the same numbers natively and in wasm; this file runs in both) and
// the statistics a uniform generator must have.
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "core/base/rng.hpp"

TEST_CASE("the generator's first outputs are pinned, in every build") {
  csl::Rng r(42);
  CHECK(r.next_u64() == 0x15780b2e0c2ec716ull);
  CHECK(r.next_u64() == 0x6104d9866d113a7eull);
  CHECK(r.next_u64() == 0xae17533239e499a1ull);
  CHECK(r.next_u64() == 0xecb8ad4703b360a1ull);

  csl::Rng q(7);
  CHECK(q.uniform01() == 0.7005764821796896);
  CHECK(q.uniform(-1.0, 3.0) == 0.11500491789513712);
  CHECK(q.below(10) == 8);
}

TEST_CASE("reseeding restarts the sequence; different seeds differ") {
  csl::Rng a(123), b(124);
  const auto first = a.next_u64();
  CHECK(first != b.next_u64());
  a.next_u64();
  a.reseed(123);
  CHECK(a.next_u64() == first);
}

TEST_CASE("uniform01 stays in [0,1) and is uniform (chi-square over 20 bins)") {
  csl::Rng r(2024);
  constexpr int kBins = 20, kDraws = 200000;
  std::array<int, kBins> count{};
  for (int i = 0; i < kDraws; ++i) {
    const double u = r.uniform01();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    ++count[static_cast<std::size_t>(u * kBins)];
  }
  double chi2 = 0;
  const double expected = double(kDraws) / kBins;
  for (int c : count) chi2 += (c - expected) * (c - expected) / expected;
  // 19 degrees of freedom: P(chi2 > 43.8) = 0.001. The seed is fixed, so this is not flaky.
  CHECK(chi2 < 43.8);
}

TEST_CASE("below(n) is unbiased and in range") {
  csl::Rng r(99);
  std::array<int, 3> count{};
  for (int i = 0; i < 30000; ++i) {
    const auto v = r.below(3);
    REQUIRE(v < 3);
    ++count[static_cast<std::size_t>(v)];
  }
  for (int c : count) CHECK(std::abs(c - 10000) < 400);  // > 5 standard deviations
}
