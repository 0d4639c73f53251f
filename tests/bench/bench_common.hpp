#pragma once
// Shared pieces of the benchmarks: the disk worlds they run in, the scenes the planner benches
// race OMPL on, a timer, medians, and the report.
// Benchmarks print figures and ratios against a peer measured in the same run; they assert
// nothing about time (ctest runs them only in a quick mode, to keep them working).
#include <algorithm>
#include <cmath>
#include <limits>
#include <chrono>
#include <functional>
#include <cstdio>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

#include "core/base/rng.hpp"
#include "core/checking/collision.hpp"
#include "core/planning/tree_planner.hpp"

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

/// A scene of the planner benchmarks (prm, rrt, lazy): a name for the table and our world.
struct PlannerScene {
  std::string name;
  csl::CollisionWorld world;
  /// The edge checks' resolution both sides use: 1% of the extent (space_extent(): OMPL's own
  /// default fraction of its extent), an absolute D (bench_ompl.hpp says how OMPL takes it).
  double resolution() const { return 0.01 * csl::space_extent(world.space()); }
};

/// The scenes, one per kind of C-space the lab has: the point among 20 disks (R^2), the 2-link
/// arm among 6 (T^2), and with `all` a polygon robot among 12 disks (SE(2)) and a 4-link arm
/// among the 2-link arm's 6 disks (T^4). All in the unit square.
inline std::vector<PlannerScene> planner_scenes(bool all) {
  std::vector<PlannerScene> out;
  out.push_back({"point, 20 disks, R^2", csl::CollisionWorld(csl::PointRobot{}, random_disks(7, 20), {0, 0}, {1, 1})});
  out.push_back({"2-link arm, 6 disks, T^2",
                 csl::CollisionWorld(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, random_disks(11, 6, 0.03, 0.06), {0, 0}, {1, 1})});
  if (!all) return out;
  // An arrow 0.14 long and 0.06 wide: it must turn to pass between some disks.
  const csl::Polygon arrow = {{-0.07, -0.03}, {0.03, -0.03}, {0.07, 0.0}, {0.03, 0.03}, {-0.07, 0.03}};
  out.push_back({"polygon, 12 disks, SE(2)",
                 csl::CollisionWorld(csl::make_polygon_robot(arrow), random_disks(13, 12, 0.03, 0.07), {0, 0}, {1, 1})});
  out.push_back({"4-link arm, 6 disks, T^4",
                 csl::CollisionWorld(csl::ArmRobot{{0.5, 0.5}, {0.15, 0.12, 0.1, 0.08}}, random_disks(11, 6, 0.03, 0.06),
                                     {0, 0}, {1, 1})});
  return out;
}

/// The first free configuration a sampler seeded with `seed` draws.
inline csl::Config first_free(const csl::CollisionWorld& world, std::uint64_t seed) {
  csl::Rng rng(seed);
  for (;;) {
    const csl::Config q = world.space().sample(rng);
    if (world.is_free(q)) return q;
  }
}

/// The median of v (NaN when empty): the benches report medians of repeated runs, as the machine
/// is shared and one disturbed run moves a mean (or a sum) by several times.
inline double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

#ifdef __EMSCRIPTEN__
// The process's CPU seconds (user and system) as node counts them.
EM_JS(double, node_cpu_seconds, (), {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1e6;
});
#endif

/// Seconds since construction. Natively the process's CPU time, not the wall clock: the machine
/// is shared (two cores, several builds at once), and a bench that got a tenth of a core took ten
/// times as long by the clock (15 s of wall time for 1.3 s of CPU) while its CPU time hardly
/// moved. Every contender here runs on one thread, OMPL's too, so CPU time is its time alone.
/// In the wasm build node's process.cpuUsage() (Emscripten's clock_gettime knows no CPU clock):
/// it also counts V8's compiler threads, which the benches' warm-up runs leave idle.
class Timer {
 public:
  Timer() : start_(now()) {}
  double seconds() const { return now() - start_; }

 private:
  static double now() {
#if defined(__EMSCRIPTEN__)
    return node_cpu_seconds();
#elif !defined(CLOCK_PROCESS_CPUTIME_ID)
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
#else
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
#endif
  }
  double start_;
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
