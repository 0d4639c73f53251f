#pragma once
// Measuring PRM's failure rate against the bound of section 2.1, a trial at a time (so a UI
// can show progress and cancel between steps).
//
// Failure means start and goal are not connected although a path exists. Whether one exists,
// and its length L and clearance r for the bound, come from a reference run with many more
// samples (first step). mu(F) is estimated by Monte Carlo. The C-space clearance r is the
// workspace clearance eta of the reference path (least over a fine sampling of it) divided by
// the robot's Lipschitz constant K (robot.hpp), which makes it a true lower bound up to that
// sampling.
#include <cstdint>
#include <functional>
#include <vector>

#include "core/planning/planner.hpp"
#include "core/planning/prm.hpp"
#include "core/teaching/analysis.hpp"

namespace csl {

/// Clearances computed along the reference path to prove its least clearance: the path has a
/// few dozen edges, and this budget lets the halving reach its 1% rule.
inline constexpr int kReferenceProofEvaluations = 4096;

struct ExperimentParams {
  std::vector<int> sample_counts;  ///< the n to test, e.g. {50, 100, 200}
  int trials = 20;                 ///< T runs per n
  std::uint64_t seed = 1;
  NeighborRule neighbors;
  EdgeCheckerSpec checker;
  /// PRM's sampler in the trials (the reference run samples uniformly: it measures the scene).
  SamplerSpec sampler;
  int reference_samples = 0;     ///< 0: max(2000, 4 x the largest n)
  long volume_samples = 100000;  ///< Monte Carlo samples for mu(F)
  /// The planner under test, for a trial with n samples and its seed; null: PRM with
  /// `neighbors` and `checker`. (The reference run that measures L and r is always PRM's: it
  /// measures the scene, not the planner.)
  std::function<PlannerFactory(int samples, std::uint64_t seed)> planner;
};

struct ExperimentReference {
  bool path_exists = false;
  int samples = 0;
  std::vector<Config> path;            ///< the path measured: the reference roadmap's widest
  double path_length = 0.0;            ///< L
  double workspace_clearance = 0.0;    ///< least eta along the path, proven (a lower bound)
  double clearance = 0.0;              ///< r = eta / K, in C-space
  double free_fraction = 0.0;          ///< mu(F) / mu(Q), estimated
  double free_volume = 0.0;            ///< mu(F)
  int dimension = 0;                   ///< d
};

struct ExperimentRow {
  int samples = 0;
  int trials = 0;
  int failures = 0;
  /// Configurations the trials' planners gave the collision checker, summed over the trials
  /// (Planner::configurations_tested(): the same measure for every planner).
  long long configurations_tested = 0;
  Proportion failure_rate;  ///< with its 95% interval
  bool has_bound = false;   ///< the reference found a path with positive clearance
  FailureBound bound;
};

class Experiment {
 public:
  /// The world must outlive the experiment.
  Experiment(const CollisionWorld& world, Config start, Config goal, ExperimentParams params);
  Experiment(CollisionWorld&&, Config, Config, ExperimentParams) = delete;

  bool done() const { return next_row_ >= params_.sample_counts.size(); }
  /// The reference run (first call), then one PRM trial per call.
  void step();
  void run();
  /// Fraction of the work done, in [0, 1] (counts trials; the reference counts as one).
  double progress() const;
  const ExperimentReference& reference() const { return reference_; }
  const std::vector<ExperimentRow>& rows() const { return rows_; }
  const ExperimentParams& params() const { return params_; }

 private:
  void run_reference();
  /// A distinct, reproducible seed for trial t at row i.
  std::uint64_t trial_seed(std::size_t row, int trial) const;

  const CollisionWorld* world_;
  Config start_, goal_;
  ExperimentParams params_;
  bool reference_done_ = false;
  ExperimentReference reference_;
  std::vector<ExperimentRow> rows_;
  std::size_t next_row_ = 0;
  int next_trial_ = 0;
};

/// A lower bound on the least clearance eta along the straight edge p -> q (ends' clearances
/// eta_p, eta_q), from the motion bound lambda: pieces are halved, a clearance computed at each
/// cut (at most max_evaluations), until the bound is within 1% of the least found.
double proven_edge_clearance(const CollisionWorld& world, const Config& p, const Config& q, double eta_p,
                             double eta_q, int max_evaluations);
/// The same along a path of straight edges.
double proven_path_clearance(const CollisionWorld& world, const std::vector<Config>& path, int max_evaluations);

/// The roadmap's start-goal path (vertices 0 to 1) whose least clearance is largest, as far as
/// its vertices' clearances and the edges' motion bounds prove, and the shortest of those;
/// empty if start and goal are not connected. (Straight-line edges.)
std::vector<int> widest_path(const CollisionWorld& world, const Roadmap& roadmap);

/// Monte Carlo estimate of the free fraction of the C-space.
double free_fraction(const CollisionWorld& world, long samples, Rng& rng);

}  // namespace csl
