// Fuzz target: scene JSON. Any bytes must either be refused with a SceneError or give a scene
// that round-trips through JSON exactly and that the collision code can query. A crash, a
// sanitizer report, a non-SceneError exception or a broken invariant is a finding.
#include <cstdint>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "core/checking/collision.hpp"
#include "core/checking/edge_check.hpp"
#include "core/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  csl::Scene scene;
  try {
    scene = csl::scene_from_string(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const csl::SceneError&) {
    return 0;  // refused, with a message: fine
  }
  // A valid scene round-trips exactly.
  const nlohmann::json once = csl::scene_to_json(scene);
  if (csl::scene_to_json(csl::scene_from_json(once)) != once) std::abort();
  // And every query the lab makes of it is well-defined.
  const csl::CollisionWorld world(scene);
  const double eta = world.clearance(scene.start);
  if (world.is_free(scene.start) != (eta > 0.0)) std::abort();
  (void)world.clearance(scene.goal);
  if (scene.obstacles.size() <= 50) {
    const auto r = csl::check_edge(world, csl::EdgeCheckerSpec::parse("bisection"), scene.start, scene.goal);
    if (r.collision && !r.collision_t) std::abort();
  }
  return 0;
}
