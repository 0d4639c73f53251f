#pragma once
// A planner's state in words, for the page's text description of the roadmap the view draws
// (the app's "describe" command): the step and phase, the graph's size, and the path found.
#include <string>

#include "core/planning/planner.hpp"

namespace csl {

/// "Step 120, phase connecting. The roadmap has 52 vertices and 140 edges in 3 components.
/// No path yet." / "... Path found: 7 edges, length 1.234." / "... No path found." Numbers to 4
/// significant digits; the length is path_length() so rounded. Without `with_length` (an
/// instructor hid it: core/teaching/restrictions.hpp) "Path found: 7 edges."
std::string describe_planner(const Planner& planner, bool with_length = true);

}  // namespace csl
