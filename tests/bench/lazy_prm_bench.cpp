// Lazy PRM: our LazyPrm and OMPL's LazyPRM in the same run, per solved query and per collision
// check.
//
//   cspacelab_bench_lazy [--quick] [--json]
//
// Scenes: bench_common.hpp's planner_scenes() (R^2, T^2, SE(2), T^4), one query each (the first
// free configurations of seeds 1 and 2). Both planners use the k = 10 nearest neighbours, without
// a distance bound, the same validity function (our CollisionWorld::is_free, counted) and the same
// edge-check resolution D (1% of the extent): OMPL's DiscreteMotionValidator with D
// (bench_ompl.hpp), our step:D checker.
// The two do not spend a budget of n samples alike: ours draws n samples, connects them all, then
// searches (Bohlin and Kavraki's order); OMPL's LazyPRM adds milestones one at a time and stops at
// its first proven path, after a few dozen at most, whatever n is (here: at n milestones at the
// latest, a termination condition on its milestone count, never on time). So at n = 1000 ours
// built a roadmap twenty times OMPL's. The ratio compares equal work: OMPL against ours@m, ours
// with m samples, the milestones OMPL took on average (less start and goal), per solved query
// counting the time of the runs that failed (ours@m fails some: so few samples may not connect). The row "ours" at n
// shows what the budget n costs ours, with OMPL / ours at n in brackets for reference.
// Reported: microseconds per solved query (the median over the runs that
// solved), per collision check (the median of a run's time over the configurations it tested: a
// sample, a point along an edge, or for ours a clearance), the checks per query, and the ratio
// OMPL / ours. It fails (exit 1) when a planner solves fewer than half of its queries (the
// figures would compare failures). With --json it runs ours alone and prints its rows for
// compare_wasm.mjs (built for wasm, without OMPL, it always runs ours alone).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "core/planning/lazy_prm.hpp"

#ifdef CSPACELAB_WITH_OMPL
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "bench_ompl.hpp"
#endif

namespace {

// One run's figures, or (add()) a contender's runs. Reported as medians over runs: the machine is
// shared, and a mean (or a sum) lets one disturbed run move a row by 10x.
struct Result {
  double seconds = 0;  ///< one run
  int runs = 0, solved = 0;
  long checks = 0;      ///< configurations tested (all runs)
  long milestones = 0;  ///< all runs
  std::vector<double> query_us, check_us;  ///< per run: its time if solved; its time per check
  double total_us = 0;                      ///< all runs, solved or not

  double us_per_query() const { return bench::median(query_us); }
  double us_per_check() const { return bench::median(check_us); }
  /// What one solved query costs when a failed run is tried again: all the time over the runs
  /// that solved. The median above leaves out the runs that failed, which flatters a planner
  /// that fails often (ours@m, with OMPL's few samples, solves 10 to 20 of 20).
  double us_per_solved() const { return solved ? total_us / solved : std::numeric_limits<double>::infinity(); }
  void add(const Result& r) {
    runs += r.runs;
    solved += r.solved;
    total_us += 1e6 * r.seconds;
    checks += r.checks;
    milestones += r.milestones;
    if (r.solved) query_us.push_back(1e6 * r.seconds);
    if (r.checks) check_us.push_back(1e6 * r.seconds / static_cast<double>(r.checks));
  }
};

Result ours(const csl::CollisionWorld& world, const csl::Config& start, const csl::Config& goal, int samples, double step,
            std::uint64_t seed) {
  csl::PrmParams p;
  p.samples = samples;
  p.neighbors = csl::NeighborRule::parse("k:10");
  char spec[64];
  std::snprintf(spec, sizeof spec, "step:%.17g", step);
  p.checker = csl::EdgeCheckerSpec::parse(spec);
  p.seed = seed;
  Result r;
  bench::Timer timer;
  csl::LazyPrm lazy(world, start, goal, p);
  lazy.run();
  r.seconds = timer.seconds();
  r.runs = 1;
  r.solved = lazy.solved() ? 1 : 0;
  // Every configuration given to the checker (samples, the edge checks' points, clearances,
  // the endpoints): what OMPL's validity checker counts of its own.
  r.checks = static_cast<long>(lazy.configurations_tested());
  r.milestones = static_cast<long>(lazy.roadmap().vertices.size());
  return r;
}

#ifdef CSPACELAB_WITH_OMPL
namespace ob = ompl::base;
namespace og = ompl::geometric;

Result ompl_lazy(const bench::OmplScene& s, const csl::Config& start, const csl::Config& goal, int samples) {
  Result r;
  const long before = s.checks();
  bench::Timer timer;
  auto pdef = std::make_shared<ob::ProblemDefinition>(s.si());
  ob::ScopedState<> a(s.si()->getStateSpace()), b(s.si()->getStateSpace());
  s.to_state(start, a.get());
  s.to_state(goal, b.get());
  pdef->setStartAndGoalStates(a, b);
  og::LazyPRM planner(s.si());
  planner.setProblemDefinition(pdef);
  // OMPL 1.5.2's LazyPRM joins a milestone to its k nearest *within the planner's range*
  // (KBoundedStrategy), which setup() sets to 20% of the space's extent unless given. Ours takes
  // the k nearest at any distance: an unbounded range makes OMPL's rule ours. (With the default
  // range, on T^2 at n = 1000 OMPL's roadmap had 2.2 edges per milestone and needed 55 of them.)
  planner.setRange(std::numeric_limits<double>::max());
  planner.setup();
  // After setup(): setMaxNearestNeighbors() before it left no milestone connected (range 0).
  planner.setMaxNearestNeighbors(10);
  const auto status = planner.solve(ob::PlannerTerminationCondition(
      [&] { return static_cast<long>(planner.milestoneCount()) >= samples + 2; }));
  r.seconds = timer.seconds();
  r.runs = 1;
  r.solved = status == ob::PlannerStatus::EXACT_SOLUTION ? 1 : 0;
  r.checks = s.checks() - before;
  r.milestones = static_cast<long>(planner.milestoneCount());
  return r;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  const bool quick = bench::quick(argc, argv);
  bool as_json = false;
  for (int i = 1; i < argc; ++i) as_json = as_json || std::strcmp(argv[i], "--json") == 0;
  const std::vector<int> sizes = quick ? std::vector<int>{300} : std::vector<int>{300, 1000, 5000};
  const int repeats = quick ? 2 : 20;
#ifdef CSPACELAB_WITH_OMPL
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(1);
#endif
  const std::vector<bench::PlannerScene> scenes = bench::planner_scenes(true);
#ifdef CSPACELAB_WITH_OMPL
  std::vector<std::unique_ptr<bench::OmplScene>> ompl;
  for (const bench::PlannerScene& s : scenes)
    ompl.push_back(std::make_unique<bench::OmplScene>(s.world, s.resolution()));
#endif

  // Untimed runs first, for a second at least (wasm tiers its code up while it runs, compiling in
  // threads node's clock counts, see prm_bench.cpp; natively the caches).
  if (!quick) {
    const bench::Timer warm;
    for (int round = 0; round < 2 || warm.seconds() < 1.0; ++round)
      for (const bench::PlannerScene& s : scenes)
        ours(s.world, bench::first_free(s.world, 1), bench::first_free(s.world, 2), 1000, s.resolution(),
             1000 + static_cast<std::uint64_t>(round));
  }

  if (!as_json) {
    std::printf("Lazy PRM, one query per scene, k = 10, edge checks every 1%% of the extent, medians of %d runs each, "
                "in turns\n", repeats);
    std::printf("%-26s %6s %-6s %6s %9s %11s %11s %9s %11s\n", "scene", "n", "who", "solved", "miles/run", "us/query",
                "us/check", "checks/q", "ratio");
  }
  int bad = 0;
  std::string json;
  for (std::size_t si = 0; si < scenes.size(); ++si) {
    const bench::PlannerScene& s = scenes[si];
    const csl::Config start = bench::first_free(s.world, 1), goal = bench::first_free(s.world, 2);
    const double step = s.resolution();
    for (int n : sizes) {
      Result mine, theirs;
      for (int r = 0; r < repeats; ++r) {
        mine.add(ours(s.world, start, goal, n, step, 1 + static_cast<std::uint64_t>(r)));
#ifdef CSPACELAB_WITH_OMPL
        if (!as_json) theirs.add(ompl_lazy(*ompl[si], start, goal, n));
#endif
      }
      bad += 2 * mine.solved < mine.runs;
      if (as_json) {
        // compare_wasm.mjs's fields: ours_us (per solved query); milestones and checks over all runs,
        // which a deterministic build repeats to the unit.
        char row[400];
        std::snprintf(row, sizeof row,
                      "%s{\"scene\": \"%s\", \"samples\": %d, \"milestones\": %ld, \"checks\": %ld, \"ours_us\": %.3f, "
                      "\"ours_ns_check\": %.3f}",
                      json.empty() ? "" : ", ", s.name.c_str(), n, mine.milestones, mine.checks, mine.us_per_query(),
                      1e3 * mine.us_per_check());
        json += row;
        continue;
      }
      const auto row = [&](int size, const char* who, const Result& x, const char* ratio) {
        std::printf("%-26s %6d %-6s %3d/%-2d %9.1f %11.1f %11.4f %9.0f %11s\n", s.name.c_str(), size, who, x.solved,
                    x.runs, static_cast<double>(x.milestones) / x.runs, x.us_per_query(), x.us_per_check(),
                    x.solved ? static_cast<double>(x.checks) / x.runs : 0.0, ratio);
      };
#ifndef CSPACELAB_WITH_OMPL
      row(n, "ours", mine, "");
#else
      if (!theirs.runs) {
        row(n, "ours", mine, "");
        continue;
      }
      bad += 2 * theirs.solved < theirs.runs;
      // Equal work (see the top): ours with m samples, m from OMPL's runs so far, in turns with OMPL
      // again (its runs of both rounds make its row).
      const int m = std::max(1, static_cast<int>(std::lround(static_cast<double>(theirs.milestones) / theirs.runs)) - 2);
      Result same;
      for (int r = 0; r < repeats; ++r) {
        same.add(ours(s.world, start, goal, m, step, 1 + static_cast<std::uint64_t>(r)));
        theirs.add(ompl_lazy(*ompl[si], start, goal, n));
      }
      char ratio[48];
      std::snprintf(ratio, sizeof ratio, "(%.1fx/%.1fx)", theirs.us_per_query() / mine.us_per_query(),
                    theirs.us_per_check() / mine.us_per_check());
      row(n, "ours", mine, ratio);
      std::snprintf(ratio, sizeof ratio, "%.1fx/%.1fx", theirs.us_per_solved() / same.us_per_solved(),
                    theirs.us_per_check() / same.us_per_check());
      row(n, "OMPL", theirs, ratio);
      row(m, "ours@m", same, "");
#endif
    }
  }
  if (as_json) {
    std::printf("[%s]\n", json.c_str());
    return bad ? 1 : 0;
  }
  std::printf("(miles/run: milestones per run; us/query: median time of a solved query; us/check: median time per\n"
              " configuration tested; checks/q: configurations tested per run; ratio: OMPL / ours@m per solved query\n"
              " (all runs' time over the runs that solved: a failed run counts), per check, equal work; ours@m: ours\n"
              " with m samples, the milestones OMPL's took to its first path, less start and goal; in brackets:\n"
              " OMPL / ours with all n samples, which OMPL's never draws)\n");
  if (bad) std::fprintf(stderr, "%d row(s) with fewer than half the queries solved\n", bad);
  return bad ? 1 : 0;
}
