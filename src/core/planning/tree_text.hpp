#pragma once
// A tree planner's events in words (the lessons' event log, Planner::describe()).
#include <string>

#include "core/planning/tree_planner.hpp"
#include "core/scene/scene.hpp"

namespace csl {

/// One line: "sample #12: vertex 7 of q_init's tree extended 0.2 toward it, new vertex 15 at
/// (...) (bisection, 3 evaluations)", obstacles named as `scene` lists them.
std::string describe_tree_event(const PlannerEvent& e, const TreePlanner& planner, const Scene& scene);

}  // namespace csl
