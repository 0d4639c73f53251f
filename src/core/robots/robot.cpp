#include "core/robots/robot.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/base/overloaded.hpp"

namespace csl {

PolygonRobot make_polygon_robot(Polygon body) {
  double r2 = 0.0;
  for (const Vec2& v : body) r2 = std::max(r2, squared_length(v));
  return PolygonRobot{std::move(body), std::sqrt(r2)};
}

RobotKind robot_kind(const Robot& r) {
  return std::visit(Overloaded{[](const PointRobot&) { return RobotKind::Point; },
                               [](const ArmRobot&) { return RobotKind::Arm; },
                               [](const PolygonRobot&) { return RobotKind::RigidPolygon; }},
                    r);
}

bool is_two_link_arm(const Robot& r) {
  const auto* arm = std::get_if<ArmRobot>(&r);
  return arm && arm->links() == 2;
}

const char* robot_type_name(const Robot& r) {
  switch (robot_kind(r)) {
    case RobotKind::Point: return "point";
    case RobotKind::Arm: return std::get<ArmRobot>(r).links() == 2 ? "arm2" : "arm";
    case RobotKind::RigidPolygon: return "polygon";
  }
  return "";
}

int robot_dof(const Robot& r) {
  switch (robot_kind(r)) {
    case RobotKind::Point: return 2;
    case RobotKind::Arm: return std::get<ArmRobot>(r).links();
    case RobotKind::RigidPolygon: return 3;
  }
  return 0;
}

Space robot_space(const Robot& r, const Vec2& lo, const Vec2& hi) {
  switch (robot_kind(r)) {
    case RobotKind::Point: return Space::box({lo.x(), lo.y()}, {hi.x(), hi.y()});
    case RobotKind::Arm: return Space::torus(std::get<ArmRobot>(r).links());
    case RobotKind::RigidPolygon: {
      const double w = std::get<PolygonRobot>(r).radius;
      return Space::se2(lo.x(), lo.y(), hi.x(), hi.y(), w > 0.0 ? w : 1.0);
    }
  }
  return Space::box({lo.x(), lo.y()}, {hi.x(), hi.y()});
}

void arm_joints(const ArmRobot& arm, const Config& q, Vec2* out) {
  out[0] = arm.base;
  double angle = 0.0;  // 0 + theta1 is theta1 exactly: the 2-link arm's bits as they always were
  for (int i = 0; i < arm.links(); ++i) {
    angle += q[i];
    double s, c;
    det::sincos(angle, s, c);
    const double l = arm.length(i);
    out[i + 1] = Vec2(out[i].x() + l * c, out[i].y() + l * s);
  }
}

ArmPose arm_pose(const ArmRobot& arm, const Config& q) {
  Vec2 joints[ArmRobot::kMaxLinks + 1];
  arm_joints(arm, q, joints);
  return {joints[0], joints[1], joints[arm.links()]};
}

void polygon_pose(const PolygonRobot& robot, const Config& q, Polygon& out) {
  double s, c;
  det::sincos(q[2], s, c);
  out.resize(robot.body.size());
  for (std::size_t i = 0; i < robot.body.size(); ++i) {
    const Vec2& v = robot.body[i];
    out[i] = Vec2(q[0] + c * v.x() - s * v.y(), q[1] + s * v.x() + c * v.y());
  }
}

double motion_bound(const Robot& r, const Config& p, const Config& q) {
  switch (robot_kind(r)) {
    case RobotKind::Arm: {
      // sum_i l_i |d_1 + ... + d_i|, the running sum and the total from 0 (0 + x is x exactly:
      // two links give l1|d1| + l2|d1 + d2| to the bit, as before).
      const ArmRobot& arm = std::get<ArmRobot>(r);
      double rate = 0.0, total = 0.0;
      for (int i = 0; i < arm.links(); ++i) {
        rate += angle_difference(p[i], q[i]);
        total += arm.length(i) * std::fabs(rate);
      }
      return total;
    }
    case RobotKind::Point:
    case RobotKind::RigidPolygon: {
      const double dx = q[0] - p[0], dy = q[1] - p[1];
      const double translation = std::sqrt(dx * dx + dy * dy);
      if (const auto* poly = std::get_if<PolygonRobot>(&r))
        return translation + poly->radius * std::fabs(angle_difference(p[2], q[2]));
      return translation;
    }
  }
  return 0.0;
}

double motion_lipschitz(const Robot& r) {
  switch (robot_kind(r)) {
    case RobotKind::Point: return 1.0;
    case RobotKind::RigidPolygon: return std::sqrt(2.0);
    case RobotKind::Arm: {
      // |a|, a_j = l_j + ... + l_N, summed from the tip (two links: a = (l1 + l2, l2)) and
      // squared from the base, as sqrt((l1 + l2)^2 + l2^2) always was.
      const ArmRobot& arm = std::get<ArmRobot>(r);
      double a[ArmRobot::kMaxLinks] = {};
      double tail = 0.0;
      for (int j = arm.links() - 1; j >= 0; --j) a[j] = tail = arm.length(j) + tail;
      double sum = 0.0;
      for (int j = 0; j < arm.links(); ++j) sum += a[j] * a[j];
      return std::sqrt(sum);
    }
  }
  return 1.0;
}

}  // namespace csl
