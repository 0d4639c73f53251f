#pragma once
// RRT-Connect (Kuffner and LaValle 2000) as a stepper on the planner interface: two trees, from
// q_init and from q_final (core/planning/tree_planner.hpp). Each round extends one tree by at
// most D toward a uniform sample (one step); if that adds a vertex, the other tree CONNECTs
// toward it, one extension of at most D per step, until it reaches it (the join: a path) or
// is trapped; then the trees swap roles. Both trees live in one Roadmap, so the component
// colours show two trees until they meet. The goal bias plays no part (the trees grow toward
// each other instead). Budget: the samples drawn; a connect under way when it runs out finishes.
#include "core/planning/tree_planner.hpp"

namespace csl {

class RrtConnect final : public TreePlanner {
 public:
  /// The world must outlive the planner. Throws std::invalid_argument as Rrt does.
  RrtConnect(const CollisionWorld& world, Config start, Config goal, TreeParams params);
  RrtConnect(CollisionWorld&&, Config, Config, TreeParams) = delete;

  const char* name() const override { return "rrt-connect"; }
  std::string describe(const PlannerEvent& e, const Scene& scene) const override;
  /// The tree the next sample extends (0: q_init's, 1: q_final's).
  int extending_tree() const { return a_; }
  /// Whether the other tree is connecting toward connect_target() (the next steps).
  bool connecting() const { return connecting_; }
  int connect_target() const { return target_; }

 private:
  template <bool kEmit>
  void grow();
  void grow_emit() override { grow<true>(); }
  void grow_quiet() override { grow<false>(); }
  bool pending() const override { return connecting_; }
  void reset_growth() override;

  int a_ = 0;              // the tree extended toward the next sample
  bool connecting_ = false;
  int target_ = -1;        // the vertex of tree a_ the other tree connects toward
  int from_ = -1;          // the other tree's vertex the connect extends next (-1: its nearest)
};

/// Makes RrtConnect planners with `params`.
PlannerFactory rrt_connect_factory(TreeParams params);

}  // namespace csl
