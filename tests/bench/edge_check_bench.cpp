// Edge checks per second and evaluations per edge for our checkers on a disk world, and the
// same edges through OMPL's DiscreteMotionValidator in the same run (when OMPL is built in).
//
//   cspacelab_bench_edges [--quick]
//
// The point robot among 20 disks in [0,1]^2; edges of length <= 0.2 between free
// configurations (the kind a roadmap checks). Our step:D checker tests the very configurations
// OMPL's validator tests at the same resolution D (t = j/n, n = ceil(|pq|/D)), both through
// the same validity function, so verdicts must agree exactly and the time ratio measures the
// checking machinery.
#include <cmath>
#include <cstdio>

#include "bench_common.hpp"
#include "core/checking/edge_check.hpp"

#ifdef CSPACELAB_WITH_OMPL
#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#endif

namespace {

struct Edge {
  csl::Config p, q;
  double eta_p, eta_q;  // a roadmap knows its vertices' clearances
};

struct Measure {
  double seconds = 0;
  long evaluations = 0;
  long collisions = 0;
};

// One pass of our checker over all edges, counting into m.
void run_ours(const csl::CollisionWorld& world, const std::vector<Edge>& edges, const csl::EdgeCheckerSpec& spec,
              Measure& m) {
  csl::EdgeChecker checker(world, spec, /*report_clearance=*/false);
  m.evaluations = m.collisions = 0;
  for (const Edge& e : edges) {
    // Roadmap use: endpoints are known free (their clearances only matter to bisection).
    checker.reset(e.p, e.q, true, e.eta_p, e.eta_q);
    while (!checker.done()) checker.step();
    m.evaluations += checker.evaluations();
    m.collisions += checker.verdict() == csl::Verdict::Collision;
  }
}

void report(const char* name, const Measure& m, std::size_t edges, double ompl_seconds) {
  std::printf("%-34s %10.0f edges/s  %7.2f evaluations/edge  %6.2f%% in collision", name,
              static_cast<double>(edges) / m.seconds, static_cast<double>(m.evaluations) / static_cast<double>(edges),
              100.0 * static_cast<double>(m.collisions) / static_cast<double>(edges));
  if (ompl_seconds > 0) std::printf("  %6.2fx OMPL's speed", ompl_seconds / m.seconds);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = bench::quick(argc, argv);
  const int kEdges = quick ? 2000 : 200000;
  const int repeats = quick ? 1 : 5;
  const double kResolution = 0.01;  // OMPL's default: 1% of the space's extent ([0,1]^2: 0.01 * sqrt 2)

  const csl::CollisionWorld world(csl::PointRobot{}, bench::random_disks(7, 20), {0, 0}, {1, 1});
  csl::Rng rng(99);
  std::vector<Edge> edges;
  while (static_cast<int>(edges.size()) < kEdges) {
    const csl::Config p = world.space().sample(rng);
    csl::Config q = world.space().sample(rng);
    const double d = world.space().distance(p, q);
    if (d > 0.2) q = world.space().interpolate(p, q, 0.2 / d);
    if (world.is_free(p) && world.is_free(q)) edges.push_back({p, q, world.clearance(p), world.clearance(q)});
  }

  const double step = kResolution * std::sqrt(2.0);  // OMPL: resolution x the space's extent
  char step_spec[64];
  std::snprintf(step_spec, sizeof step_spec, "step:%.17g", step);
  Measure ours_step, ours_bisection, ours_grid, ompl;
  std::vector<std::function<void()>> contenders = {
      [&] { run_ours(world, edges, csl::EdgeCheckerSpec::parse(step_spec), ours_step); },
      [&] { run_ours(world, edges, csl::EdgeCheckerSpec::parse("bisection"), ours_bisection); },
      [&] { run_ours(world, edges, csl::EdgeCheckerSpec::parse("grid:10"), ours_grid); },
  };

#ifdef CSPACELAB_WITH_OMPL
  namespace ob = ompl::base;
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  space->setBounds(0.0, 1.0);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  long counted = 0;
  si->setStateValidityChecker([&](const ob::State* s) {
    ++counted;
    const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
    return world.is_free(csl::config({v->values[0], v->values[1]}));
  });
  si->setStateValidityCheckingResolution(kResolution);
  si->setMotionValidator(std::make_shared<ob::DiscreteMotionValidator>(si));
  si->setup();
  if (std::fabs(si->getStateValidityCheckingResolution() * space->getMaximumExtent() - step) > 1e-15) {
    std::printf("MISMATCH: OMPL's resolution is not %g\n", step);
    return 1;
  }
  std::vector<ob::State*> a, b;
  for (const Edge& e : edges) {
    a.push_back(si->allocState());
    b.push_back(si->allocState());
    auto* va = a.back()->as<ob::RealVectorStateSpace::StateType>();
    auto* vb = b.back()->as<ob::RealVectorStateSpace::StateType>();
    va->values[0] = e.p[0];
    va->values[1] = e.p[1];
    vb->values[0] = e.q[0];
    vb->values[1] = e.q[1];
  }
  const auto validator = si->getMotionValidator();
  contenders.push_back([&] {
    counted = ompl.collisions = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) ompl.collisions += !validator->checkMotion(a[i], b[i]);
    ompl.evaluations = counted;
  });
#endif

  const std::vector<double> seconds = bench::best_of_interleaved(repeats, contenders);
  ours_step.seconds = seconds[0];
  ours_bisection.seconds = seconds[1];
  ours_grid.seconds = seconds[2];
  const double ompl_seconds = seconds.size() > 3 ? seconds[3] : 0.0;
  ompl.seconds = ompl_seconds;

  std::printf("Edge checks: point robot, 20 disks, %d edges of length <= 0.2, best of %d interleaved runs\n", kEdges,
              repeats);
  report(("ours " + std::string(step_spec).substr(0, 12)).c_str(), ours_step, edges.size(), ompl_seconds);
  report("ours bisection (exact)", ours_bisection, edges.size(), ompl_seconds);
  report("ours grid:10", ours_grid, edges.size(), ompl_seconds);
  if (ompl_seconds > 0) {
    report("OMPL DiscreteMotionValidator", ompl, edges.size(), 0);
    if (ompl.collisions != ours_step.collisions) {
      std::printf("MISMATCH: OMPL found %ld colliding edges, our step checker %ld\n", ompl.collisions,
                  ours_step.collisions);
      return 1;
    }
    std::printf("ratio (our step checker / OMPL, same configurations tested): %.2fx\n", ompl_seconds / ours_step.seconds);
    std::printf("ratio (our exact bisection / OMPL): %.2fx\n", ompl_seconds / ours_bisection.seconds);
  } else {
    std::printf("(OMPL not built in: no peer in this run)\n");
  }
#ifdef CSPACELAB_WITH_OMPL
  for (std::size_t i = 0; i < edges.size(); ++i) {
    si->freeState(a[i]);
    si->freeState(b[i]);
  }
#endif
  if (ours_bisection.collisions < ours_step.collisions) {
    std::printf("MISMATCH: the exact checker found fewer collisions than the grid-like one\n");
    return 1;
  }
  return 0;
}
