// Tree planners against OMPL's in the same run: our RRT and RRT-Connect (core/planning/rrt.hpp,
// rrt_connect.hpp) and OMPL's RRT and RRTConnect on the same scenes, with the same range D, goal
// bias, edge-check resolution (our step:D checker, which tests configurations at most D apart
// as OMPL's DiscreteMotionValidator does with its resolution), validity test (our
// CollisionWorld::is_free) and sample budget (OMPL's planners stopped by a termination
// condition that counts their iterations: one sample each, never time). Each planner answers the
// same queries (start and goal pairs), a fresh seed per query. Reported per planner: the time
// per solved query, and per collision check (configurations evaluated: ours count their own,
// OMPL's are counted in its validity checker), and the ratio OMPL / ours of each.
// Built for wasm (without OMPL) it reports our figures alone, for the wasm/native ratio
// (tests/bench/compare_wasm.mjs runs both).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "core/base/angles.hpp"
#include "core/planning/rrt.hpp"
#include "core/planning/rrt_connect.hpp"

#ifdef CSPACELAB_WITH_OMPL
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#endif

namespace {

// What a batch of queries cost one planner.
struct Result {
  double seconds = 0.0;
  long checks = 0;  ///< configurations evaluated
  int solved = 0;
  int queries = 0;
  double us_per_solved() const { return solved ? 1e6 * seconds / solved : 0.0; }
  double ns_per_check() const { return checks ? 1e9 * seconds / static_cast<double>(checks) : 0.0; }
};

struct Query {
  csl::Config start, goal;
};

// A scene: our world, the queries, D and the check resolution, natively OMPL's view of it.
struct Scene {
  std::string name;
  const csl::CollisionWorld* world = nullptr;
  std::vector<Query> queries;
  double range = 0.0;  ///< D, the longest extension (OMPL's default: a fifth of the extent)
  double resolution = 0.0;  ///< the edge check's: 1% of the extent (OMPL's default fraction)
#ifdef CSPACELAB_WITH_OMPL
  ompl::base::SpaceInformationPtr si;
  std::function<void(const csl::Config&, ompl::base::State*)> to_state;
  long* counter = nullptr;  // OMPL's validity checks, counted by the checker
#endif
};

csl::Config free_config(const csl::CollisionWorld& world, csl::Rng& rng) {
  for (;;) {
    const csl::Config q = world.space().sample(rng);
    if (world.is_free(q)) return q;
  }
}

// Queries whose ends are at least half the extent apart (a query next door says little).
std::vector<Query> queries(const csl::CollisionWorld& world, int count, std::uint64_t seed) {
  csl::Rng rng(seed);
  std::vector<Query> out;
  const double far = 0.5 * csl::space_extent(world.space());
  while (static_cast<int>(out.size()) < count) {
    Query q{free_config(world, rng), free_config(world, rng)};
    if (world.space().distance(q.start, q.goal) >= far) out.push_back(std::move(q));
  }
  return out;
}

Result ours(const Scene& s, bool connect, int samples) {
  Result r;
  csl::TreeParams p;
  p.samples = samples;
  p.step = s.range;
  p.goal_bias = 0.05;
  p.checker = csl::EdgeCheckerSpec::parse("step:" + std::to_string(s.resolution));
  const bench::Timer timer;
  for (std::size_t i = 0; i < s.queries.size(); ++i) {
    p.seed = 1 + i;
    std::unique_ptr<csl::TreePlanner> planner;
    if (connect)
      planner = std::make_unique<csl::RrtConnect>(*s.world, s.queries[i].start, s.queries[i].goal, p);
    else
      planner = std::make_unique<csl::Rrt>(*s.world, s.queries[i].start, s.queries[i].goal, p);
    planner->run();
    r.solved += planner->solved();
    r.checks += planner->evaluations();
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
  const long before = *s.counter;
  const bench::Timer timer;
  for (const Query& q : s.queries) {
    auto pdef = std::make_shared<ob::ProblemDefinition>(s.si);
    ob::ScopedState<> start(s.si->getStateSpace()), goal(s.si->getStateSpace());
    s.to_state(q.start, start.get());
    s.to_state(q.goal, goal.get());
    pdef->setStartAndGoalStates(start, goal);
    ob::PlannerPtr planner;
    if (connect) {
      auto c = std::make_shared<og::RRTConnect>(s.si);
      c->setRange(s.range);
      planner = c;
    } else {
      auto c = std::make_shared<og::RRT>(s.si);
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
  r.checks = *s.counter - before;
  return r;
}
#endif

struct Row {
  std::string scene, planner;
  Result ours, ompl;
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

  const csl::CollisionWorld disks(csl::PointRobot{}, bench::random_disks(7, 20), {0, 0}, {1, 1});
  const csl::CollisionWorld arm(csl::ArmRobot{{0.5, 0.5}, 0.3, 0.2}, bench::random_disks(11, 6, 0.03, 0.06), {0, 0},
                                {1, 1});
  std::vector<Scene> scenes(2);
  scenes[0].name = "point, 20 disks, R^2";
  scenes[0].world = &disks;
  scenes[1].name = "2-link arm, 6 disks, T^2";
  scenes[1].world = &arm;
  for (Scene& s : scenes) {
    s.queries = queries(*s.world, count, 5);
    s.range = csl::tree_step(s.world->space(), 0.0);
    s.resolution = 0.01 * csl::space_extent(s.world->space());
  }
#ifdef CSPACELAB_WITH_OMPL
  static long counters[2] = {0, 0};
  auto plane = std::make_shared<ob::RealVectorStateSpace>(2);
  plane->setBounds(0.0, 1.0);
  auto torus = std::make_shared<ob::CompoundStateSpace>();  // SO(2) x SO(2)
  torus->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
  torus->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
  const ob::StateSpacePtr spaces[2] = {plane, torus};
  for (int i = 0; i < 2; ++i) {
    Scene& s = scenes[static_cast<std::size_t>(i)];
    s.si = std::make_shared<ob::SpaceInformation>(spaces[i]);
    const csl::CollisionWorld* w = s.world;
    long* counter = &counters[i];
    s.counter = counter;
    if (i == 0) {
      s.si->setStateValidityChecker([w, counter](const ob::State* st) {
        ++*counter;
        const auto* v = st->as<ob::RealVectorStateSpace::StateType>();
        return w->is_free(csl::config({v->values[0], v->values[1]}));
      });
      s.to_state = [](const csl::Config& q, ob::State* st) {
        auto* v = st->as<ob::RealVectorStateSpace::StateType>();
        v->values[0] = q[0];
        v->values[1] = q[1];
      };
    } else {
      s.si->setStateValidityChecker([w, counter](const ob::State* st) {
        ++*counter;
        const auto* c = st->as<ob::CompoundStateSpace::StateType>();
        return w->is_free(csl::config(
            {c->as<ob::SO2StateSpace::StateType>(0)->value, c->as<ob::SO2StateSpace::StateType>(1)->value}));
      });
      s.to_state = [](const csl::Config& q, ob::State* st) {
        auto* c = st->as<ob::CompoundStateSpace::StateType>();
        c->as<ob::SO2StateSpace::StateType>(0)->value = q[0];
        c->as<ob::SO2StateSpace::StateType>(1)->value = q[1];
      };
    }
    // The same absolute edge-check resolution as ours (1% of our extent): OMPL takes it as a
    // fraction of its own extent. (On T^2 OMPL's compound metric sums the angles' distances
    // where ours takes their Euclidean norm: its extent is 2 pi, ours sqrt(2) pi. D and the
    // resolution are the same numbers for both, so OMPL's steps are never longer than ours.)
    s.si->setStateValidityCheckingResolution(s.resolution / spaces[i]->getMaximumExtent());
    s.si->setup();
  }
#endif

  // A warm-up (wasm tiers its code up while it runs; natively the caches).
  if (!quick)
    for (const Scene& s : scenes) ours(s, false, 2000), ours(s, true, 2000);

  std::vector<Row> rows;
  int bad = 0;
  for (const Scene& s : scenes)
    for (int connect = 0; connect < 2; ++connect) {
      Row row;
      row.scene = s.name;
      row.planner = connect ? "RRT-Connect" : "RRT";
      std::vector<std::function<Result(int)>> contenders = {[&](int) { return ours(s, connect == 1, samples); }};
#ifdef CSPACELAB_WITH_OMPL
      contenders.push_back([&](int) { return ompl_run(s, connect == 1, samples); });
#endif
      const auto best = bench::best_in_turns(repeats, contenders, [](const Result& a, const Result& b) {
        return a.seconds < b.seconds;
      });
      row.ours = best[0];
      if (best.size() > 1) row.ompl = best[1];
      // Both must solve nearly every query, or the times compare different work.
      if (row.ours.solved < row.ours.queries * 9 / 10 || (best.size() > 1 && row.ompl.solved < row.ompl.queries * 9 / 10)) {
        std::fprintf(stderr, "%s, %s: solved ours %d, OMPL %d of %d\n", s.name.c_str(), row.planner.c_str(),
                     row.ours.solved, row.ompl.solved, row.ours.queries);
        ++bad;
      }
      rows.push_back(row);
    }

  if (as_json) {
    // compare_wasm.mjs's fields: ours_us (here per solved query); milestones and checks, which
    // a deterministic build repeats to the unit (queries solved, configurations evaluated).
    std::printf("[");
    for (std::size_t i = 0; i < rows.size(); ++i)
      std::printf("%s{\"scene\": \"%s, %s\", \"samples\": %d, \"milestones\": %d, \"checks\": %ld, \"ours_us\": %.3f}",
                  i ? ", " : "", rows[i].scene.c_str(), rows[i].planner.c_str(), samples, rows[i].ours.solved,
                  rows[i].ours.checks, rows[i].ours.us_per_solved());
    std::printf("]\n");
    return bad ? 1 : 0;
  }
  std::printf("Tree planners, %d queries per scene, budget %d samples, D = extent / 5, goal bias 0.05 (RRT),\n"
              "edge checks every 1%% of the extent; best of %d batches taken in turns\n",
              count, samples, repeats);
  std::printf("%-26s %-12s %7s %11s %11s %10s %10s %7s %11s %11s %7s\n", "scene", "planner", "solved", "ours us/q",
              "OMPL us/q", "ours chk/q", "OMPL chk/q", "ratio", "ours ns/chk", "OMPL ns/chk", "ratio");
  for (const Row& r : rows) {
    std::printf("%-26s %-12s %3d/%-3d %11.1f ", r.scene.c_str(), r.planner.c_str(), r.ours.solved, r.ours.queries,
                r.ours.us_per_solved());
    if (r.ompl.queries)
      std::printf("%11.1f %10ld %10ld %6.1fx %11.2f %11.2f %6.1fx\n", r.ompl.us_per_solved(),
                  r.ours.checks / std::max(1, r.ours.solved), r.ompl.checks / std::max(1, r.ompl.solved),
                  r.ompl.us_per_solved() / r.ours.us_per_solved(), r.ours.ns_per_check(), r.ompl.ns_per_check(),
                  r.ompl.ns_per_check() / r.ours.ns_per_check());
    else
      std::printf("%11s %10ld %10s %7s %11.2f %11s %7s\n", "-", r.ours.checks / std::max(1, r.ours.solved), "-", "-",
                  r.ours.ns_per_check(), "-", "-");
  }
  std::printf("(us/q: microseconds per solved query, all queries' time over those solved; chk/q: configurations\n"
              " evaluated per solved query; ns/chk: time per configuration evaluated; ratios: OMPL's / ours)\n");
  if (bad) std::fprintf(stderr, "%d disagreement(s): the figures above compare different work\n", bad);
  return bad ? 1 : 0;
}
