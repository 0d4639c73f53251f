#pragma once
// The robots of the lab, a closed set: `Robot` is one of the types below, each in its own file
// with everything the lab needs of it (its C-space, pose, motion bound, control points and
// Jacobians, JSON). The calls here dispatch to the type with std::visit, so that a new type
// added to the variant is a compile error wherever it lacks a member, never a silent default.
// The motion bound lambda(p, q) is Schwarzer, Saha and Latombe's (2005): an upper bound on how
// far any point of the robot travels while its configuration moves along the straight line p -> q.
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <variant>
#include <vector>

#include "core/base/config.hpp"
#include "core/robots/arm_robot.hpp"
#include "core/robots/control_point.hpp"
#include "core/robots/point_robot.hpp"
#include "core/robots/polygon_robot.hpp"
#include "core/spaces/space.hpp"

namespace csl {

using Robot = std::variant<PointRobot, ArmRobot, PolygonRobot>;

/// The robot types by name, for a switch: without a default, the compiler (-Wswitch) checks
/// that it handles each.
enum class RobotKind { Point, Arm, RigidPolygon };
RobotKind robot_kind(const Robot& r);

/// Whether r is the 2-link arm: the one the torus square, its exact C-space map and the lessons
/// built on them show.
bool is_two_link_arm(const Robot& r);

/// "point", "arm2" (the 2-link arm), "arm" (any other number of links) or "polygon": the JSON
/// type names.
const char* robot_type_name(const Robot& r);
/// Number of coordinates of a configuration: 2 (point), N (an N-link arm), 3 (polygon).
int robot_dof(const Robot& r);

/// The robot's configuration space over the given workspace box: R^2, T^N or SE(2) (the angle
/// weighted by the polygon's radius).
Space robot_space(const Robot& r, const Vec2& workspace_min, const Vec2& workspace_max);

/// lambda(p, q): an upper bound on the path length of every point of the robot along the
/// straight line from p to q (angles the shortest way round); each type's file gives its formula.
double motion_bound(const Robot& r, const Config& p, const Config& q);

/// K = sup lambda(p, q) / d(p, q) in the robot's C-space metric: no point of the robot moves
/// more than K times the C-space distance. A workspace clearance eta thus frees a C-space ball
/// of radius eta / K.
double motion_lipschitz(const Robot& r);

/// The robot's control points at q (which, and in what order: each type's file).
void control_points(const Robot& robot, const Config& q, std::vector<ControlPoint>& out);
std::vector<ControlPoint> control_points(const Robot& robot, const Config& q);
/// "point", "elbow", "tip", "joint 2", "vertex 0", ...
std::string control_point_name(const Robot& robot, int i);

/// The "robot" object of a scene: the type whose reads() takes its "type". Throws SceneError
/// naming the field.
Robot robot_from_json(const nlohmann::json& r);
nlohmann::json robot_to_json(const Robot& r);

}  // namespace csl
