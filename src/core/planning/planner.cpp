#include "core/planning/planner.hpp"

#include "core/planning/graph.hpp"

namespace csl {

const char* event_kind_name(PlannerEvent::Kind k) {
  static const char* const kNames[] = {"add_endpoint", "endpoint_in_collision", "sample_accepted", "sample_rejected",
                                       "neighbors",    "edge_added",            "edge_rejected",   "path_edge_removed",
                                       "path_found",   "no_path",               "edge_checked",    "path_candidate"};
  return kNames[static_cast<int>(k)];
}

std::vector<int> Planner::component_labels() const {
  const Roadmap& r = roadmap();
  const int n = static_cast<int>(r.vertices.size());
  UnionFind sets;
  sets.reset(n);
  for (const RoadmapEdge& e : r.edges)
    if (e.alive) sets.unite(e.a, e.b);
  std::vector<int> label(r.vertices.size(), -1), by_root(r.vertices.size(), -1);
  int next = 0;
  for (int v = 0; v < n; ++v) {
    const auto root = static_cast<std::size_t>(sets.find(v));
    if (by_root[root] < 0) by_root[root] = next++;
    label[static_cast<std::size_t>(v)] = by_root[root];
  }
  return label;
}

}  // namespace csl
