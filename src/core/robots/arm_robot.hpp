#pragma once
// The planar arm of N revolute joints in series (1 <= N <= kMaxLinks): Q = T^N,
// q = (theta1, ..., thetaN), each angle relative to the link before it (theta1 to the x axis).
// The lessons show the 2-link arm; a 3-link arm is a scene, not another type. Everything the
// lab needs of this robot type is here; core/robots/robot.hpp dispatches to it.
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

#include "core/base/config.hpp"
#include "core/base/vec2.hpp"
#include "core/robots/control_point.hpp"
#include "core/spaces/space.hpp"

namespace csl {

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

  /// "arm2" (the 2-link arm) or "arm" (any other number of links): the JSON type names.
  const char* type_name() const { return links() == 2 ? "arm2" : "arm"; }
  int dof() const { return links(); }
  /// T^N.
  Space space(const Vec2& lo, const Vec2& hi) const;
  /// lambda(p, q) = sum_i l_i |d_1 + ... + d_i|, delta = q - p the shortest way round; for two
  /// links l1 |d1| + l2 |d1 + d2| (a point of link 1 at distance s <= l1 from the base moves at
  /// speed s|d1|; a point of link 2 at distance u <= l2 from the elbow moves at most at the
  /// elbow's speed l1|d1| plus u|d1 + d2|, since link 2's absolute angle theta1 + theta2 changes
  /// at the rate d1 + d2; link i likewise adds l_i times its absolute angle's rate).
  double motion_bound(const Config& p, const Config& q) const;
  /// K = |a|, a_j = l_j + ... + l_N (lambda <= sum_j a_j |d_j|, then Cauchy-Schwarz); two
  /// links: sqrt((l1 + l2)^2 + l2^2).
  double motion_lipschitz() const;
  /// The end of each link, in order (the last is the tip), with its Jacobian: column j is the
  /// sum over links i = j .. k of l_i (-sin A_i, cos A_i), A_i link i's absolute angle.
  void control_points(const Config& q, std::vector<ControlPoint>& out) const;
  /// "elbow" (two links) or "joint k", and "tip".
  std::string control_point_name(int i) const;
  /// JSON: {"type": "arm2", "base": [x, y], "lengths": [l1, l2]} or {"type": "arm", ... 1 to
  /// kMaxLinks lengths}.
  static bool reads(const std::string& type) { return type == "arm2" || type == "arm"; }
  static ArmRobot from_json(const nlohmann::json& r, const std::string& type);
  void to_json(nlohmann::json& r) const;
};

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

}  // namespace csl
