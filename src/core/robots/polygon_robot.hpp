#pragma once
// The polygon robot: a rigid polygon translating and rotating in the plane, Q = SE(2),
// q = (x, y, theta). `body` is given in the robot's frame; its origin is the reference point
// (x, y). Everything the lab needs of this robot type is here; core/robots/robot.hpp
// dispatches to it.
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

#include "core/base/config.hpp"
#include "core/geometry/geometry.hpp"
#include "core/robots/control_point.hpp"
#include "core/spaces/space.hpp"

namespace csl {

/// The most vertices a robot's body may have (a scene's limit).
inline constexpr std::size_t kMaxRobotVertices = 32;

/// Make one with make_polygon_robot(), which fills in the radius.
struct PolygonRobot {
  Polygon body;
  /// Farthest body point from the origin (a vertex): how far a turn of 1 rad moves any point.
  double radius = 0.0;

  const char* type_name() const { return "polygon"; }
  int dof() const { return 3; }
  /// SE(2) over the workspace box, the angle weighted by the radius.
  Space space(const Vec2& lo, const Vec2& hi) const;
  /// lambda(p, q) = |(dx, dy)| + R |dtheta|, R the body's radius.
  double motion_bound(const Config& p, const Config& q) const;
  /// K = sqrt 2 (angle weighted by R: |dxy| + R|dtheta| <= sqrt 2 sqrt(|dxy|^2 + R^2 dtheta^2)).
  double motion_lipschitz() const;
  /// Each vertex of the body, in order, with its Jacobian [[1, 0, -y'], [0, 1, x']], (x', y')
  /// the vertex turned by theta.
  void control_points(const Config& q, std::vector<ControlPoint>& out) const;
  /// "vertex 0", "vertex 1", ...
  std::string control_point_name(int i) const { return "vertex " + std::to_string(i); }
  /// JSON: {"type": "polygon", "vertices": [[x, y], ...]} (robot frame, at most kMaxRobotVertices).
  static bool reads(const std::string& type) { return type == "polygon"; }
  static PolygonRobot from_json(const nlohmann::json& r, const std::string& type);
  void to_json(nlohmann::json& r) const;
};
/// A polygon robot with the given body (robot frame) and its radius.
PolygonRobot make_polygon_robot(Polygon body);

/// The polygon's vertices in the workspace at q = (x, y, theta), written into `out`.
void polygon_pose(const PolygonRobot& robot, const Config& q, Polygon& out);

}  // namespace csl
