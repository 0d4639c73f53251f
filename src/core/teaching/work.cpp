#include "core/teaching/work.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <cstdio>

#include "core/teaching/analysis.hpp"

namespace csl {

double expected_edge_length(const Space& space, const NeighborRule& rule, int samples) {
  const int d = space.dim();
  if (rule.kind == NeighborRule::Kind::Radius) {
    // Pairs within r lie d / (d + 1) r apart on average (uniform in the ball); no farther than
    // the space allows (the side of a cube of its volume), whatever r says.
    const double side = std::pow(space.volume(), 1.0 / d);
    return std::min(rule.radius, side) * d / (d + 1.0);
  }
  const double n = static_cast<double>(samples) + 2.0;
  const double k = rule.kind == NeighborRule::Kind::Nearest ? rule.k : NeighborRule::prm_star_k(samples + 2, d);
  // k of n uniform points in a ball of volume k / n of the space's.
  return std::pow(std::min(1.0, k / n) * space.volume() / unit_ball_volume(d), 1.0 / d);
}

double expected_edge_evaluations(const EdgeCheckerSpec& spec, double length) {
  switch (spec.kind) {
    case EdgeCheckerSpec::Kind::Grid:
      return spec.resolution - 2.0;
    case EdgeCheckerSpec::Kind::Step:
      return std::max(0.0, std::min(static_cast<double>(kMaxGridResolution), std::ceil(length / spec.step)) - 1.0);
    case EdgeCheckerSpec::Kind::Bisection:
      break;
  }
  return kBisectionEvaluationsPerEdge;
}

WorkEstimate expected_prm_work(const CollisionWorld& world, const PrmParams& params) {
  const Space& space = world.space();
  const double cost = world.evaluation_cost();
  const double n = static_cast<double>(params.samples) + 2.0;
  WorkEstimate w;
  w.pairs = expected_candidate_pairs(space, params.neighbors, params.samples);
  const double evaluations =
      params.connector ? params.connector->expected_evaluations()
                       : expected_edge_evaluations(params.checker, expected_edge_length(space, params.neighbors, params.samples));
  w.per_edge = (1.0 + evaluations) * cost;  // the motion bound and the ends' check count as one
  // A draw of the Gaussian sampler tests 2 configurations, of the bridge test up to 3 (sampler.hpp).
  const double per_draw = params.sampler.kind == SamplerSpec::Kind::Gaussian ? 2.0
                          : params.sampler.kind == SamplerSpec::Kind::Bridge ? 3.0
                                                                              : 1.0;
  w.sampling = n * per_draw * cost;
  w.connecting = w.pairs * w.per_edge;
  // The neighbour search: about one distance per candidate and per vertex (a grid or k-d tree).
  w.neighbours = n + 4.0 * w.pairs;
  return w;
}

WorkEstimate expected_tree_work(const CollisionWorld& world, const TreeParams& params, double edges_per_sample) {
  const double cost = world.evaluation_cost();
  const double n = static_cast<double>(params.samples) + 2.0;
  WorkEstimate w;
  w.pairs = n * edges_per_sample;
  w.per_edge = (1.0 + expected_edge_evaluations(params.checker, tree_step(world.space(), params.step))) * cost;
  w.sampling = n * cost;
  w.connecting = w.pairs * w.per_edge;
  w.neighbours = 20.0 * n;  // a nearest-vertex search per sample: a few dozen distances
  return w;
}

double tree_edges_per_sample(const Space& space, const TreeParams& params, bool connect) {
  return connect ? 1.0 + space_extent(space) / (2.0 * tree_step(space, params.step)) : 1.0;
}

WorkEstimate expected_tree_work(const CollisionWorld& world, const PlannerChoice& choice) {
  if (!planner_kind_info(choice.kind).tree)
    throw std::invalid_argument(std::string(planner_kind_info(choice.kind).name) + " is not a tree planner");
  const TreeParams params = tree_params(choice);
  const bool connect = choice.kind == PlannerChoice::Kind::RrtConnect;
  return expected_tree_work(world, params, tree_edges_per_sample(world.space(), params, connect));
}

ExperimentWork expected_experiment_work(const CollisionWorld& world, const ExperimentParams& params) {
  PrmParams run;
  run.neighbors = params.neighbors;
  run.checker = params.checker;
  run.samples = params.reference_samples;
  ExperimentWork w;
  w.reference = expected_prm_work(world, run).total() +
                (kReferenceProofEvaluations + static_cast<double>(params.volume_samples)) * world.evaluation_cost();
  w.largest_run = w.total = w.reference;
  run.sampler = params.sampler;  // the trials' (the reference run's is uniform)
  for (int n : params.sample_counts) {
    run.samples = n;
    const double one = expected_prm_work(world, run).total();
    w.largest_run = std::max(w.largest_run, one);
    w.total += params.trials * one;
  }
  return w;
}

double expected_check_work(const CollisionWorld& world, const EdgeCheckerSpec& spec, const Config& p, const Config& q) {
  const double cost = world.evaluation_cost();
  if (spec.kind == EdgeCheckerSpec::Kind::Bisection) return bisection_evaluation_limit(world) * cost;
  const EdgeChecker checker(world, spec, false);
  return checker.grid_configurations(world.space().distance(p, q)) * cost;
}

std::string work_text(double units) {
  char text[48];
  std::snprintf(text, sizeof text, "%.2g units", units);
  return text;
}

}  // namespace csl
