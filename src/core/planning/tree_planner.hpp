#pragma once
// What RRT and RRT-Connect share (core/planning/rrt.hpp, rrt_connect.hpp): two trees in one
// Roadmap, one rooted at q_init (vertex 0), one at q_final (vertex 1), each edge joining a
// child to its parent, so that the roadmap's drawing, JSON, hash and component colours show the
// trees as they are. RRT grows only the first (the second stays q_final alone until an edge
// joins it); RRT-Connect grows both. A path exists once one edge, the join, links the two trees:
// the tree path from q_init to the join's end in the first tree, the join, and the tree path
// from its other end down to q_final.
//
// The unit of work is one extension (extend()): from a tree vertex toward a target by at most
// the step D, in the space's metric and along its interpolation (so an angle goes the short way
// round, across the seam of S^1), its new end checked, then the edge by the chosen EdgeChecker.
// Steps are deterministic from (world, start, goal, params): the lab's Rng, the space's sampling,
// and nearest vertices by NeighborIndex (ties by smaller index).
// Phases: endpoints (add q_init, then q_final), growing (the derived planner's units), query
// (the found path re-checked with the exact check, as PRM does; an edge that fails is removed,
// the part of its tree below it dropped, and growing goes on), done.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/checking/edge_check.hpp"
#include "core/planning/nearest.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/roadmap.hpp"

namespace csl {

struct TreeParams {
  int samples = 1000;       ///< samples drawn at most (goal draws included): the budget
  double goal_bias = 0.05;  ///< RRT: the chance of extending toward q_final instead
  double step = 0.0;        ///< D, the longest extension; 0: tree_step()'s default
  EdgeCheckerSpec checker;  ///< default: exact bisection
  std::uint64_t seed = 1;
};

/// The space's maximum extent as OMPL measures it: the length of the diagonal of its bounds,
/// an angle's extent pi (half the way round, the farthest two angles are), weighted.
double space_extent(const Space& space);
/// The shortest D a tree planner takes, as a fraction of space_extent(): one RRT-Connect connect
/// then adds at most about a thousand vertices (a D of 1e-9 would add a billion, for ever).
inline constexpr double kMinTreeStepFraction = 1e-3;
/// D itself if > 0 (but at least kMinTreeStepFraction of space_extent()), else a fifth of
/// space_extent() (OMPL's default for its RRTs).
double tree_step(const Space& space, double requested);

enum class TreePhase { Endpoints, Growing, Query, Done };
const char* phase_name(TreePhase p);

class TreePlanner : public Planner {
 public:
  bool done() const override { return phase_ == TreePhase::Done; }
  const PlannerEvent& step() override;
  void finish_phase() override;
  void reset() override;
  long steps() const override { return steps_; }
  TreePhase phase() const { return phase_; }
  const char* phase_label() const override { return phase_name(phase_); }
  const PlannerEvent& last_event() const override { return event_; }
  double progress() const override;

  const TreeParams& params() const { return params_; }
  /// D as used (tree_step() of the params' step).
  double step_size() const { return step_; }
  const CollisionWorld& world() const override { return *world_; }
  const Roadmap& roadmap() const override { return roadmap_; }
  long edges_alive() const override { return edges_alive_; }
  int components() const override;
  bool solved() const override { return !path_.empty(); }
  const std::vector<int>& path() const override { return path_; }
  std::vector<Config> path_configurations() const override;
  double path_length() const override { return path_length_; }
  long edge_checks() const override { return edge_checks_; }
  /// Configurations evaluated: each extension's new end, the edge checks' and the clearances they
  /// needed (not the path's re-check).
  long evaluations() const override { return evaluations_; }
  int samples_drawn() const override { return samples_drawn_; }

  /// The tree vertex v belongs to: 0 (q_init's), 1 (q_final's), or -1 (none: cut off by a
  /// failed re-check). In RRT q_final is tree 1 alone until the join.
  int tree_of(int v) const { return tree_[static_cast<std::size_t>(v)]; }
  /// v's parent in its tree (-1 for a root or a vertex in no tree).
  int parent_of(int v) const { return parent_[static_cast<std::size_t>(v)]; }
  /// The edge joining the trees (index into roadmap().edges), -1 while they are apart.
  int join_edge() const { return join_edge_; }

 protected:
  TreePlanner(const CollisionWorld& world, Config start, Config goal, TreeParams params);

  /// How an extension ended.
  enum class Extension { Advanced, Reached, Trapped };
  /// One unit: extends tree `tree` from its vertex `near` toward `target` by at most D. With
  /// `target_vertex` >= 0 (a vertex of the other tree, at `target`) and the target within D,
  /// the edge near -> target_vertex is checked and, if free, becomes the join: Reached, and the
  /// phase moves to query. Otherwise the new end is checked, then the edge: a new vertex
  /// (Reached if it is the target, else Advanced) or Trapped. `sample`: the sample's number
  /// (1..n) the extension heads for, -1 for none (RRT-Connect's connect). The event (kEmit, or
  /// always for a join, which ends the phase) says what happened.
  template <bool kEmit>
  Extension extend(int tree, int near, const Config& target, int target_vertex, int sample);
  /// The vertex of tree `tree` nearest to q.
  int nearest_in(int tree, const Config& q);
  /// The next sample from the planner's random numbers (Space::sample), counted.
  Config draw_sample() {
    ++samples_drawn_;
    return world_->space().sample(rng_);
  }
  /// Counts a sample drawn otherwise (RRT's goal draws).
  void count_sample() { ++samples_drawn_; }
  Rng& rng() { return rng_; }
  const Config& start() const { return start_; }
  const Config& goal() const { return goal_; }
  /// The derived planner's unit of growing; sets its event if kEmit.
  virtual void grow_emit() = 0;
  virtual void grow_quiet() = 0;
  /// Whether a unit is pending beyond the samples drawn (RRT-Connect's connect).
  virtual bool pending() const = 0;
  /// Back to the derived planner's state before step 1.
  virtual void reset_growth() = 0;

  PlannerEvent event_;
  long steps_ = 0;

 private:
  void add_endpoint();
  void query();
  bool verify_edge(const RoadmapEdge& r, double& collision_t);
  // Removes edge `edge` (a failed re-check): a join is dropped; a tree edge cuts its child's
  // subtree out of the tree (its vertices stay in V, in no tree).
  void remove_edge(int edge);
  // Roadmap vertex of q, free with clearance eta (NaN: not computed), in tree `tree` under
  // `parent` by an edge of `length`; returns it.
  int add_vertex(const Config& q, double eta, int tree, int parent, double length);
  int add_edge(int a, int b, double length);
  void rebuild_index(int tree);
  // An edge near -> q of `length` by the chosen checker, q's clearance eta_q (NaN: not known).
  bool check(int near, const Config& q, double length, double& eta_q, double& collision_t);

  const CollisionWorld* world_;
  Config start_, goal_;
  TreeParams params_;
  double step_;
  Rng rng_;
  EdgeChecker checker_;
  EdgeChecker exact_;
  TreePhase phase_ = TreePhase::Endpoints;
  Roadmap roadmap_;
  std::vector<int> tree_, parent_, parent_edge_;
  std::array<NeighborIndex, 2> index_;
  std::array<std::vector<int>, 2> members_;  // per tree: the index's ids -> vertices
  std::vector<Neighbor> scratch_;
  int samples_drawn_ = 0;
  int join_edge_ = -1;
  std::vector<int> path_;
  std::vector<int> path_edges_;
  double path_length_ = 0.0;
  long edge_checks_ = 0, evaluations_ = 0, edges_alive_ = 0;
};

}  // namespace csl
