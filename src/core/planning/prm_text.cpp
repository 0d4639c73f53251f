#include "core/planning/prm_text.hpp"

#include "core/planning/prm.hpp"

#include <cstdio>

namespace csl {
namespace {

// What an edge check cost: its evaluations, and for the grid checkers in a roadmap, which test
// only what the endpoints' clearances leave unproven, how many they proved free.
std::string checks_text(const PrmEvent& e) {
  if (e.skipped == 0 && e.evaluations == 0) return "its ends are vertices, free: nothing between them to test";
  if (e.skipped == 0) return std::to_string(e.evaluations) + (e.evaluations == 1 ? " evaluation" : " evaluations");
  if (e.evaluations == 0)
    return "all " + std::to_string(e.skipped) + " configurations proven free by the ends' clearances, none tested";
  return std::to_string(e.evaluations) + " tested, " + std::to_string(e.skipped) + " proven free by the ends' clearances";
}

// An edge added: how it was proven free. Bisection with no evaluation is not a missing check:
// the ends' clearances cover the whole line at once (lambda < eta(p) + eta(q)).
std::string edge_added_text(const PrmEvent& e, const Prm& prm) {
  const EdgeCheckerSpec& checker = prm.params().checker;
  if (!prm.params().connector && checker.kind == EdgeCheckerSpec::Kind::Bisection && e.evaluations == 0)
    return "free at once: its ends' clearances cover it (λ < η(p) + η(q), nothing between to test)";
  return "free (" + checker.name() + ", " + checks_text(e) + ")";
}

// A vertex's close pairs: how many are new, and why fewer than k (or than are within r) are.
std::string neighbors_text(const PrmEvent& e, const Prm& prm) {
  const std::string rule = prm.params().neighbors.name();
  std::string out = std::to_string(e.candidates) + (e.candidates == 1 ? " close pair" : " close pairs") + " to check (" + rule;
  if (e.seen > 0)
    out += "; " + std::to_string(e.seen) + (e.seen == 1 ? " other was" : " others were") + " checked already from the other vertex";
  out += ")";
  if (e.candidates == 0 && e.seen == 0) out += ": no other vertex is close";
  return out;
}

// Why a non-uniform sampler kept or dropped its draw (uniform: nothing to add).
const char* accepted_why(SamplerSpec::Kind k) {
  switch (k) {
    case SamplerSpec::Kind::Gaussian: return " and its Gaussian partner in collision";
    case SamplerSpec::Kind::Bridge: return ", the midpoint of a bridge between two collisions";
    case SamplerSpec::Kind::Halton: return " (Halton point)";
    case SamplerSpec::Kind::Uniform: break;
  }
  return "";
}
const char* rejected_why(SamplerSpec::Kind k) {
  switch (k) {
    case SamplerSpec::Kind::Gaussian: return ", and so is its Gaussian partner";
    case SamplerSpec::Kind::Bridge: return " (a bridge's midpoint)";
    case SamplerSpec::Kind::Halton: return " (Halton point)";
    case SamplerSpec::Kind::Uniform: break;
  }
  return "";
}

}  // namespace

std::string describe_prm_event(const PlannerEvent& e, const Prm& prm, const Scene& scene) {
  char buf[256];
  const std::string q = format_config(e.q);
  switch (e.kind) {
    case PrmEvent::Kind::AddEndpoint:
      std::snprintf(buf, sizeof buf, "%s added as vertex %d at %s", e.vertex == 0 ? "q_init" : "q_final", e.vertex,
                    q.c_str());
      break;
    case PrmEvent::Kind::EndpointInCollision:
      std::snprintf(buf, sizeof buf, "%s at %s is inside %s: no path can %s there",
                    e.vertex == 0 ? "q_init" : "q_final", q.c_str(), obstacle_label(scene, e.obstacle).c_str(),
                    e.vertex == 0 ? "start" : "end");
      break;
    case PrmEvent::Kind::SampleAccepted:
      std::snprintf(buf, sizeof buf, "sample #%d at %s: free%s, added as vertex %d", e.sample, q.c_str(),
                    accepted_why(prm.params().sampler.kind), e.vertex);
      break;
    case PrmEvent::Kind::SampleRejected:
      if (e.obstacle < 0) {
        std::snprintf(buf, sizeof buf, "sample #%d at %s: rejected, %s", e.sample, q.c_str(),
                      prm.params().sampler.kind == SamplerSpec::Kind::Bridge
                          ? "a bridge end is free (the bridge test keeps only midpoints between two collisions)"
                          : "free, and so is its Gaussian partner (nothing near an obstacle's boundary)");
        break;
      }
      std::snprintf(buf, sizeof buf, "sample #%d at %s: rejected, inside %s%s", e.sample, q.c_str(),
                    obstacle_label(scene, e.obstacle).c_str(), rejected_why(prm.params().sampler.kind));
      break;
    case PrmEvent::Kind::Neighbors:
      std::snprintf(buf, sizeof buf, "connecting vertex %d: %s", e.vertex, neighbors_text(e, prm).c_str());
      break;
    case PrmEvent::Kind::EdgeAdded:
      std::snprintf(buf, sizeof buf, "edge %d-%d: %s, added", e.vertex, e.other, edge_added_text(e, prm).c_str());
      break;
    case PrmEvent::Kind::EdgeRejected:
      std::snprintf(buf, sizeof buf, "edge %d-%d: in collision at t = %.3f (%s)", e.vertex, e.other, e.collision_t,
                    checks_text(e).c_str());
      break;
    case PrmEvent::Kind::PathEdgeRemoved:
      std::snprintf(buf, sizeof buf, "path edge %d-%d fails the exact check at t = %.3f: removed, searching again",
                    e.vertex, e.other, e.collision_t);
      break;
    case PrmEvent::Kind::PathFound:
      std::snprintf(buf, sizeof buf, "q_init and q_final are connected: a path of %zu edges, length %.4f",
                    prm.path().size() - 1, e.path_length);
      break;
    case PrmEvent::Kind::EdgeChecked:  // Lazy PRM's: PRM checks every edge as it adds it
    case PrmEvent::Kind::PathCandidate:
      std::snprintf(buf, sizeof buf, "%s (not a PRM event)", event_kind_name(e.kind));
      break;
    case PrmEvent::Kind::NoPath:
      std::snprintf(buf, sizeof buf, "q_init and q_final are not connected: PRM declares no path (n = %d)",
                    prm.params().samples);
      break;
  }
  return buf;
}

}  // namespace csl
