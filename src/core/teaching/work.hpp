#pragma once
// How much work a planning request means, before it runs: one measure and one budget for every
// surface (the CLI, links, the page's API, the app's sliders), so that a request that would take
// minutes is refused up front with the reason, wherever it comes from.
//
// The unit is one primitive distance test (CollisionWorld::evaluation_cost() counts them per
// configuration). A roadmap's work is its samples' evaluations, plus its candidate pairs times
// what one edge check is expected to evaluate, plus the neighbour search. These are estimates
// from the parameters alone, deterministic (no clocks), and on the high side for the edges
// (the ends' clearances settle most roadmap edges without a configuration: measured on the
// bundled scenes at n = 2000, bisection evaluates 0.1 to 1.5 configurations per edge).
#include "core/planning/planner_choice.hpp"
#include "core/planning/prm.hpp"
#include "core/planning/tree_planner.hpp"
#include "core/teaching/experiment.hpp"

namespace csl {

/// Units a request of the app (a link, the API, a slider) may be expected to take: a few seconds
/// in the browser where every configuration really costs its estimate (50 bands of 256 vertices
/// whose boxes all hold the workspace: 3e9 expected, 2.1 s natively), far less where boxes prune
/// (1000 small polygons: 20 times less). A run is drawn in slices of a frame with its progress
/// and a Cancel, so the page stays responsive whatever it costs.
inline constexpr double kLabMaxWork = 4e9;
/// Candidate pairs a request of the app may be expected to check: about as many as k = 50 with
/// the most samples (20000). The pairs hold memory as well as time (k = 1000 with 20000
/// samples, 2e7 pairs, ran the wasm out of memory); a radius rule's grow with n^2.
inline constexpr double kLabMaxPairs = 1e6;
/// Units the app spends at once, within one frame (an edit's edge checks in the collision
/// lesson, a heat map, a measurement): about 20 ms natively and 40 in the browser at the dense
/// end (a point among overlapping polygons; far less where boxes prune).
inline constexpr double kLabFrameWork = 2e7;
/// The CLI's default limit (--max-work): 25 times the lab's, a minute or so.
inline constexpr double kCliMaxWork = 1e11;

/// Configurations the bisection check is expected to evaluate per roadmap edge: more than the
/// 0.1 to 1.5 measured, as scenes may be more cluttered than the bundled ones.
inline constexpr double kBisectionEvaluationsPerEdge = 2.0;

/// The expected length of a roadmap edge: the radius of the ball around a vertex that holds its
/// k nearest among n + 2 uniform vertices; for a radius rule, the mean distance within r (at most
/// the side of the space).
double expected_edge_length(const Space& space, const NeighborRule& rule, int samples);

/// Configurations one check of an edge of `length` is expected to evaluate with `spec` (the
/// ends known free, as in a roadmap): N - 2 for grid:N, the configurations D apart between the
/// ends for step:D, kBisectionEvaluationsPerEdge for bisection.
double expected_edge_evaluations(const EdgeCheckerSpec& spec, double length);

/// The parts of a planning request's expected work, in units.
struct WorkEstimate {
  double pairs = 0;        ///< candidate pairs (expected_candidate_pairs)
  double per_edge = 0;     ///< units one edge check is expected to take
  double sampling = 0;     ///< the samples' evaluations
  double connecting = 0;   ///< pairs x per_edge
  double neighbours = 0;   ///< the neighbour search
  double total() const { return sampling + connecting + neighbours; }
};
/// What PRM with `params` on `world` is expected to cost.
WorkEstimate expected_prm_work(const CollisionWorld& world, const PrmParams& params);

/// A tree planner's (core/planning/tree_planner.hpp) expected work: per sample, its new end
/// and `edges_per_sample` edge checks of length D (RRT: 1; RRT-Connect's connect adds more;
/// the CLI counts 2), and a nearest-vertex search.
WorkEstimate expected_tree_work(const CollisionWorld& world, const TreeParams& params, double edges_per_sample);
/// The edge checks per sample to price a tree planner with: RRT 1 (and its new end); RRT-Connect
/// 1 plus its connect's steps toward a vertex about half the space away, extent / (2 D).
double tree_edges_per_sample(const Space& space, const TreeParams& params, bool connect);
/// What the tree planner `choice` names (RRT or RRT-Connect: planner_kind_info(kind).tree) is
/// expected to cost on `world`: expected_tree_work() of tree_params(choice), with
/// tree_edges_per_sample()'s edges for its kind. The one price of a tree run that the CLI's plan
/// and experiment and the compare lesson hold against their budgets. std::invalid_argument for
/// a roadmap planner (expected_prm_work prices those).
WorkEstimate expected_tree_work(const CollisionWorld& world, const PlannerChoice& choice);

/// An experiment's expected work (experiment.hpp), in units.
struct ExperimentWork {
  double reference = 0;    ///< its first step: the reference run, the proof of its path's clearance, the volume
  double largest_run = 0;  ///< its dearest single step (the first, or a run of the largest n)
  double total = 0;        ///< all of it: the first step and `trials` runs for each n
};
/// What Experiment(world, ..., params) is expected to cost, with params.reference_samples as
/// given (the experiment's own default applies when it is 0: pass Experiment::params()).
ExperimentWork expected_experiment_work(const CollisionWorld& world, const ExperimentParams& params);

/// One check of the edge p -> q with `spec` from scratch (the ends evaluated too): its expected
/// units. Grid and step checkers: exactly their configurations times the evaluation cost;
/// bisection: at most bisection_evaluation_limit().
double expected_check_work(const CollisionWorld& world, const EdgeCheckerSpec& spec, const Config& p, const Config& q);

/// Work as short text for messages: "3.2e9 units".
std::string work_text(double units);

}  // namespace csl
