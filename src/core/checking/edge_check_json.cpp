#include "core/checking/edge_check_json.hpp"

#include "core/scene/scene.hpp"

namespace csl {

nlohmann::json edge_check_to_json(const EdgeCheckResult& r, const EdgeCheckerSpec& spec, bool with_trace) {
  using json = nlohmann::json;
  json out{{"collision", r.collision},
           {"evaluations", r.evaluations},
           {"collision_t", r.collision_t ? json(*r.collision_t) : json(nullptr)},
           {"checker", spec.name()}};
  if (!with_trace) return out;
  const bool bisection = spec.kind == EdgeCheckerSpec::Kind::Bisection;
  json steps = json::array(), pieces = json::array();
  for (const EdgeEvent& e : r.trace) {
    if (e.kind == EdgeEvent::Kind::Evaluate) {
      json s{{"t", e.t}, {"q", config_to_json(e.q)}, {"eta", e.eta}, {"free", e.free}};
      if (bisection) {
        s["t0"] = e.t0;
        s["t1"] = e.t1;
        s["lambda"] = e.lambda;
        s["depth"] = e.depth;
      }
      steps.push_back(s);
    } else {
      pieces.push_back({{"t0", e.t0},
                        {"t1", e.t1},
                        {"lambda", e.lambda},
                        {"eta0", e.eta0},
                        {"eta1", e.eta1},
                        {"depth", e.depth},
                        {"unresolved", e.kind == EdgeEvent::Kind::Unresolved}});
    }
  }
  out["trace"] = steps;
  if (bisection) out["pieces"] = pieces;
  return out;
}

}  // namespace csl
