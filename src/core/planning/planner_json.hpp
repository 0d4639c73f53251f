#pragma once
// A planner's state as JSON: the one description the lab's API (each planner lesson's state())
// and the CLI's plan report, so that they cannot drift apart (the torus lesson used to leave
// out components, edge checks, evaluations and samples drawn).
#include <nlohmann/json_fwd.hpp>

#include "core/planning/planner.hpp"

namespace csl {

/// {"phase", "steps", "done", "nodes", "edges" (alive), "components", "edge_checks",
///  "evaluations", "samples_drawn", "solved", "path" ([Q, ...], with a connector's waypoints),
///  "path_length" (null unless solved), "roadmap_hash" (16 hex digits), "last_event" (its kind,
///  null before step 1)}; with `roadmap`, also "vertices" ([Q, ...]) and "edge_list" ([[a, b],
///  ...] of the live edges, indices into vertices: 0 is the start, 1 the goal).
/// A planner with checked_edge_flags() (Lazy PRM, also through a wrapper) adds "edges_unchecked"
/// (live edges never checked) and,
/// with `roadmap`, "edge_checked" ([bool, ...], one per entry of edge_list: whether the exact check
/// examined it; false: in the roadmap on trust).
nlohmann::json planner_state_json(const Planner& planner, bool roadmap);

}  // namespace csl
