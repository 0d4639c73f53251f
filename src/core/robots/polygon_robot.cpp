#include "core/robots/polygon_robot.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/geometry/json_fields.hpp"

namespace csl {

PolygonRobot make_polygon_robot(Polygon body) {
  double r2 = 0.0;
  for (const Vec2& v : body) r2 = std::max(r2, squared_length(v));
  PolygonRobot robot;
  robot.body = std::move(body);
  robot.radius = std::sqrt(r2);
  return robot;
}

Space PolygonRobot::space(const Vec2& lo, const Vec2& hi) const {
  return Space::se2(lo.x(), lo.y(), hi.x(), hi.y(), radius > 0.0 ? radius : 1.0);
}

double PolygonRobot::motion_bound(const Config& p, const Config& q) const {
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  const double translation = std::sqrt(dx * dx + dy * dy);
  return translation + radius * std::fabs(angle_difference(p[2], q[2]));
}

double PolygonRobot::motion_lipschitz() const { return std::sqrt(2.0); }

void PolygonRobot::control_points(const Config& q, std::vector<ControlPoint>& out) const {
  double s, c;
  det::sincos(q[2], s, c);
  out.resize(body.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vec2& v = body[i];
    const Vec2 rv(c * v.x() - s * v.y(), s * v.x() + c * v.y());  // R(theta) v
    out[i].position = Vec2(q[0] + rv.x(), q[1] + rv.y());          // as polygon_pose
    out[i].jacobian.resize(2, 3);
    out[i].jacobian << 1.0, 0.0, -rv.y(), 0.0, 1.0, rv.x();
  }
}

PolygonRobot PolygonRobot::from_json(const nlohmann::json& r, const std::string&) {
  using namespace json_fields;
  expect_object(r, "robot", {"type", "vertices"});
  return make_polygon_robot(polygon(field(r, "vertices", "robot"), "robot.vertices", kMaxRobotVertices));
}

void PolygonRobot::to_json(nlohmann::json& r) const { r["vertices"] = json_fields::polygon_json(body); }

void polygon_pose(const PolygonRobot& robot, const Config& q, Polygon& out) {
  double s, c;
  det::sincos(q[2], s, c);
  out.resize(robot.body.size());
  for (std::size_t i = 0; i < robot.body.size(); ++i) {
    const Vec2& v = robot.body[i];
    out[i] = Vec2(q[0] + c * v.x() - s * v.y(), q[1] + s * v.x() + c * v.y());
  }
}

}  // namespace csl
