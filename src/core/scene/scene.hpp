#pragma once
// The scene: workspace bounds, the robot, obstacles, start and goal; and its JSON form
// (schema version 1):
//
//   { "version": 1,
//     "name": "optional title",
//     "workspace": { "min": [0, 0], "max": [1, 1] },
//     "robot": { "type": "point" }
//            | { "type": "arm2", "base": [x, y], "lengths": [l1, l2] }
//            | { "type": "polygon", "vertices": [[x, y], ...] }        (robot frame)
//     "obstacles": [ { "type": "disk", "center": [x, y], "radius": r },
//                    { "type": "polygon", "vertices": [[x, y], ...] },
//                    { "type": "segment", "a": [x, y], "b": [x, y] } ],
//     "start": q, "goal": q }
//
// q is [x, y] for the point robot, [theta1, theta2] (radians, theta2 relative to link 1) for
// the arm, [x, y, theta] for the polygon robot. Angles are stored wrapped into [-pi, pi).
// Defaults: workspace [0,1]^2, point robot, no obstacles, start = workspace min corner,
// goal = max corner (arm: 0,0 and pi/2,0).
#include <nlohmann/json_fwd.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/base/config.hpp"
#include "core/geometry/json_fields.hpp"  // SceneError, kMaxCoordinate
#include "core/geometry/obstacles.hpp"
#include "core/robots/robot.hpp"

namespace csl {

/// Limits that keep a scene something a browser tab can hold and draw.
inline constexpr std::size_t kMaxObstacles = 1000;
inline constexpr std::size_t kMaxPolygonVertices = 256;
inline constexpr std::size_t kMaxNameLength = 200;
/// The workspace's sides: each at least this long, and the longer at most kMaxWorkspaceAspect
/// times the shorter. A view fits the workspace to its pixels; a side of 1e-15 (or 5e-324) left
/// the app's grid and scale nothing finite to work with (issue 27: one such link crashed the
/// wasm, and the autosave crashed every later start), and a sliver 1e6 times longer than wide
/// shows as a line no one can draw in. Within +-1e6 coordinates, 1e-3 still resolves to
/// 1e-9 of the largest coordinate (doubles resolve 2e-16).
inline constexpr double kMinWorkspaceExtent = 1e-3;
inline constexpr double kMaxWorkspaceAspect = 100.0;
/// Bytes of scene JSON: the largest scene the other limits allow (1000 polygons of 256
/// vertices at full precision) is about 12 MB, 28 MB indented by 4 a level.
inline constexpr std::size_t kMaxSceneBytes = std::size_t{64} << 20;

struct Scene {
  std::string name;
  Vec2 workspace_min{0.0, 0.0};
  Vec2 workspace_max{1.0, 1.0};
  Robot robot = PointRobot{};
  std::vector<Obstacle> obstacles;
  Config start = config({0.0, 0.0});
  Config goal = config({1.0, 1.0});
};

/// JSON nested deeper than this is refused by parse_json_text(): no scene needs more than 4
/// levels, and copying a value nested 200000 deep recurses once a level (a stack overflow).
inline constexpr int kMaxJsonDepth = 64;
/// Parses JSON text strictly: the whole text (a NUL byte is not an end), at most kMaxJsonDepth
/// levels deep. Throws std::invalid_argument saying what is wrong ("not valid JSON", ...).
nlohmann::json parse_json_text(const std::string& text);

/// Parses and validates a scene (schema version 1). Throws SceneError.
Scene scene_from_json(const nlohmann::json& j);
/// Parses scene text (JSON). Throws SceneError, also for malformed JSON.
Scene scene_from_string(const std::string& text);
/// The scene as schema-version-1 JSON; scene_from_json(scene_to_json(s)) reproduces s exactly.
nlohmann::json scene_to_json(const Scene& s);
/// Whether two scenes are the same in every field: their JSON is equal (it holds every field
/// exactly; numbers compare by value).
bool same_scene(const Scene& a, const Scene& b);
/// Whether two scenes are the same but perhaps for their names: what a planner, a field or a
/// check runs in (the app renames an edited scene without changing what it holds).
bool same_content(const Scene& a, const Scene& b);

/// Checks an obstacle on its own (used by the parser and by editors before they commit a
/// change); returns what is wrong, or "" if it is valid. `path` prefixes the message.
std::string obstacle_problem(const Obstacle& o, const std::string& path);

/// "disk 3", "wall 2", "polygon 1" (1-based, as the panels list them); "an obstacle" for an
/// index the scene has not: how the event logs name an obstacle.
std::string obstacle_label(const Scene& scene, int index);

/// JSON of one configuration / obstacle, as in the scene format.
nlohmann::json config_to_json(const Config& q);
nlohmann::json obstacle_to_json(const Obstacle& o);

}  // namespace csl
