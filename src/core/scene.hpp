#pragma once
// The scene: workspace bounds, obstacles, start and goal, and its JSON form (schema version 1).
#include <nlohmann/json_fwd.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/vec2.hpp"

namespace csl {

/// A closed disk obstacle.
struct Disk {
  Vec2 center{0.0, 0.0};
  double radius = 0.0;
};

/// Everything the lab needs to reproduce a planning problem.
struct Scene {
  Vec2 workspace_min{0.0, 0.0};
  Vec2 workspace_max{1.0, 1.0};
  std::vector<Disk> disks;
  Vec2 start{0.0, 0.0};
  Vec2 goal{1.0, 1.0};
};

/// Thrown for invalid scene JSON; what() names the offending field, e.g. "obstacles[2].radius: ...".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses and validates a scene (schema version 1). Throws SceneError.
Scene scene_from_json(const nlohmann::json& j);
/// Parses scene text (JSON). Throws SceneError, also for malformed JSON.
Scene scene_from_string(const std::string& text);
/// The scene as schema-version-1 JSON; scene_from_json(scene_to_json(s)) == s.
nlohmann::json scene_to_json(const Scene& s);

}  // namespace csl
