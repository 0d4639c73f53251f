#include "core/planning/rrt_connect.hpp"

#include "core/planning/tree_text.hpp"

namespace csl {

RrtConnect::RrtConnect(const CollisionWorld& world, Config start, Config goal, TreeParams params)
    : TreePlanner(world, std::move(start), std::move(goal), params) {
  reset();
}

void RrtConnect::reset_growth() {
  a_ = 0;
  connecting_ = false;
  target_ = from_ = -1;
}

template <bool kEmit>
void RrtConnect::grow() {
  if (!connecting_) {
    // EXTEND(T_a, q_rand).
    const Config q = draw_sample();
    const Extension r = extend<kEmit>(a_, nearest_in(a_, q), q, -1, samples_drawn());
    if (r == Extension::Trapped) {
      a_ = 1 - a_;  // SWAP(T_a, T_b)
      return;
    }
    connecting_ = true;
    target_ = static_cast<int>(roadmap().vertices.size()) - 1;
    from_ = -1;
    return;
  }
  // CONNECT(T_b, q_new): one extension per step, from the vertex the last one added.
  const int b = 1 - a_;
  const Config target = roadmap().vertices[static_cast<std::size_t>(target_)];  // a copy: V grows
  const int from = from_ >= 0 ? from_ : nearest_in(b, target);
  const Extension r = extend<kEmit>(b, from, target, target_, -1);
  if (r == Extension::Advanced) {
    from_ = static_cast<int>(roadmap().vertices.size()) - 1;
    return;
  }
  // Reached (the join) or trapped: this round is over.
  connecting_ = false;
  target_ = from_ = -1;
  a_ = 1 - a_;
}

std::string RrtConnect::describe(const PlannerEvent& e, const Scene& scene) const {
  return describe_tree_event(e, *this, scene);
}

PlannerFactory rrt_connect_factory(TreeParams params) {
  return [params](const CollisionWorld& world, const Config& start, const Config& goal) {
    return std::make_unique<RrtConnect>(world, start, goal, params);
  };
}

}  // namespace csl
