#include "core/planning/planner_text.hpp"

#include "core/base/text.hpp"

namespace csl {

std::string describe_planner(const Planner& p, bool with_length) {
  const Roadmap& r = p.roadmap();
  const auto count = [](long n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  std::string out = "Step " + std::to_string(p.steps()) + ", phase " + p.phase_label() + ". The roadmap has " +
                    count(static_cast<long>(r.vertices.size()), "vertex", "vertices") + " and " +
                    count(p.edges_alive(), "edge", "edges") + " in " + count(p.components(), "component", "components") +
                    ". ";
  if (p.solved())
    return out + "Path found: " + count(static_cast<long>(p.path().size()) - 1, "edge", "edges") +
           (with_length ? ", length " + significant(p.path_length()) : std::string()) + ".";
  return out + (p.done() ? "No path found." : "No path yet.");
}

}  // namespace csl
