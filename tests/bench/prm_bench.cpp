// Roadmap construction time per milestone: our PRM and OMPL's PRM in the same run.
//
//   cspacelab_bench_prm [--quick] [--json]
//
// Scenes: bench_common.hpp's planner_scenes(false): the point robot among 20 disks in [0,1]^2,
// and the 2-link arm on T^2 among 6 disks. Both planners use k = 10 nearest neighbours, the same
// validity function (our CollisionWorld::is_free) and the same edge-check resolution D (1% of the
// extent): OMPL's DiscreteMotionValidator with D (bench_ompl.hpp), our step:D checker with that
// very D (on R^2 it tests the same configurations along an edge). OMPL's PRM is driven by a milestone-count termination
// condition, never by time. Reported: microseconds per milestone and the ratio OMPL / ours.
// It fails (exit 1) when the runs disagree (see disagreements()): ctest's quick run checks that.
// Built for wasm (without OMPL) it reports our figures alone, for the wasm/native ratio
// (tests/bench/compare_wasm.mjs runs both).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "core/planning/prm.hpp"

#ifdef CSPACELAB_WITH_OMPL
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/util/Console.h>

#include "bench_ompl.hpp"
#endif

namespace {

struct Result {
  double seconds = 0;
  long milestones = 0;
  long edges = 0;
  std::uint64_t hash = 0;  ///< our roadmap's (0 for OMPL's)
  double us_per_milestone() const { return 1e6 * seconds / static_cast<double>(milestones); }
};

// Our PRM up to the end of the connect phase (the roadmap), as the homework builds it: phase by
// phase as the CLI and experiments run it, or (`stepped`) one step() at a time with an event
// per step, as the lessons animate it. Both build the identical roadmap for a seed. One timed run.
Result ours(const csl::CollisionWorld& world, const csl::Config& start, const csl::Config& goal, int samples,
            double step, std::uint64_t seed, bool stepped = false) {
  csl::PrmParams p;
  p.samples = samples;
  p.neighbors = csl::NeighborRule::parse("k:10");
  char spec[64];
  std::snprintf(spec, sizeof spec, "step:%.17g", step);
  p.checker = csl::EdgeCheckerSpec::parse(spec);
  p.seed = seed;
  Result r;
  bench::Timer timer;
  csl::Prm prm(world, start, goal, p);
  while (prm.phase() != csl::PrmPhase::Query && !prm.done()) {
    if (stepped)
      prm.step();
    else
      prm.finish_phase();
  }
  r.seconds = timer.seconds();
  r.milestones = static_cast<long>(prm.roadmap().vertices.size());
  r.edges = prm.edges_alive();
  r.hash = csl::roadmap_hash(prm.roadmap());
  return r;
}

// The faster of two runs: per milestone, since runs with different seeds grow slightly
// different roadmaps.
bool faster_per_milestone(const Result& a, const Result& b) { return a.us_per_milestone() < b.us_per_milestone(); }

#ifdef CSPACELAB_WITH_OMPL
namespace ob = ompl::base;
namespace og = ompl::geometric;

// OMPL's PRM grown until it has `milestones` milestones. One timed run.
Result ompl_prm(const ob::SpaceInformationPtr& si, long milestones) {
  Result r;
  bench::Timer timer;
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  ob::ScopedState<> s(si->getStateSpace()), g(si->getStateSpace());
  si->getStateSpace()->copyState(s.get(), si->allocState());
  og::PRM prm(si);
  prm.setMaxNearestNeighbors(10);
  pdef->setStartAndGoalStates(s, g);  // unused by growRoadmap, required by setup()
  prm.setProblemDefinition(pdef);
  prm.setup();
  prm.growRoadmap(
      ob::PlannerTerminationCondition([&] { return static_cast<long>(prm.milestoneCount()) >= milestones; }));
  r.seconds = timer.seconds();
  r.milestones = static_cast<long>(prm.milestoneCount());
  r.edges = static_cast<long>(prm.edgeCount());
  return r;
}
#endif

// Our PRM's seed in the repeat r. A run repeated with the same seed repeats every branch, which
// the CPU's branch predictor partly learns (ours took 0.67-0.69 us per milestone at n = 1000
// repeating seed 1, 0.81-0.93 with a new seed per run), while OMPL's PRM draws new samples every
// run. Fresh samples for both: the bench times unseen roadmaps.
std::uint64_t seed_of(int r) { return 1 + static_cast<std::uint64_t>(r); }

struct Row {
  std::string scene;
  int samples;
  Result reference;  ///< our run with seed 1: its milestones (OMPL grows as many) and edges
  Result ours, stepped, ompl;
};

// A scene of the bench: our world with a free start and goal (they only seed our roadmap;
// OMPL's grows on its own), the edge-check resolution both use, and natively OMPL's view of it.
struct Scene {
  std::string name;
  const csl::CollisionWorld* world = nullptr;
  csl::Config start, goal;
  double step = 0.0;  ///< the edge checks' resolution (bench::PlannerScene::resolution())
#ifdef CSPACELAB_WITH_OMPL
  std::shared_ptr<bench::OmplScene> ompl;
#endif
};

Scene scene(const bench::PlannerScene& p) {
  Scene s;
  s.name = p.name;
  s.world = &p.world;
  s.start = bench::first_free(p.world, 1);
  s.goal = bench::first_free(p.world, 2);
  s.step = p.resolution();
#ifdef CSPACELAB_WITH_OMPL
  s.ompl = std::make_shared<bench::OmplScene>(p.world, s.step);
#endif
  return s;
}

// What the runs must agree on, or the figures compare different work: the roadmap built phase
// by phase and the one built step by step (the same seed: identical, to the bit), OMPL's
// milestones and ours (it grows until it has as many), and edges per milestone of the same
// order (k = 10 both; OMPL also joins pairs that only one side has among its k nearest, so it
// has more, not several times more or fewer). Each disagreement is printed; main() fails on any.
int disagreements(const Scene& s, const Row& row) {
  int bad = 0;
  const Result stepped = ours(*s.world, s.start, s.goal, row.samples, s.step, 1, true);
  if (stepped.hash != row.reference.hash || stepped.edges != row.reference.edges) {
    std::fprintf(stderr, "%s, n = %d: stepping built another roadmap than phase by phase (%ld vs %ld edges)\n",
                 row.scene.c_str(), row.samples, stepped.edges, row.reference.edges);
    ++bad;
  }
  if (row.ompl.milestones) {
    if (row.ompl.milestones < row.reference.milestones || row.ompl.milestones > row.reference.milestones + 1) {
      std::fprintf(stderr, "%s, n = %d: OMPL grew %ld milestones, ours %ld\n", row.scene.c_str(), row.samples,
                   row.ompl.milestones, row.reference.milestones);
      ++bad;
    }
    const double ratio = static_cast<double>(row.ompl.edges) / static_cast<double>(std::max(1L, row.reference.edges));
    if (!(ratio >= 0.8 && ratio <= 2.5)) {
      std::fprintf(stderr, "%s, n = %d: OMPL has %ld edges, ours %ld\n", row.scene.c_str(), row.samples,
                   row.ompl.edges, row.reference.edges);
      ++bad;
    }
  }
  return bad;
}

// One row: our PRM phase by phase and stepped, and OMPL's, n samples, in turns.
Row measure(const Scene& s, int n, int repeats) {
  Row row{s.name, n, {}, {}, {}, {}};
  row.reference = ours(*s.world, s.start, s.goal, n, s.step, 1);
  std::vector<std::function<Result(int)>> contenders = {
      [&](int r) { return ours(*s.world, s.start, s.goal, n, s.step, seed_of(r)); },
      [&](int r) { return ours(*s.world, s.start, s.goal, n, s.step, seed_of(r), true); }};
#ifdef CSPACELAB_WITH_OMPL
  contenders.push_back([&](int) { return ompl_prm(s.ompl->si(), row.reference.milestones); });
#endif
  const std::vector<Result> best = bench::best_in_turns(repeats, contenders, faster_per_milestone);
  row.ours = best[0];
  row.stepped = best[1];
  if (best.size() > 2) row.ompl = best[2];
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = bench::quick(argc, argv);
  bool as_json = false;
  for (int i = 1; i < argc; ++i) as_json = as_json || std::strcmp(argv[i], "--json") == 0;
  const std::vector<int> sizes = quick ? std::vector<int>{300} : std::vector<int>{1000, 5000, 20000};
  const int repeats = quick ? 1 : 9;  // a few seconds in all; the fastest of 9 is steadier
#ifdef CSPACELAB_WITH_OMPL
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
#endif

  const std::vector<bench::PlannerScene> worlds = bench::planner_scenes(false);
  std::vector<Scene> scenes;
  for (const bench::PlannerScene& w : worlds) scenes.push_back(scene(w));

  // Untimed runs first, both ways, for a second: under node, V8 compiles wasm with its
  // baseline compiler and tiers a function up only after it has run a while, compiling in the
  // background, and the optimised code serves the calls after that. One run of each scene (as
  // before) left the first rows on the baseline code: wasm took 1.6x its time per milestone at
  // n = 1000 of that at 5000. A second by the clock is a warm-up, not a budget of the planner;
  // natively it only warms the caches.
  if (!quick) {
    const bench::Timer warm;
    for (int round = 0; round < 2 || warm.seconds() < 1.0; ++round)
      for (const Scene& s : scenes) {
        ours(*s.world, s.start, s.goal, 1000, s.step, 1000 + round);
        ours(*s.world, s.start, s.goal, 1000, s.step, 1000 + round, true);
      }
  }

  std::vector<Row> rows;
  int bad = 0;
  for (const Scene& s : scenes)
    for (int n : sizes) {
      rows.push_back(measure(s, n, repeats));
      bad += disagreements(s, rows.back());
    }

  if (as_json) {
    std::printf("[");
    for (std::size_t i = 0; i < rows.size(); ++i)
      std::printf("%s{\"scene\": \"%s\", \"samples\": %d, \"milestones\": %ld, \"ours_us\": %.4f, \"stepped_us\": %.4f, \"ompl_us\": %s}",
                  i ? ", " : "", rows[i].scene.c_str(), rows[i].samples, rows[i].reference.milestones,
                  rows[i].ours.us_per_milestone(), rows[i].stepped.us_per_milestone(),
                  rows[i].ompl.milestones ? std::to_string(rows[i].ompl.us_per_milestone()).c_str() : "null");
    std::printf("]\n");
    return bad ? 1 : 0;
  }
  std::printf("Roadmap construction, k = 10, matching edge-check resolution, best of %d runs taken in turns\n", repeats);
  std::printf("%-26s %7s %10s %11s %11s %11s %10s %10s %7s\n", "scene", "samples", "milestones", "ours us/ms", "stepped",
              "OMPL us/ms", "ours edges", "OMPL edges", "ratio");
  for (const Row& r : rows) {
    std::printf("%-26s %7d %10ld %11.3f %11.3f ", r.scene.c_str(), r.samples, r.reference.milestones, r.ours.us_per_milestone(),
                r.stepped.us_per_milestone());
    if (r.ompl.milestones)
      std::printf("%11.3f %10ld %10ld %6.1fx\n", r.ompl.us_per_milestone(), r.reference.edges, r.ompl.edges,
                  r.ompl.us_per_milestone() / r.ours.us_per_milestone());
    else
      std::printf("%11s %10ld %10s %7s\n", "-", r.reference.edges, "-", "-");
  }
  std::printf("(us/ms: microseconds per milestone; ours: phase by phase, as the CLI runs it; stepped: one step()\n"
              " and its event at a time, as a lesson animates it; ratio: OMPL's time per milestone / ours;\n"
              " milestones and ours edges: our roadmap with seed 1, the runs timed use seeds 1, 2, ...)\n");
  if (bad) std::fprintf(stderr, "%d disagreement(s): the figures above compare different work\n", bad);
  return bad ? 1 : 0;
}
