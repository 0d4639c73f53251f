#pragma once
// What a PRM step did, in words: Prm::describe(), the text of the lab's event log.
#include <string>

#include "core/base/config.hpp"
#include "core/planning/planner.hpp"
#include "core/scene/scene.hpp"

namespace csl {

/// "obstacle 3 (a disk)" style name of a scene obstacle (1-based, as the panel lists them).
std::string obstacle_label(const Scene& scene, int index);
class Prm;
/// One line describing the event, e.g. "sample #37 at (0.41, 0.77): rejected, inside disk 3".
std::string describe_prm_event(const PlannerEvent& e, const Prm& prm, const Scene& scene);
/// A configuration as "(0.410, 0.770)".
std::string format_config(const Config& q);

}  // namespace csl
