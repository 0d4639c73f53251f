#pragma once
// What a PRM step did, in words, for the event log.
#include <string>

#include "core/prm.hpp"
#include "core/scene.hpp"

namespace csl::app {

/// "obstacle 3 (a disk)" style name of a scene obstacle (1-based, as the panel lists them).
std::string obstacle_label(const Scene& scene, int index);
/// One line describing the event, e.g. "sample #37 at (0.41, 0.77): rejected, inside disk 3".
std::string describe(const PrmEvent& e, const Prm& prm, const Scene& scene);
/// A configuration as "(0.410, 0.770)".
std::string format_config(const Config& q);

}  // namespace csl::app
