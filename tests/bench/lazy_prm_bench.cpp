// Lazy PRM: our LazyPrm and OMPL's LazyPRM in the same run, per solved query and per collision
// check.
//
//   cspacelab_bench_lazy [--quick]
//
// Scenes: those of prm_bench.cpp (the point robot among 20 disks in [0,1]^2, the 2-link arm on
// T^2 among 6 disks), one query each (the first free configurations of seeds 1 and 2). Both
// planners use k = 10 nearest neighbours, the same validity function (our CollisionWorld::is_free,
// counted) and the same edge-check resolution: OMPL's DiscreteMotionValidator at its default 1%
// of the space's extent, our step:D checker with that D. The sample budget is n for both: ours
// draws n samples, then searches and checks; OMPL's LazyPRM adds milestones one at a time and
// stops at its first proven path, or at n milestones (a termination condition on its milestone
// count, never on time). Reported: microseconds per solved query (the median over the runs that
// solved), per collision check (the median of a run's time over the configurations it tested: a
// sample, a point along an edge, or for ours a clearance), the checks per query, and the ratio
// OMPL / ours. It fails (exit 1) when
// a planner solves fewer than half of its queries (the figures would compare failures).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "core/planning/lazy_prm.hpp"

#ifdef CSPACELAB_WITH_OMPL
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
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

  static double median(std::vector<double> v) {
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  }
  double us_per_query() const { return median(query_us); }
  double us_per_check() const { return median(check_us); }
  void add(const Result& r) {
    runs += r.runs;
    solved += r.solved;
    checks += r.checks;
    milestones += r.milestones;
    if (r.solved) query_us.push_back(1e6 * r.seconds);
    if (r.checks) check_us.push_back(1e6 * r.seconds / static_cast<double>(r.checks));
  }
};

csl::Config first_free(const csl::CollisionWorld& world, std::uint64_t seed) {
  csl::Rng rng(seed);
  for (;;) {
    const csl::Config q = world.space().sample(rng);
    if (world.is_free(q)) return q;
  }
}

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
  // Samples tested (each uniform draw tests one) and the edge checks' configurations and clearances.
  r.checks = lazy.samples_drawn() + lazy.evaluations();
  r.milestones = static_cast<long>(lazy.roadmap().vertices.size());
  return r;
}

#ifdef CSPACELAB_WITH_OMPL
namespace ob = ompl::base;
namespace og = ompl::geometric;

struct OmplScene {
  ob::SpaceInformationPtr si;
  std::function<void(const csl::Config&, ob::State*)> to_state;
  long* counter = nullptr;
};

Result ompl_lazy(const OmplScene& s, const csl::Config& start, const csl::Config& goal, int samples) {
  Result r;
  *s.counter = 0;
  bench::Timer timer;
  auto pdef = std::make_shared<ob::ProblemDefinition>(s.si);
  ob::ScopedState<> a(s.si->getStateSpace()), b(s.si->getStateSpace());
  s.to_state(start, a.get());
  s.to_state(goal, b.get());
  pdef->setStartAndGoalStates(a, b);
  og::LazyPRM planner(s.si);
  planner.setProblemDefinition(pdef);
  planner.setup();
  // After setup(): OMPL 1.5.2 bounds the k nearest by the planner's range (KBoundedStrategy),
  // which setup() configures (20% of the space's extent); set before it, the range is still 0
  // and no milestone ever connects.
  planner.setMaxNearestNeighbors(10);
  const auto status = planner.solve(ob::PlannerTerminationCondition(
      [&] { return static_cast<long>(planner.milestoneCount()) >= samples + 2; }));
  r.seconds = timer.seconds();
  r.runs = 1;
  r.solved = status == ob::PlannerStatus::EXACT_SOLUTION ? 1 : 0;
  r.checks = *s.counter;
  r.milestones = static_cast<long>(planner.milestoneCount());
  return r;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  const bool quick = bench::quick(argc, argv);
  const std::vector<int> sizes = quick ? std::vector<int>{300} : std::vector<int>{300, 1000, 5000};
  const int repeats = quick ? 2 : 20;
#ifdef CSPACELAB_WITH_OMPL
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(1);
#endif
  const csl::CollisionWorld disks(csl::PointRobot{}, bench::random_disks(7, 20), {0, 0}, {1, 1});
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, bench::random_disks(11, 6, 0.03, 0.06), {0, 0},
                                {1, 1});
  struct Scene {
    std::string name;
    const csl::CollisionWorld* world = nullptr;
    double step = 0.0;
#ifdef CSPACELAB_WITH_OMPL
    OmplScene ompl;
#endif
  };
  std::vector<Scene> scenes(2);
  scenes[0].name = "point, 20 disks, R^2";
  scenes[0].world = &disks;
  scenes[0].step = 0.01 * std::sqrt(2.0);
  scenes[1].name = "2-link arm, 6 disks, T^2";
  scenes[1].world = &arm;
  scenes[1].step = 0.01 * std::sqrt(2.0) * csl::kPi;
#ifdef CSPACELAB_WITH_OMPL
  static long counters[2];
  {
    auto plane = std::make_shared<ob::RealVectorStateSpace>(2);
    plane->setBounds(0.0, 1.0);
    auto& s = scenes[0].ompl;
    s.si = std::make_shared<ob::SpaceInformation>(plane);
    s.counter = &counters[0];
    s.si->setStateValidityChecker([&disks](const ob::State* st) {
      ++counters[0];
      const auto* v = st->as<ob::RealVectorStateSpace::StateType>();
      return disks.is_free(csl::config({v->values[0], v->values[1]}));
    });
    s.si->setup();
    scenes[0].step = s.si->getStateValidityCheckingResolution() * plane->getMaximumExtent();
    s.to_state = [](const csl::Config& q, ob::State* st) {
      auto* v = st->as<ob::RealVectorStateSpace::StateType>();
      v->values[0] = q[0];
      v->values[1] = q[1];
    };
  }
  {
    auto torus = std::make_shared<ob::CompoundStateSpace>();
    torus->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
    torus->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
    auto& s = scenes[1].ompl;
    s.si = std::make_shared<ob::SpaceInformation>(torus);
    s.counter = &counters[1];
    s.si->setStateValidityChecker([&arm](const ob::State* st) {
      ++counters[1];
      const auto* c = st->as<ob::CompoundStateSpace::StateType>();
      return arm.is_free(csl::config({c->as<ob::SO2StateSpace::StateType>(0)->value,
                                      c->as<ob::SO2StateSpace::StateType>(1)->value}));
    });
    s.si->setup();
    scenes[1].step = s.si->getStateValidityCheckingResolution() * torus->getMaximumExtent();
    s.to_state = [](const csl::Config& q, ob::State* st) {
      auto* c = st->as<ob::CompoundStateSpace::StateType>();
      c->as<ob::SO2StateSpace::StateType>(0)->value = q[0];
      c->as<ob::SO2StateSpace::StateType>(1)->value = q[1];
    };
  }
#endif

  std::printf("Lazy PRM, one query per scene, k = 10, matching edge-check resolution, medians of %d runs each, in turns\n", repeats);
  std::printf("%-26s %6s %-6s %6s %9s %11s %11s %9s %9s\n", "scene", "n", "who", "solved", "miles/run", "us/query",
              "us/check", "checks/q", "ratio");
  int bad = 0;
  for (const Scene& s : scenes) {
    const csl::Config start = first_free(*s.world, 1), goal = first_free(*s.world, 2);
    for (int n : sizes) {
      Result mine, theirs;
      for (int r = 0; r < repeats; ++r) {
        mine.add(ours(*s.world, start, goal, n, s.step, 1 + static_cast<std::uint64_t>(r)));
#ifdef CSPACELAB_WITH_OMPL
        theirs.add(ompl_lazy(s.ompl, start, goal, n));
#endif
      }
      const auto row = [&](const char* who, const Result& x, const char* ratio) {
        std::printf("%-26s %6d %-6s %3d/%-2d %9.1f %11.1f %11.4f %9.0f %9s\n", s.name.c_str(), n, who, x.solved, x.runs,
                    static_cast<double>(x.milestones) / x.runs, x.us_per_query(), x.us_per_check(),
                    x.solved ? static_cast<double>(x.checks) / x.runs : 0.0, ratio);
      };
      row("ours", mine, "");
      bad += 2 * mine.solved < mine.runs;
      if (theirs.runs) {
        char ratio[48];
        std::snprintf(ratio, sizeof ratio, "%.1fx/%.1fx", theirs.us_per_query() / mine.us_per_query(),
                      theirs.us_per_check() / mine.us_per_check());
        row("OMPL", theirs, ratio);
        bad += 2 * theirs.solved < theirs.runs;
        // OMPL's stops at its first proven path, after far fewer than n milestones: ours again with
        // the samples OMPL took on average (its milestones less start and goal), the same budget.
        const int m = std::max(1, static_cast<int>(std::lround(static_cast<double>(theirs.milestones) / theirs.runs)) - 2);
        Result same;
        for (int r = 0; r < repeats; ++r) same.add(ours(*s.world, start, goal, m, s.step, 1 + static_cast<std::uint64_t>(r)));
        std::snprintf(ratio, sizeof ratio, "%.1fx/%.1fx", theirs.us_per_query() / same.us_per_query(),
                      theirs.us_per_check() / same.us_per_check());
        std::printf("%-26s %6d %-6s %3d/%-2d %9.1f %11.1f %11.4f %9.0f %9s\n", s.name.c_str(), m, "ours@m", same.solved,
                    same.runs, static_cast<double>(same.milestones) / same.runs, same.us_per_query(), same.us_per_check(),
                    static_cast<double>(same.checks) / same.runs, ratio);
      }
    }
  }
  std::printf("(miles/run: milestones per run; us/query: median time of a solved query; us/check: median time per\n"
              " configuration tested; checks/q: configurations tested per run; ratio: OMPL / ours per query, per check;\n"
              " ours@m: ours with m samples, the milestones OMPL's took to its first path, less start and goal)\n");
  if (bad) std::fprintf(stderr, "%d row(s) with fewer than half the queries solved\n", bad);
  return bad ? 1 : 0;
}
