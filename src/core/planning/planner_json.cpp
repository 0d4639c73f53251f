#include "core/planning/planner_json.hpp"

#include <nlohmann/json.hpp>

namespace csl {

using json = nlohmann::json;

json planner_state_json(const Planner& planner, bool roadmap) {
  const Roadmap& r = planner.roadmap();
  json path = json::array();
  for (const Config& q : planner.path_configurations()) path.push_back(config_to_json(q));
  json out{{"phase", planner.phase_label()},
           {"steps", planner.steps()},
           {"done", planner.done()},
           {"nodes", r.vertices.size()},
           {"edges", planner.edges_alive()},
           {"components", planner.components()},
           {"edge_checks", planner.edge_checks()},
           {"evaluations", planner.evaluations()},
           {"configurations_tested", planner.configurations_tested()},
           {"samples_drawn", planner.samples_drawn()},
           {"solved", planner.solved()},
           {"path", path},
           {"path_length", planner.solved() ? json(planner.path_length()) : json(nullptr)},
           {"roadmap_hash", roadmap_hash_text(r)},
           {"last_event", planner.steps() > 0 ? json(event_kind_name(planner.last_event().kind)) : json(nullptr)}};
  // A planner that adds edges on trust (Lazy PRM) adds what it never had to check: a count, and
  // with the roadmap a flag per edge.
  const std::vector<unsigned char>* flags = planner.checked_edge_flags();
  if (flags) out["edges_unchecked"] = planner.edges_unchecked();
  if (roadmap) {
    json vertices = json::array(), edges = json::array(), checked = json::array();
    for (const Config& q : r.vertices) vertices.push_back(config_to_json(q));
    for (std::size_t i = 0; i < r.edges.size(); ++i) {
      const RoadmapEdge& e = r.edges[i];
      if (!e.alive) continue;
      edges.push_back(json::array({e.a, e.b}));
      if (flags) checked.push_back((*flags)[i] != 0);
    }
    out["vertices"] = vertices;
    out["edge_list"] = edges;
    if (flags) out["edge_checked"] = checked;
  }
  return out;
}

}  // namespace csl
