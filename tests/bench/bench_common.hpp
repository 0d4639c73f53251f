#pragma once
// Shared pieces of the benchmarks: the disk worlds they run in, a timer, and the report.
// Benchmarks print figures and ratios against a peer measured in the same run; they assert
// nothing about time (ctest runs them only in a quick mode, to keep them working).
#include <algorithm>
#include <chrono>
#include <functional>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/base/rng.hpp"
#include "core/checking/collision.hpp"

namespace bench {

/// `count` disks with centres uniform in [0,1]^2 and radii in [r_lo, r_hi] (seeded).
inline std::vector<csl::Obstacle> random_disks(std::uint64_t seed, int count, double r_lo = 0.03, double r_hi = 0.08) {
  csl::Rng rng(seed);
  std::vector<csl::Obstacle> out;
  for (int i = 0; i < count; ++i) {
    const double x = rng.uniform01(), y = rng.uniform01();
    out.push_back(csl::Disk{{x, y}, rng.uniform(r_lo, r_hi)});
  }
  return out;
}

class Timer {
 public:
  Timer() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

/// Runs f() `repeats` times and returns the fastest time in seconds (least disturbed by noise).
template <class F>
double best_of(int repeats, F&& f) {
  double best = 1e300;
  for (int i = 0; i < repeats; ++i) {
    Timer t;
    f();
    const double s = t.seconds();
    if (s < best) best = s;
  }
  return best;
}

/// Runs several contenders in turns (A B C A B C ...), `repeats` rounds, so that a change in the
/// machine's load during the run hits all of them alike, and keeps each one's best run.
/// Contender i, called with the round's number (0, 1, ...: a seed, say), returns a result R;
/// better(a, b) says whether a beats b.
template <class R, class Better>
std::vector<R> best_in_turns(int repeats, const std::vector<std::function<R(int)>>& contenders, Better better) {
  std::vector<R> best(contenders.size());
  for (int r = 0; r < repeats; ++r)
    for (std::size_t i = 0; i < contenders.size(); ++i) {
      R got = contenders[i](r);
      if (r == 0 || better(got, best[i])) best[i] = std::move(got);
    }
  return best;
}

/// best_in_turns() for contenders that return nothing: each one's fastest time, in seconds.
inline std::vector<double> best_of_interleaved(int repeats, const std::vector<std::function<void()>>& contenders) {
  std::vector<std::function<double(int)>> timed;
  for (const std::function<void()>& c : contenders)
    timed.push_back([&c](int) {
      Timer t;
      c();
      return t.seconds();
    });
  return best_in_turns(repeats, timed, [](double a, double b) { return a < b; });
}

/// Whether the benchmark was started with --quick (ctest's smoke run).
inline bool quick(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--quick") return true;
  return false;
}

}  // namespace bench
