#pragma once
// Artificial potential fields in the workspace, mapped to configuration space (homework P13;
// Spong, Hutchinson and Vidyasagar, "Robot Modeling and Control" (2006), section 5.2, here "SHV").
//
// The field acts on control points o_i(q) of the robot, not on the whole body:
//   point robot: the point; 2-link arm: the elbow and the tip (the base never moves);
//   polygon robot: its vertices, in body order (P13: "the repulsive forces act only at the four
//   vertices"), attracted each to where it is at the goal configuration.
// Each control point feels
//   an attractive potential toward its goal position o_i(q_f), quadratic near it and conic far
//   away (one switch distance d; U and F = -grad U continuous at |e| = d, e = o_i(q) - o_i(q_f)):
//     |e| <= d:  U = 1/2 zeta |e|^2,            F = -zeta e
//     |e| >  d:  U = d zeta |e| - 1/2 zeta d^2,  F = -d zeta e / |e|
//   a repulsive potential from each obstacle j, with rho = rho_j(o_i(q)) (obstacle_distance.hpp):
//     rho <= rho0: U = 1/2 eta (1/rho - 1/rho0)^2,  F = eta (1/rho - 1/rho0) (1/rho^2) grad rho
//     rho >  rho0: U = 0, F = 0
//   (SHV eqs (5.5), (5.6)). Every obstacle has its own field and they add up; with regions of
//   influence that do not overlap (P13's choice of rho0) only the nearest obstacle matters.
//   On or inside an obstacle (rho = 0) U is +infinity and F points along grad rho with infinite
//   length: components +-infinity, 0 where grad rho has a zero component. Free configurations
//   never get there (their control points are off every obstacle), so planners never see it.
// The configuration-space force is tau(q) = sum_i J_i(q)^T F_i = -grad_q U(q) (SHV section 5.2.3,
// Example 5.6), J_i the Jacobian of o_i with respect to q:
//   point:   J = I;
//   polygon: o = (x, y) + R(theta) v, J = [[1, 0, -(R v)_y], [0, 1, (R v)_x]]: tau = (force,
//            torque about the reference point);
//   arm:     elbow = base + l1 (c1, s1), tip = elbow + l2 (c12, s12):
//            J_elbow = [[-l1 s1, 0], [l1 c1, 0]],
//            J_tip   = [[-l1 s1 - l2 s12, -l2 s12], [l1 c1 + l2 c12, l2 c12]]: tau = joint torques.
// Sums run over control points in order, then obstacles in scene order, with plain loops (no
// vectorised reductions) and the lab's own sine and cosine: the same bits natively and in wasm.
#include <string>
#include <vector>

#include "core/base/params.hpp"
#include "core/checking/collision.hpp"
#include "core/geometry/obstacle_distance.hpp"

namespace csl {

/// The field's constants, the same at every control point. Defaults suit a unit workspace: a
/// control point feels at most d zeta = 0.2 of attraction; the repulsion matches that at about
/// rho = 0.06 and is 10 at rho = 0.02 (and only within rho0 = 0.1 of an obstacle).
struct PotentialParams {
  // The defaults are the specs' (core/base/params.hpp: the CLI's and the API's ranges).
  double zeta = kFieldZeta.def;              ///< attractive gain
  double switch_distance = kFieldSwitch.def;  ///< d: quadratic within d of the goal position, conic beyond
  double eta = kFieldEta.def;                ///< repulsive gain
  double rho0 = kFieldRho0.def;              ///< region of influence of every obstacle
  /// What is wrong (e.g. "rho0 must be > 0"), or "" if the parameters are usable.
  std::string problem() const;
};

/// A potential U and its force F = -grad U at one workspace point.
struct FieldValue {
  double U = 0.0;
  Vec2 F{0.0, 0.0};
};

/// The attractive field at x toward `goal`: quadratic within d, conic beyond (file comment).
FieldValue attractive_field(const Vec2& x, const Vec2& goal, double zeta, double d);
/// The repulsive field of one obstacle, given rho and grad rho there (SHV (5.5), (5.6)).
FieldValue repulsive_field(const ObstacleDistance& r, double eta, double rho0);

// Control points, their Jacobians and names: each robot type's (core/robots/robot.hpp).

/// J^T F: the configuration-space force of a workspace force F applied at a control point.
Config generalized_force(const PointJacobian& jacobian, const Vec2& force);

/// One obstacle's share of a control point's repulsion.
struct RepulsiveTerm {
  int obstacle = -1;  ///< scene index
  ObstacleDistance distance;
  FieldValue field;
};

/// Everything about one control point, for the CLI and the lessons.
struct ControlPointReport {
  Vec2 position{0.0, 0.0};
  Vec2 goal{0.0, 0.0};  ///< o_i(q_f)
  PointJacobian jacobian;
  int nearest_obstacle = -1;  ///< the obstacle of least rho (ties: lower index); -1: no obstacles
  ObstacleDistance nearest;   ///< rho and grad rho to it (rho = +infinity without obstacles)
  FieldValue attractive;
  FieldValue repulsive;               ///< summed over the obstacles within rho0
  std::vector<RepulsiveTerm> terms;   ///< those obstacles (rho <= rho0), in scene order
  Config tau;                         ///< J^T (F_att + F_rep)
};

/// The whole field at one configuration.
struct PotentialReport {
  std::vector<ControlPointReport> points;
  double U_att = 0.0, U_rep = 0.0, U = 0.0;
  Vec2 F_att{0.0, 0.0}, F_rep{0.0, 0.0}, F{0.0, 0.0};  ///< workspace sums over control points
  Config tau_att, tau_rep, tau;  ///< configuration-space forces: sum J^T F
  bool contact = false;          ///< some control point is on or inside an obstacle (U infinite)
};

/// The potential field of a world toward one goal configuration.
class PotentialField {
 public:
  /// The world must outlive the field. Throws std::invalid_argument for bad parameters or a
  /// goal of the wrong dimension.
  PotentialField(const CollisionWorld& world, const Config& goal, PotentialParams params = {});
  PotentialField(CollisionWorld&&, const Config&, PotentialParams = {}) = delete;

  const CollisionWorld& world() const { return *world_; }
  const Config& goal() const { return goal_; }
  const PotentialParams& params() const { return params_; }
  /// o_i(q_f), the control points' goal positions.
  const std::vector<Vec2>& goal_positions() const { return goal_positions_; }

  /// U(q) and tau(q) = -grad_q U(q), the quantities gradient descent needs.
  struct Gradient {
    double U = 0.0;
    Config tau;
  };
  /// Fast: skips obstacles whose bounding box is farther than rho0; reuses scratch storage
  /// (like CollisionWorld, one field is not for concurrent use).
  Gradient gradient(const Config& q) const;
  double potential(const Config& q) const { return gradient(q).U; }
  /// The full breakdown per control point (same totals as gradient(), bit for bit).
  PotentialReport evaluate(const Config& q) const;

 private:
  const CollisionWorld* world_;
  Config goal_;
  PotentialParams params_;
  std::vector<Vec2> goal_positions_;
  std::vector<Box> boxes_;  // obstacle bounds
  mutable std::vector<ControlPoint> scratch_;
};

}  // namespace csl
