#pragma once
// The point robot: a point translating in the plane, Q = R^2 (the workspace box), q = (x, y).
// Everything the lab needs of this robot type is here; core/robots/robot.hpp dispatches to it.
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

#include "core/base/config.hpp"
#include "core/robots/control_point.hpp"
#include "core/spaces/space.hpp"

namespace csl {

struct PointRobot {
  /// The JSON type name.
  const char* type_name() const { return "point"; }
  int dof() const { return 2; }
  /// R^2 over the workspace box.
  Space space(const Vec2& lo, const Vec2& hi) const;
  /// lambda(p, q) = |q - p|: the point travels the straight line.
  double motion_bound(const Config& p, const Config& q) const;
  /// K = 1.
  double motion_lipschitz() const { return 1.0; }
  /// One control point, the robot itself, with the identity Jacobian.
  void control_points(const Config& q, std::vector<ControlPoint>& out) const;
  std::string control_point_name(int) const { return "point"; }
  /// JSON: {"type": "point"}.
  static bool reads(const std::string& type) { return type == "point"; }
  static PointRobot from_json(const nlohmann::json& r, const std::string& type);
  void to_json(nlohmann::json& r) const;
};

}  // namespace csl
