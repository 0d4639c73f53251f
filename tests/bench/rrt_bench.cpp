// Tree planners against OMPL's in the same run: our RRT and RRT-Connect (core/planning/rrt.hpp,
// rrt_connect.hpp) and OMPL's RRT and RRTConnect on the same scenes, with the same range D, goal
// bias, edge-check resolution (our step:D checker, which tests configurations at most D apart
// as OMPL's DiscreteMotionValidator does with its resolution), validity test (our
// CollisionWorld::is_free) and sample budget (OMPL's planners stopped by a termination
// condition that counts their iterations: one sample each, never time). Each planner answers the
// same queries (start and goal pairs), a fresh seed per query. Reported per planner: the time
// per solved query, and per collision check (configurations given to the checker: ours
// Planner::configurations_tested(), OMPL's counted in its validity checker), and the ratio OMPL / ours of each: medians over
// `repeats` batches, ours and OMPL's taken in turns. Scenes: bench_common.hpp's planner_scenes()
// (R^2, T^2, SE(2), T^4); OMPL's spaces and checker: bench_ompl.hpp. Last, what the shared
// validity test leaves to win: the ratios were our planner's own work free (is_free_ns), an
// estimate.
// Built for wasm (without OMPL) it reports our figures alone, for the wasm/native ratio
// (tests/bench/compare_wasm.mjs runs both).
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "core/planning/rrt.hpp"
#include "core/planning/rrt_connect.hpp"

#ifdef CSPACELAB_WITH_OMPL
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "bench_ompl.hpp"
#endif

namespace {

// What a batch of queries cost one planner.
struct Result {
  double seconds = 0.0;
  long checks = 0;  ///< configurations evaluated
  int solved = 0;
  int queries = 0;
};

// A contender's batches: medians of its time per solved query and per check.
struct Runs {
  std::vector<Result> batches;
  int solved() const { return batches.empty() ? 0 : batches.front().solved; }
  int queries() const { return batches.empty() ? 0 : batches.front().queries; }
  long checks() const { return batches.empty() ? 0 : batches.front().checks; }
  int least_solved() const {
    int least = queries();
    for (const Result& r : batches) least = std::min(least, r.solved);
    return least;
  }
  double us_per_solved() const {
    std::vector<double> v;
    for (const Result& r : batches)
      if (r.solved) v.push_back(1e6 * r.seconds / r.solved);
    return bench::median(v);
  }
  double ns_per_check() const {
    std::vector<double> v;
    for (const Result& r : batches)
      if (r.checks) v.push_back(1e9 * r.seconds / static_cast<double>(r.checks));
    return bench::median(v);
  }
  double checks_per_solved() const {
    std::vector<double> v;
    for (const Result& r : batches)
      if (r.solved) v.push_back(static_cast<double>(r.checks) / r.solved);
    return bench::median(v);
  }
};

struct Query {
  csl::Config start, goal;
};

// A scene: our world, the queries, D and the check resolution, natively OMPL's view of it.
struct Scene {
  const bench::PlannerScene* scene = nullptr;
  std::vector<Query> queries;
  double range = 0.0;       ///< D, the longest extension (OMPL's default: a fifth of the extent)
  double resolution = 0.0;  ///< the edge check's (bench::PlannerScene::resolution())
  double check_ns = 0.0;    ///< is_free's time per configuration (is_free_ns)
#ifdef CSPACELAB_WITH_OMPL
  std::unique_ptr<bench::OmplScene> ompl;
#endif
};

// Queries whose ends are at least half the extent apart (a query next door says little).
std::vector<Query> queries(const csl::CollisionWorld& world, int count, std::uint64_t seed) {
  csl::Rng rng(seed);
  std::vector<Query> out;
  const double far = 0.5 * csl::space_extent(world.space());
  auto free_config = [&] {
    for (;;) {
      const csl::Config q = world.space().sample(rng);
      if (world.is_free(q)) return q;
    }
  };
  while (static_cast<int>(out.size()) < count) {
    Query q{free_config(), free_config()};
    if (world.space().distance(q.start, q.goal) >= far) out.push_back(std::move(q));
  }
  return out;
}

#ifdef CSPACELAB_WITH_OMPL
// The validity test alone: CollisionWorld::is_free's time per configuration, on uniform samples
// of the space (free and not), median of `repeats` passes. Both planners pay it for every
// configuration they test, so it limits what any planner could gain over OMPL's on a check (an
// estimate: one in collision may stop at its first hit, and the planners test mostly free ones).
double is_free_ns(const csl::CollisionWorld& world, int count, int repeats) {
  csl::Rng rng(11);
  std::vector<csl::Config> qs;
  for (int i = 0; i < count; ++i) qs.push_back(world.space().sample(rng));
  std::vector<double> v;
  static volatile long sink = 0;  // the results are used, so the calls are made
  for (int r = 0; r < repeats; ++r) {
    long free = 0;
    const bench::Timer timer;
    for (const csl::Config& q : qs) free += world.is_free(q);
    v.push_back(1e9 * timer.seconds() / count);
    sink = sink + free;
  }
  return bench::median(v);
}
#endif

Result ours(const Scene& s, bool connect, int samples) {
  Result r;
  csl::TreeParams p;
  p.samples = samples;
  p.step = s.range;
  p.goal_bias = 0.05;
  char spec[64];
  std::snprintf(spec, sizeof spec, "step:%.17g", s.resolution);
  p.checker = csl::EdgeCheckerSpec::parse(spec);
  const csl::CollisionWorld& world = s.scene->world;
  const bench::Timer timer;
  for (std::size_t i = 0; i < s.queries.size(); ++i) {
    p.seed = 1 + i;
    std::unique_ptr<csl::TreePlanner> planner;
    if (connect)
      planner = std::make_unique<csl::RrtConnect>(world, s.queries[i].start, s.queries[i].goal, p);
    else
      planner = std::make_unique<csl::Rrt>(world, s.queries[i].start, s.queries[i].goal, p);
    planner->run();
    r.solved += planner->solved();
    r.checks += planner->configurations_tested();  // as OMPL's validity checker counts
    ++r.queries;
  }
  r.seconds = timer.seconds();
  return r;
}

#ifdef CSPACELAB_WITH_OMPL
namespace ob = ompl::base;
namespace og = ompl::geometric;

Result ompl_run(const Scene& s, bool connect, int samples) {
  Result r;
  const bench::OmplScene& o = *s.ompl;
  const long before = o.checks();
  const bench::Timer timer;
  for (const Query& q : s.queries) {
    auto pdef = std::make_shared<ob::ProblemDefinition>(o.si());
    ob::ScopedState<> start(o.si()->getStateSpace()), goal(o.si()->getStateSpace());
    o.to_state(q.start, start.get());
    o.to_state(q.goal, goal.get());
    pdef->setStartAndGoalStates(start, goal);
    ob::PlannerPtr planner;
    if (connect) {
      auto c = std::make_shared<og::RRTConnect>(o.si());
      c->setRange(s.range);
      planner = c;
    } else {
      auto c = std::make_shared<og::RRT>(o.si());
      c->setRange(s.range);
      c->setGoalBias(0.05);
      planner = c;
    }
    planner->setProblemDefinition(pdef);
    planner->setup();
    long iterations = 0;
    const ob::PlannerStatus status =
        planner->solve(ob::PlannerTerminationCondition([&] { return ++iterations > samples; }));
    r.solved += status == ob::PlannerStatus::EXACT_SOLUTION;
    ++r.queries;
  }
  r.seconds = timer.seconds();
  r.checks = o.checks() - before;
  return r;
}
#endif

struct Row {
  std::string scene, planner;
  double check_ns = 0.0;
  Runs ours, ompl;
};

}  // namespace

int main(int argc, char** argv) {
  const bool quick = bench::quick(argc, argv);
  bool as_json = false;
  for (int i = 1; i < argc; ++i) as_json = as_json || std::strcmp(argv[i], "--json") == 0;
  const int count = quick ? 5 : 100, samples = quick ? 2000 : 20000;
  const int repeats = quick ? 1 : 5;
#ifdef CSPACELAB_WITH_OMPL
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(1);
#endif

  const std::vector<bench::PlannerScene> worlds = bench::planner_scenes(true);
  std::vector<Scene> scenes(worlds.size());
  for (std::size_t i = 0; i < worlds.size(); ++i) {
    Scene& s = scenes[i];
    s.scene = &worlds[i];
    s.queries = queries(s.scene->world, count, 5);
    s.range = csl::tree_step(s.scene->world.space(), 0.0);
    s.resolution = s.scene->resolution();
#ifdef CSPACELAB_WITH_OMPL
    s.check_ns = is_free_ns(s.scene->world, quick ? 1000 : 20000, repeats);
#endif
#ifdef CSPACELAB_WITH_OMPL
    s.ompl = std::make_unique<bench::OmplScene>(s.scene->world, s.resolution);
#endif
  }

  // Untimed runs first, for a second at least (prm_bench.cpp's warm-up): under node V8 runs wasm
  // on its baseline code and tiers a function up only after a while, compiling in background
  // threads whose CPU time node's clock counts. One pass (about 0.15 s) left the first rows on
  // it: R^2 RRT-Connect took 1.8x native's time, T^2 RRT 1.9x, the later rows 1.1x.
  // Natively it only warms the caches.
  if (!quick) {
    const bench::Timer warm;
    for (int round = 0; round < 2 || warm.seconds() < 1.0; ++round)
      for (const Scene& s : scenes) ours(s, false, 2000), ours(s, true, 2000);
  }

  std::vector<Row> rows;
  int bad = 0;
  for (const Scene& s : scenes)
    for (int connect = 0; connect < 2; ++connect) {
      Row row;
      row.scene = s.scene->name;
      row.planner = connect ? "RRT-Connect" : "RRT";
      row.check_ns = s.check_ns;
      // In turns (ours, OMPL's, ours, ...), so that a change in the machine's load hits both.
      for (int r = 0; r < repeats; ++r) {
        row.ours.batches.push_back(ours(s, connect == 1, samples));
#ifdef CSPACELAB_WITH_OMPL
        row.ompl.batches.push_back(ompl_run(s, connect == 1, samples));
#endif
      }
      // Both must solve nearly every query, or the times compare different work.
      const int need = row.ours.queries() * 9 / 10;
      if (row.ours.least_solved() < need || (!row.ompl.batches.empty() && row.ompl.least_solved() < need)) {
        std::fprintf(stderr, "%s, %s: solved ours %d, OMPL %d of %d\n", row.scene.c_str(), row.planner.c_str(),
                     row.ours.least_solved(), row.ompl.least_solved(), row.ours.queries());
        ++bad;
      }
      rows.push_back(std::move(row));
    }

  if (as_json) {
    // compare_wasm.mjs's fields: ours_us (here per solved query); milestones and checks, which
    // a deterministic build repeats to the unit (queries solved, configurations evaluated).
    std::printf("[");
    for (std::size_t i = 0; i < rows.size(); ++i)
      std::printf("%s{\"scene\": \"%s, %s\", \"samples\": %d, \"milestones\": %d, \"checks\": %ld, \"ours_us\": %.3f, "
                  "\"ours_ns_check\": %.3f}",
                  i ? ", " : "", rows[i].scene.c_str(), rows[i].planner.c_str(), samples, rows[i].ours.solved(),
                  rows[i].ours.checks(), rows[i].ours.us_per_solved(), rows[i].ours.ns_per_check());
    std::printf("]\n");
    return bad ? 1 : 0;
  }
  std::printf("Tree planners, %d queries per scene, budget %d samples, D = extent / 5, goal bias 0.05 (RRT),\n"
              "edge checks every 1%% of the extent; medians of %d batches, ours and OMPL's in turns\n",
              count, samples, repeats);
  std::printf("%-26s %-12s %7s %11s %11s %10s %10s %7s %11s %11s %7s\n", "scene", "planner", "solved", "ours us/q",
              "OMPL us/q", "ours chk/q", "OMPL chk/q", "ratio", "ours ns/chk", "OMPL ns/chk", "ratio");
  for (const Row& r : rows) {
    std::printf("%-26s %-12s %3d/%-3d %11.1f ", r.scene.c_str(), r.planner.c_str(), r.ours.solved(), r.ours.queries(),
                r.ours.us_per_solved());
    if (!r.ompl.batches.empty())
      std::printf("%11.1f %10.0f %10.0f %6.1fx %11.2f %11.2f %6.1fx\n", r.ompl.us_per_solved(),
                  r.ours.checks_per_solved(), r.ompl.checks_per_solved(), r.ompl.us_per_solved() / r.ours.us_per_solved(),
                  r.ours.ns_per_check(), r.ompl.ns_per_check(), r.ompl.ns_per_check() / r.ours.ns_per_check());
    else
      std::printf("%11s %10.0f %10s %7s %11.2f %11s %7s\n", "-", r.ours.checks_per_solved(), "-", "-",
                  r.ours.ns_per_check(), "-", "-");
  }
  std::printf("(us/q: microseconds per solved query, a batch's time over the queries it solved; chk/q: configurations\n"
              " evaluated per solved query; ns/chk: time per configuration evaluated; ratios: OMPL's / ours; all\n"
              " medians over the batches)\n");
#ifdef CSPACELAB_WITH_OMPL
  // What the shared validity test leaves to win: were our planner's own work free, a query would
  // still cost its checks (ours chk/q x is_free's time) and a check is_free's time. An estimate:
  // a check's cost depends on the configuration (one in collision may stop at its first hit).
  std::printf("\nThe ratios were our planner's own work free (both call the same is_free), estimated\n");
  std::printf("%-26s %-12s %11s %14s %14s\n", "scene", "planner", "is_free ns", "ratio/q", "ratio/chk");
  for (const Row& r : rows)
    std::printf("%-26s %-12s %11.1f %13.1fx %13.1fx\n", r.scene.c_str(), r.planner.c_str(), r.check_ns,
                1e3 * r.ompl.us_per_solved() / (r.ours.checks_per_solved() * r.check_ns), r.ompl.ns_per_check() / r.check_ns);
  std::printf("(is_free ns: its time per configuration on uniform samples of the space, free and not, standing\n"
              " for each check's; ratio/q: OMPL us/q over ours chk/q x is_free ns; ratio/chk: OMPL ns/chk over\n"
              " is_free ns. Estimates: is_free's cost depends on the configuration (one in collision may stop at\n"
              " its first hit), so both move with the mix a planner tests; and ours counts a clearance it computes\n"
              " (dearer than is_free: it lets the check skip the configurations within it) as one evaluation, so\n"
              " ratio/q leans high. A goal above these needs fewer checks or a cheaper is_free, which OMPL would\n"
              " share)\n");
#endif
  if (bad) std::fprintf(stderr, "%d disagreement(s): the figures above compare different work\n", bad);
  return bad ? 1 : 0;
}
