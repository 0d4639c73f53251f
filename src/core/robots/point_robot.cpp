#include "core/robots/point_robot.hpp"

#include <cmath>

#include "core/geometry/json_fields.hpp"

namespace csl {

Space PointRobot::space(const Vec2& lo, const Vec2& hi) const { return Space::box({lo.x(), lo.y()}, {hi.x(), hi.y()}); }

double PointRobot::motion_bound(const Config& p, const Config& q) const {
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  return std::sqrt(dx * dx + dy * dy);
}

void PointRobot::control_points(const Config& q, std::vector<ControlPoint>& out) const {
  out.resize(1);
  out[0].position = Vec2(q[0], q[1]);
  out[0].jacobian.resize(2, 2);
  out[0].jacobian << 1.0, 0.0, 0.0, 1.0;
}

PointRobot PointRobot::from_json(const nlohmann::json& r, const std::string&) {
  json_fields::expect_object(r, "robot", {"type"});
  return PointRobot{};
}

void PointRobot::to_json(nlohmann::json&) const {}

}  // namespace csl
