#pragma once
// RRT, the rapidly-exploring random tree (LaValle 1998), as a stepper on the planner interface.
// One step after the endpoints is one extension: draw q_final with probability B (the goal
// bias), else a uniform sample; extend the vertex of q_init's tree nearest to it by at most D
// toward it (core/planning/tree_planner.hpp): a new vertex and its edge to its parent if both
// are free. Only a goal draw within D of the tree reaches q_final, by an edge to vertex 1 (with
// B = 0 the tree never joins q_final, as in the textbook and OMPL with an exact goal). Then the
// path is re-checked (the query step). Budget: the samples drawn, goal draws included.
#include "core/planning/tree_planner.hpp"

namespace csl {

class Rrt final : public TreePlanner {
 public:
  /// The world must outlive the planner. Throws std::invalid_argument for a budget, bias or
  /// step outside params.hpp's ranges.
  Rrt(const CollisionWorld& world, Config start, Config goal, TreeParams params);
  Rrt(CollisionWorld&&, Config, Config, TreeParams) = delete;

  const char* name() const override { return "rrt"; }
  std::string describe(const PlannerEvent& e, const Scene& scene) const override;

 private:
  template <bool kEmit>
  void grow();
  void grow_emit() override { grow<true>(); }
  void grow_quiet() override { grow<false>(); }
  bool pending() const override { return false; }
  void reset_growth() override {}
};

/// Makes Rrt planners with `params`.
PlannerFactory rrt_factory(TreeParams params);

}  // namespace csl
