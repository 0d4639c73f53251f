#include "core/robot.hpp"

#include <algorithm>
#include <cmath>

#include "core/angles.hpp"
#include "core/detmath.hpp"

namespace csl {

PolygonRobot make_polygon_robot(Polygon body) {
  double r2 = 0.0;
  for (const Vec2& v : body) r2 = std::max(r2, squared_length(v));
  return PolygonRobot{std::move(body), std::sqrt(r2)};
}

const char* robot_type_name(const Robot& r) {
  static const char* const kNames[] = {"point", "arm2", "polygon"};
  return kNames[r.index()];
}

int robot_dof(const Robot& r) { return std::holds_alternative<PolygonRobot>(r) ? 3 : 2; }

Space robot_space(const Robot& r, const Vec2& lo, const Vec2& hi) {
  if (std::holds_alternative<ArmRobot>(r)) return Space::torus(2);
  if (const auto* poly = std::get_if<PolygonRobot>(&r)) {
    const double w = poly->radius;
    return Space::se2(lo.x(), lo.y(), hi.x(), hi.y(), w > 0.0 ? w : 1.0);
  }
  return Space::box({lo.x(), lo.y()}, {hi.x(), hi.y()});
}

ArmPose arm_pose(const ArmRobot& arm, const Config& q) {
  double s1, c1, s12, c12;
  det::sincos(q[0], s1, c1);
  det::sincos(q[0] + q[1], s12, c12);  // link 2's absolute angle
  const Vec2 elbow(arm.base.x() + arm.length1 * c1, arm.base.y() + arm.length1 * s1);
  return {arm.base, elbow, Vec2(elbow.x() + arm.length2 * c12, elbow.y() + arm.length2 * s12)};
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
  if (const auto* arm = std::get_if<ArmRobot>(&r)) {
    const double d1 = angle_difference(p[0], q[0]);
    const double d2 = angle_difference(p[1], q[1]);
    return arm->length1 * std::fabs(d1) + arm->length2 * std::fabs(d1 + d2);
  }
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  const double translation = std::sqrt(dx * dx + dy * dy);
  if (const auto* poly = std::get_if<PolygonRobot>(&r))
    return translation + poly->radius * std::fabs(angle_difference(p[2], q[2]));
  return translation;
}

double motion_lipschitz(const Robot& r) {
  if (const auto* arm = std::get_if<ArmRobot>(&r)) {
    const double a = arm->length1 + arm->length2, b = arm->length2;
    return std::sqrt(a * a + b * b);
  }
  return std::holds_alternative<PolygonRobot>(r) ? std::sqrt(2.0) : 1.0;
}

}  // namespace csl
