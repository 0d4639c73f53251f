#pragma once
// The robots of the lab, their configuration spaces, their shape at a configuration, and the
// motion bound lambda(p, q) of Schwarzer, Saha and Latombe (2005): an upper bound on how far
// any point of the robot travels while its configuration moves along the straight line p -> q.
#include <variant>
#include <vector>

#include "core/base/config.hpp"
#include "core/geometry/geometry.hpp"
#include "core/spaces/space.hpp"

namespace csl {

/// A point translating in the plane: Q = R^2 (the workspace box), q = (x, y).
struct PointRobot {};

/// A planar arm of N revolute joints in series (1 <= N <= kMaxLinks): Q = T^N,
/// q = (theta1, ..., thetaN), each angle relative to the link before it (theta1 to the x axis).
/// The lessons show the 2-link arm; a 3-link arm is a scene, not another type.
struct ArmRobot {
  static constexpr int kMaxLinks = 6;
  Vec2 base{0.0, 0.0};
  std::vector<double> lengths{0.5, 0.5};

  ArmRobot() = default;
  /// The 2-link arm.
  ArmRobot(const Vec2& base_, double length1, double length2) : base(base_), lengths{length1, length2} {}
  ArmRobot(const Vec2& base_, std::vector<double> lengths_) : base(base_), lengths(std::move(lengths_)) {}
  int links() const { return static_cast<int>(lengths.size()); }
  double length(int i) const { return lengths[static_cast<std::size_t>(i)]; }
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

/// The robot types, a closed set: a switch on robot_kind() without a default is checked by the
/// compiler (-Wswitch) to handle each, where an if-chain or an index test would let a new type
/// through to whatever its last branch does.
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

/// The arm's joints at q (forward kinematics): out[0] is the base, out[i] the end of link i,
/// out[N] the tip; `out` holds kMaxLinks + 1 points. Each link's absolute angle is the running
/// sum theta1 + ... + thetai, turned into sine and cosine by det::sincos (the same bits in every
/// build), each joint the one before plus length times (cos, sin), in that order.
void arm_joints(const ArmRobot& arm, const Config& q, Vec2* out);
/// The 2-link arm's elbow and tip at q (for an N-link arm: the end of link 1 and the tip).
struct ArmPose {
  Vec2 base, elbow, tip;
};
ArmPose arm_pose(const ArmRobot& arm, const Config& q);

/// The polygon's vertices in the workspace at q = (x, y, theta), written into `out`.
void polygon_pose(const PolygonRobot& robot, const Config& q, Polygon& out);

/// lambda(p, q): an upper bound on the path length of every point of the robot along the
/// straight line from p to q (angles the shortest way round). Formulas, with delta = q - p:
///   point:   |delta|
///   arm:     sum_i l_i |d_1 + ... + d_i|; for two links l1 |d1| + l2 |d1 + d2| (a point of
///            link 1 at distance s <= l1 from the base moves at speed s|d1|; a point of link 2
///            at distance u <= l2 from the elbow moves at most at the elbow's speed l1|d1| plus
///            u|d1 + d2|, since link 2's absolute angle theta1 + theta2 changes at the rate
///            d1 + d2; link i likewise adds l_i times its absolute angle's rate)
///   polygon: |(dx, dy)| + R |dtheta|, R = the body's radius.
double motion_bound(const Robot& r, const Config& p, const Config& q);

/// K = sup lambda(p, q) / d(p, q) in the robot's C-space metric: no point of the robot moves
/// more than K times the C-space distance. A workspace clearance eta thus frees a C-space ball
/// of radius eta / K. Point: 1. Arm: lambda = sum_i l_i |d_1 + ... + d_i| <= sum_j a_j |d_j| with
/// a_j = l_j + ... + l_N, so K = |a| (Cauchy-Schwarz); two links: sqrt((l1 + l2)^2 + l2^2).
/// Polygon (angle weighted by R): |dxy| + R|dtheta| <= sqrt 2 * sqrt(|dxy|^2 + R^2 dtheta^2).
double motion_lipschitz(const Robot& r);

}  // namespace csl
