#pragma once
// The robots of the lab, their configuration spaces, their shape at a configuration, and the
// motion bound lambda(p, q) of Schwarzer, Saha and Latombe (2005): an upper bound on how far
// any point of the robot travels while its configuration moves along the straight line p -> q.
#include <variant>
#include <vector>

#include "core/config.hpp"
#include "core/geometry.hpp"
#include "core/space.hpp"

namespace csl {

/// A point translating in the plane: Q = R^2 (the workspace box), q = (x, y).
struct PointRobot {};

/// A planar arm of two revolute joints: Q = T^2, q = (theta1, theta2), theta2 relative to link 1.
struct ArmRobot {
  Vec2 base{0.0, 0.0};
  double length1 = 0.5;
  double length2 = 0.5;
};

/// A rigid polygon translating and rotating in the plane: Q = SE(2), q = (x, y, theta).
/// `body` is given in the robot's frame; its origin is the reference point (x, y).
/// Make one with make_polygon_robot(), which fills in the radius.
struct PolygonRobot {
  Polygon body;
  /// Farthest body point from the origin (a vertex): how far a turn of 1 rad moves any point.
  double radius = 0.0;
};
/// A polygon robot with the given body (robot frame) and its radius.
PolygonRobot make_polygon_robot(Polygon body);

using Robot = std::variant<PointRobot, ArmRobot, PolygonRobot>;

/// "point", "arm2" or "polygon" (the JSON type names).
const char* robot_type_name(const Robot& r);
/// Number of coordinates of a configuration: 2, 2 or 3.
int robot_dof(const Robot& r);

/// The robot's configuration space over the given workspace box: R^2, T^2 or SE(2) (the angle
/// weighted by the polygon's radius).
Space robot_space(const Robot& r, const Vec2& workspace_min, const Vec2& workspace_max);

/// The arm's elbow and tip at q (forward kinematics).
struct ArmPose {
  Vec2 base, elbow, tip;
};
ArmPose arm_pose(const ArmRobot& arm, const Config& q);

/// The polygon's vertices in the workspace at q = (x, y, theta), written into `out`.
void polygon_pose(const PolygonRobot& robot, const Config& q, Polygon& out);

/// lambda(p, q): an upper bound on the path length of every point of the robot along the
/// straight line from p to q (angles the shortest way round). Formulas, with delta = q - p:
///   point:   |delta|
///   arm:     l1 |d1| + l2 |d1 + d2|  (a point of link 1 at distance s <= l1 from the base moves
///            at speed s|d1|; a point of link 2 at distance u <= l2 from the elbow moves at most
///            at the elbow's speed l1|d1| plus u|d1 + d2|, since link 2's absolute angle
///            theta1 + theta2 changes at the rate d1 + d2)
///   polygon: |(dx, dy)| + R |dtheta|, R = the body's radius.
double motion_bound(const Robot& r, const Config& p, const Config& q);

/// K = sup lambda(p, q) / d(p, q) in the robot's C-space metric: no point of the robot moves
/// more than K times the C-space distance. A workspace clearance eta thus frees a C-space ball
/// of radius eta / K. Point: 1. Arm: lambda = l1|d1| + l2|d1 + d2| = a . (|d1|, ...) is at most
/// sqrt((l1 + l2)^2 + l2^2) |d| (Cauchy-Schwarz on the worst sign pattern). Polygon (angle
/// weighted by R): |dxy| + R|dtheta| <= sqrt 2 * sqrt(|dxy|^2 + R^2 dtheta^2).
double motion_lipschitz(const Robot& r);

}  // namespace csl
