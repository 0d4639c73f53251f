#include "core/planning/rrt.hpp"

#include "core/planning/tree_text.hpp"

namespace csl {

Rrt::Rrt(const CollisionWorld& world, Config start, Config goal, TreeParams params)
    : TreePlanner(world, std::move(start), std::move(goal), params) {
  reset();
}

template <bool kEmit>
void Rrt::grow() {
  // One uniform number per step, whatever B (0 included): the goal or a sample.
  const bool to_goal = rng().uniform01() < params().goal_bias;
  if (to_goal) {
    count_sample();
    extend<kEmit>(0, nearest_in(0, goal()), goal(), 1, samples_drawn());
  } else {
    const Config q = draw_sample();
    extend<kEmit>(0, nearest_in(0, q), q, -1, samples_drawn());
  }
}

std::string Rrt::describe(const PlannerEvent& e, const Scene& scene) const { return describe_tree_event(e, *this, scene); }

PlannerFactory rrt_factory(TreeParams params) {
  return [params](const CollisionWorld& world, const Config& start, const Config& goal) {
    return std::make_unique<Rrt>(world, start, goal, params);
  };
}

}  // namespace csl
