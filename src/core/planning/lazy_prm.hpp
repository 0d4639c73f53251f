#pragma once
// Lazy PRM (Bohlin and Kavraki 2000) as a stepper: the roadmap is built without checking a single
// edge; only the edges of a shortest path are checked, and only when the search proposes them.
//   1. add q_init and q_final to V;
//   2. n draws of the sampler (core/planning/sampler.hpp), each kept if its rule says so;
//   3. for each vertex p, for each close q: add (p, q) to E unchecked;
//   4. search the shortest path from q_init to q_final over the edges not disproved; none: no path;
//   5. check the path's unchecked edges one by one, in order from q_init, with the exact check
//      (bisection, unless params.checker says otherwise); one in collision is removed and the
//      search repeated (4); all free: the path.
// step() does one unit: add an endpoint, draw one sample, find one vertex's close pairs
// (Neighbors), add one of them unchecked (EdgeAdded, no evaluation), search once (PathCandidate,
// NoPath, or PathFound when the path it finds is checked already), check one path edge
// (EdgeChecked, or PathEdgeRemoved), or, with every edge of the candidate checked, declare it the
// path (PathFound). The counters say what a lazy planner saves: edge_checks() counts only the
// edges checked, edges_unchecked() those that were never needed. Deterministic as PRM: run_to(k)
// replays to the identical state.
#include <memory>
#include <string>
#include <vector>

#include "core/checking/edge_check.hpp"
#include "core/planning/graph.hpp"
#include "core/planning/nearest.hpp"
#include "core/planning/nearest_grid.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/prm.hpp"
#include "core/planning/roadmap.hpp"
#include "core/planning/sampler.hpp"

namespace csl {

enum class LazyPrmPhase { Endpoints, Sampling, Connecting, Search, Checking, Done };
const char* phase_name(LazyPrmPhase p);

class LazyPrm final : public Planner {
 public:
  /// PRM's parameters (samples, sampler, neighbours, checker, seed). The checker checks the
  /// path's edges: bisection (the default) proves them free; grid:N or step:D only at their
  /// resolution (for benchmarks against planners that check so). Vertices are joined by straight
  /// lines: a local connector is std::invalid_argument.
  LazyPrm(const CollisionWorld& world, Config start, Config goal, PrmParams params);
  LazyPrm(CollisionWorld&&, Config, Config, PrmParams) = delete;

  const char* name() const override { return "lazy-prm"; }
  const PlannerEvent& step() override;
  void finish_phase() override;
  void reset() override;
  bool done() const override { return phase_ == LazyPrmPhase::Done; }
  long steps() const override { return steps_; }
  LazyPrmPhase phase() const { return phase_; }
  const char* phase_label() const override { return phase_name(phase_); }
  const PlannerEvent& last_event() const override { return event_; }
  double progress() const override;
  std::string describe(const PlannerEvent& e, const Scene& scene) const override;
  const PrmParams& params() const { return params_; }

  const CollisionWorld& world() const override { return *world_; }
  const Roadmap& roadmap() const override { return roadmap_; }
  long edges_alive() const override { return edges_alive_; }
  int components() const override;
  bool solved() const override { return !path_.empty(); }
  const std::vector<int>& path() const override { return path_; }
  std::vector<Config> path_configurations() const override;
  double path_length() const override { return path_length_; }
  long edge_checks() const override { return edge_checks_; }
  long evaluations() const override { return evaluations_; }
  int samples_drawn() const override { return samples_drawn_; }

  /// Per edge of roadmap(): 1 once the exact check has examined it (a removed edge was checked
  /// and found in collision), 0 for an edge no search has needed yet.
  const std::vector<unsigned char>& edge_checked() const { return checked_; }
  const std::vector<unsigned char>* checked_edge_flags() const override { return &checked_; }
  /// Live edges never checked: what Lazy PRM did not have to check.
  long edges_unchecked() const override { return edges_alive_ - checked_alive_; }
  /// The last search's path (vertex indices, q_init first) while its edges are being checked;
  /// path() once proven.
  const std::vector<int>& candidate_path() const { return candidate_; }
  /// The vertex being connected and its close pairs (Connecting phase).
  int connecting_vertex() const { return p_; }
  const std::vector<Neighbor>& candidates() const { return pairs_; }

 private:
  template <bool kEmit>
  void draw_sample();
  void begin_connecting();
  template <bool kEmit>
  void find_pairs();
  template <bool kEmit>
  void add_pair();
  void search();
  void check_next();

  const CollisionWorld* world_;
  Config start_, goal_;
  PrmParams params_;
  Rng rng_;
  Sampler sampler_;
  EdgeChecker checker_;  // params.checker: bisection by default, which proves an edge free
  NeighborIndex index_;
  LazyPrmPhase phase_ = LazyPrmPhase::Endpoints;
  PlannerEvent event_;
  long steps_ = 0;
  Roadmap roadmap_;
  std::vector<unsigned char> checked_;
  int samples_drawn_ = 0;
  int k_ = 0;
  std::vector<NearNeighbor> knn_;
  std::vector<unsigned char> seen_;
  int p_ = -1;
  std::vector<Neighbor> pairs_;
  std::size_t next_pair_ = 0;
  std::vector<Neighbor> scratch_;
  ShortestPaths paths_;                            // the searches' graph: edges removed as checked
  std::vector<double> to_goal_;                    // A*'s heuristic per vertex
  std::vector<int> candidate_, candidate_edges_;  // the last search's path and its edges
  std::size_t next_check_ = 0;                     // first edge of candidate_edges_ not known free
  std::vector<int> path_;
  double path_length_ = 0.0;
  long edge_checks_ = 0, evaluations_ = 0, edges_alive_ = 0, checked_alive_ = 0;
};

/// Makes LazyPrm planners with `params` (how --planner lazy-prm and the lessons get one).
PlannerFactory lazy_prm_factory(PrmParams params);

}  // namespace csl
