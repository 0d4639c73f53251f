#pragma once
// What a PRM step did, in words: Prm::describe(), the text of the lab's event log (its pieces,
// format_config and obstacle_label, are any planner's: core/base/config.hpp, core/scene/scene.hpp).
#include <string>

#include "core/base/config.hpp"
#include "core/planning/planner.hpp"
#include "core/scene/scene.hpp"

namespace csl {

class Prm;
/// One line describing the event, e.g. "sample #37 at (0.41, 0.77): rejected, inside disk 3".
std::string describe_prm_event(const PlannerEvent& e, const Prm& prm, const Scene& scene);

}  // namespace csl
