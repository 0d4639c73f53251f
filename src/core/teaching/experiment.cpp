#include "core/teaching/experiment.hpp"

#include "core/base/params.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/planning/graph.hpp"

namespace csl {

double proven_edge_clearance(const CollisionWorld& world, const Config& p, const Config& q, double eta_p,
                             double eta_q, int max_evaluations) {
  // On a piece from x to y the clearance at q(t) is at least eta_x - t lambda and
  // eta_y - (1 - t) lambda (the robot moves at most that far), whose larger is smallest where
  // they meet, (eta_x + eta_y - lambda) / 2, or at an end. A piece whose bound could lower the
  // least so far, by more than 1% of it, is halved at a computed clearance, as the bisection
  // checker halves: the bound is then close to the truth wherever the edge passes an obstacle,
  // within the budget of clearances computed.
  const auto piece_bound = [](double x, double y, double lambda) {
    return std::fabs(x - y) <= lambda ? 0.5 * (x + y - lambda) : std::max(x, y) - lambda;
  };
  struct Piece {
    double t0, t1, eta0, eta1;
  };
  const Space& space = world.space();
  const double lambda = world.motion_bound(p, q);
  const Config delta = space.difference(p, q);
  double least = std::min(eta_p, eta_q);
  std::vector<Piece> pieces = {{0.0, 1.0, eta_p, eta_q}};
  int evaluations = 0;
  while (!pieces.empty()) {
    const Piece piece = pieces.back();
    pieces.pop_back();
    const double bound = piece_bound(piece.eta0, piece.eta1, lambda * (piece.t1 - piece.t0));
    if (bound >= least) continue;  // cannot lower the least
    if (evaluations >= max_evaluations || least - bound <= 0.01 * least) {
      least = bound;
      continue;
    }
    const double t = 0.5 * (piece.t0 + piece.t1);
    const double eta = world.clearance(space.along(p, delta, t));
    ++evaluations;
    least = std::min(least, eta);
    pieces.push_back({piece.t0, t, piece.eta0, eta});
    pieces.push_back({t, piece.t1, eta, piece.eta1});
  }
  return least;
}

double proven_path_clearance(const CollisionWorld& world, const std::vector<Config>& path, int max_evaluations) {
  if (path.empty()) return std::numeric_limits<double>::infinity();
  double eta = world.clearance(path.front()), least = eta;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double next = world.clearance(path[i + 1]);
    least = std::min(least, proven_edge_clearance(world, path[i], path[i + 1], eta, next, max_evaluations));
    eta = next;
  }
  return least;
}

std::vector<int> widest_path(const CollisionWorld& world, const Roadmap& roadmap) {
  const auto& v = roadmap.vertices;
  const int n = static_cast<int>(v.size());
  if (n < 2) return {};
  std::vector<double> eta(roadmap.clearance);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::isnan(eta[i])) eta[i] = world.clearance(v[i]);
  // Each edge's least clearance, from below (at most 4 clearances an edge: all are measured).
  std::vector<GraphEdge> graph;
  std::vector<double> width;
  std::vector<int> order;
  for (const RoadmapEdge& e : roadmap.edges) {
    // A connector's edge is no straight line: its pieces are not what this bound measures.
    if (!e.alive || !roadmap.waypoints(e).empty()) continue;
    const auto a = static_cast<std::size_t>(e.a), b = static_cast<std::size_t>(e.b);
    order.push_back(static_cast<int>(graph.size()));
    graph.push_back({e.a, e.b, e.length});
    width.push_back(proven_edge_clearance(world, v[a], v[b], eta[a], eta[b], 4));  // all edges: cheap
  }
  // The bottleneck: the widest edges first until start and goal meet (ties by order added).
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
    return width[static_cast<std::size_t>(x)] > width[static_cast<std::size_t>(y)];
  });
  UnionFind sets(n);
  double bottleneck = -std::numeric_limits<double>::infinity();
  for (int i : order) {
    sets.unite(graph[static_cast<std::size_t>(i)].a, graph[static_cast<std::size_t>(i)].b);
    if (sets.find(0) == sets.find(1)) {
      bottleneck = width[static_cast<std::size_t>(i)];
      break;
    }
  }
  if (sets.find(0) != sets.find(1)) return {};
  // The shortest path on edges at least that wide.
  const Config& goal = v[1];
  return shortest_path(
      n, graph, [&](int i) { return width[static_cast<std::size_t>(i)] >= bottleneck; }, 0, 1,
      [&](int u) { return world.space().distance(v[static_cast<std::size_t>(u)], goal); });
}

double free_fraction(const CollisionWorld& world, long samples, Rng& rng) {
  long free = 0;
  for (long i = 0; i < samples; ++i) free += world.is_free(world.space().sample(rng));
  return samples > 0 ? static_cast<double>(free) / static_cast<double>(samples) : 0.0;
}

Experiment::Experiment(const CollisionWorld& world, Config start, Config goal, ExperimentParams params)
    : world_(&world), start_(std::move(start)), goal_(std::move(goal)), params_(std::move(params)) {
  if (params_.sample_counts.empty()) throw std::invalid_argument("the list of sample counts is empty");
  // The ranges and texts of their one description (core/base/params.hpp).
  for (int n : params_.sample_counts)
    if (!in_range(kExperimentSamples, n)) throw std::invalid_argument(param_error(kExperimentSamples));
  if (!in_range(kExperimentTrials, params_.trials)) throw std::invalid_argument(param_error(kExperimentTrials));
  if (params_.reference_samples == 0)
    params_.reference_samples =
        std::max(2000, 4 * *std::max_element(params_.sample_counts.begin(), params_.sample_counts.end()));
  params_.reference_samples = std::min(params_.reference_samples, kMaxPrmSamples);
  for (int n : params_.sample_counts) {
    ExperimentRow row;
    row.samples = n;
    rows_.push_back(row);
  }
}

std::uint64_t Experiment::trial_seed(std::size_t row, int trial) const {
  Rng mixer(params_.seed ^ (static_cast<std::uint64_t>(row) << 32) ^ static_cast<std::uint64_t>(trial));
  return mixer.next_u64();
}

void Experiment::run_reference() {
  PrmParams p;
  p.samples = params_.reference_samples;
  p.neighbors = params_.neighbors;
  p.checker = params_.checker;
  p.seed = params_.seed ^ 0x5eed5eed5eed5eedull;
  Prm prm(*world_, start_, goal_, p);
  prm.run();
  const Space& space = world_->space();
  reference_.samples = p.samples;
  reference_.dimension = space.dim();
  Rng rng(params_.seed ^ 0xf4eef4eef4eef4eeull);
  reference_.free_fraction = free_fraction(*world_, params_.volume_samples, rng);
  reference_.free_volume = reference_.free_fraction * space.volume();
  reference_.path_exists = prm.solved();
  if (prm.solved()) {
    // The bound holds for any free path, and its r counts exponentially: measure the roadmap's
    // widest path, not PRM's shortest, which hugs the obstacles' corners (in the wall-gap
    // scene it passed the wall's end at a clearance of 0.005, where the gap allows 0.05).
    // (The widest by what 4 clearances an edge prove; where PRM's own path proves clearer, that.)
    // Its r is proven too, not sampled: a sampled least clearance can only be too large, and
    // the bound holds for a path of clearance r, not of about r.
    const auto measure = [&](const std::vector<int>& vertices) {
      ExperimentReference m;
      for (int v : vertices) {
        const Config& q = prm.roadmap().vertices[static_cast<std::size_t>(v)];
        if (!m.path.empty()) m.path_length += space.distance(m.path.back(), q);
        m.path.push_back(q);
      }
      m.workspace_clearance = std::max(0.0, proven_path_clearance(*world_, m.path, kReferenceProofEvaluations));
      return m;
    };
    ExperimentReference best = measure(prm.path());
    if (const std::vector<int> wide = widest_path(*world_, prm.roadmap()); !wide.empty()) {
      ExperimentReference widest = measure(wide);
      if (widest.workspace_clearance > best.workspace_clearance) best = std::move(widest);
    }
    reference_.path = std::move(best.path);
    reference_.path_length = best.path_length;
    reference_.workspace_clearance = best.workspace_clearance;
    reference_.clearance = reference_.workspace_clearance / motion_lipschitz(world_->robot());
  }
  const bool bound = reference_.path_exists && reference_.clearance > 0 && reference_.path_length > 0 &&
                     reference_.free_volume > 0;
  for (ExperimentRow& row : rows_) {
    row.has_bound = bound;
    if (bound)
      row.bound = path_tiling_bound(reference_.path_length, reference_.clearance, reference_.dimension,
                                    reference_.free_volume, row.samples);
  }
  reference_done_ = true;
}

void Experiment::step() {
  if (done()) return;
  if (!reference_done_) {
    run_reference();
    return;
  }
  ExperimentRow& row = rows_[next_row_];
  const std::uint64_t seed = trial_seed(next_row_, next_trial_);
  PlannerFactory make;
  if (params_.planner) {
    make = params_.planner(row.samples, seed);
  } else {
    PrmParams p;
    p.samples = row.samples;
    p.neighbors = params_.neighbors;
    p.checker = params_.checker;
    p.sampler = params_.sampler;
    p.seed = seed;
    make = prm_factory(p);
  }
  const std::unique_ptr<Planner> planner = make(*world_, start_, goal_);
  planner->run();
  ++row.trials;
  row.failures += !planner->solved();
  row.configurations_tested += planner->configurations_tested();
  row.failure_rate = wilson_interval(row.failures, row.trials);
  if (++next_trial_ == params_.trials) {
    next_trial_ = 0;
    ++next_row_;
  }
}

void Experiment::run() {
  while (!done()) step();
}

double Experiment::progress() const {
  const double total = 1.0 + static_cast<double>(rows_.size()) * params_.trials;
  const double finished = (reference_done_ ? 1.0 : 0.0) + static_cast<double>(next_row_) * params_.trials + next_trial_;
  return finished / total;
}

}  // namespace csl
