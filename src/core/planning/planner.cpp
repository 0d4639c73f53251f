#include "core/planning/planner.hpp"

namespace csl {

const char* event_kind_name(PlannerEvent::Kind k) {
  static const char* const kNames[] = {"add_endpoint", "endpoint_in_collision", "sample_accepted", "sample_rejected",
                                       "neighbors",    "edge_added",            "edge_rejected",   "path_edge_removed",
                                       "path_found",   "no_path"};
  return kNames[static_cast<int>(k)];
}

}  // namespace csl
