#include "core/planning/tree_text.hpp"

#include <cstdio>

namespace csl {
namespace {

const char* tree_name(int tree) { return tree == 0 ? "q_init's tree" : tree == 1 ? "q_final's tree" : "no tree"; }

// What an edge check cost, as PRM's log says it.
std::string checks_text(const PlannerEvent& e, const TreePlanner& planner) {
  const std::string checker = planner.params().checker.name();
  if (e.evaluations == 0 && e.skipped == 0) return checker + ", proven free by its ends' clearances";
  std::string out = checker + ", " + std::to_string(e.evaluations) + (e.evaluations == 1 ? " evaluation" : " evaluations");
  if (e.skipped > 0) out += ", " + std::to_string(e.skipped) + " proven free by the ends' clearances";
  return out;
}

// "sample #12" or "connect" (an extension toward the other tree's vertex).
std::string toward_text(const PlannerEvent& e) {
  return e.sample > 0 ? "sample #" + std::to_string(e.sample) : std::string("connect");
}

}  // namespace

std::string describe_tree_event(const PlannerEvent& e, const TreePlanner& planner, const Scene& scene) {
  char buf[320];
  const std::string q = format_config(e.q);
  const std::string toward = toward_text(e);
  switch (e.kind) {
    case PlannerEvent::Kind::AddEndpoint:
      std::snprintf(buf, sizeof buf, "%s added as vertex %d at %s, the root of %s", e.vertex == 0 ? "q_init" : "q_final",
                    e.vertex, q.c_str(), tree_name(e.vertex));
      break;
    case PlannerEvent::Kind::EndpointInCollision:
      std::snprintf(buf, sizeof buf, "%s at %s is inside %s: no path can %s there", e.vertex == 0 ? "q_init" : "q_final",
                    q.c_str(), obstacle_label(scene, e.obstacle).c_str(), e.vertex == 0 ? "start" : "end");
      break;
    case PlannerEvent::Kind::SampleAccepted:
      std::snprintf(buf, sizeof buf, "%s: vertex %d of %s extended to %s, free (%s): new vertex %d, edge %d-%d",
                    toward.c_str(), e.other, tree_name(planner.tree_of(e.vertex)), q.c_str(),
                    checks_text(e, planner).c_str(), e.vertex, e.other, e.vertex);
      break;
    case PlannerEvent::Kind::SampleRejected:
      std::snprintf(buf, sizeof buf, "%s: the extension from vertex %d ends at %s, inside %s: trapped", toward.c_str(),
                    e.vertex, q.c_str(), obstacle_label(scene, e.obstacle).c_str());
      break;
    case PlannerEvent::Kind::EdgeRejected:
      if (e.other >= 0)
        std::snprintf(buf, sizeof buf, "%s: edge %d-%d to %s in collision at t = %.3f (%s): trapped", toward.c_str(),
                      e.vertex, e.other, e.other == 1 ? "q_final" : "the other tree", e.collision_t,
                      checks_text(e, planner).c_str());
      else
        std::snprintf(buf, sizeof buf, "%s: the extension from vertex %d to %s in collision at t = %.3f (%s): trapped",
                      toward.c_str(), e.vertex, q.c_str(), e.collision_t, checks_text(e, planner).c_str());
      break;
    case PlannerEvent::Kind::EdgeAdded:
      std::snprintf(buf, sizeof buf, "%s: edge %d-%d free (%s): it joins q_init's tree and q_final's", toward.c_str(),
                    e.vertex, e.other, checks_text(e, planner).c_str());
      break;
    case PlannerEvent::Kind::PathEdgeRemoved:
      std::snprintf(buf, sizeof buf,
                    "path edge %d-%d fails the exact check at t = %.3f: removed, what hung below it dropped; growing on",
                    e.vertex, e.other, e.collision_t);
      break;
    case PlannerEvent::Kind::PathFound:
      std::snprintf(buf, sizeof buf, "q_init and q_final are joined: a path of %zu edges, length %.4f",
                    planner.path().size() - 1, e.path_length);
      break;
    case PlannerEvent::Kind::NoPath:
      std::snprintf(buf, sizeof buf, "the trees did not meet in %d samples: %s declares no path",
                    planner.params().samples, planner.name());
      break;
    case PlannerEvent::Kind::Neighbors:  // PRM's and Lazy PRM's alone: a tree never emits these
    case PlannerEvent::Kind::EdgeChecked:
    case PlannerEvent::Kind::PathCandidate:
      std::snprintf(buf, sizeof buf, "%s event at vertex %d", event_kind_name(e.kind), e.vertex);
      break;
  }
  return buf;
}

}  // namespace csl
