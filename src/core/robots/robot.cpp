#include "core/robots/robot.hpp"

#include <nlohmann/json.hpp>

#include "core/base/overloaded.hpp"
#include "core/geometry/json_fields.hpp"

namespace csl {

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
  return std::visit([](const auto& robot) { return robot.type_name(); }, r);
}

int robot_dof(const Robot& r) {
  return std::visit([](const auto& robot) { return robot.dof(); }, r);
}

Space robot_space(const Robot& r, const Vec2& lo, const Vec2& hi) {
  return std::visit([&](const auto& robot) { return robot.space(lo, hi); }, r);
}

double motion_bound(const Robot& r, const Config& p, const Config& q) {
  return std::visit([&](const auto& robot) { return robot.motion_bound(p, q); }, r);
}

double motion_lipschitz(const Robot& r) {
  return std::visit([](const auto& robot) { return robot.motion_lipschitz(); }, r);
}

void control_points(const Robot& robot, const Config& q, std::vector<ControlPoint>& out) {
  std::visit([&](const auto& r) { r.control_points(q, out); }, robot);
}

std::vector<ControlPoint> control_points(const Robot& robot, const Config& q) {
  std::vector<ControlPoint> out;
  control_points(robot, q, out);
  return out;
}

std::string control_point_name(const Robot& robot, int i) {
  return std::visit([&](const auto& r) { return r.control_point_name(i); }, robot);
}

namespace {
// Tries each type of the variant in turn: the first whose reads() takes `name` parses it; none
// does: the error names `type` as the scene gave it (a string or any other JSON value).
template <std::size_t I = 0>
Robot read_robot(const nlohmann::json& r, const std::string& name, const nlohmann::json& type) {
  if constexpr (I < std::variant_size_v<Robot>) {
    using Type = std::variant_alternative_t<I, Robot>;
    if (Type::reads(name)) return Type::from_json(r, name);
    return read_robot<I + 1>(r, name, type);
  } else {
    json_fields::fail("robot.type", "unknown robot type " + json_fields::value_text(type) +
                                        " (point, arm2, arm or polygon)");
  }
}
}  // namespace

Robot robot_from_json(const nlohmann::json& r) {
  if (!r.is_object()) json_fields::fail("robot", "must be an object");
  const nlohmann::json& type = json_fields::field(r, "type", "robot");
  // A type that is no string is no type's name: "" is read by none.
  return read_robot(r, type.is_string() ? type.get<std::string>() : std::string(), type);
}

nlohmann::json robot_to_json(const Robot& r) {
  nlohmann::json out{{"type", robot_type_name(r)}};
  std::visit([&](const auto& robot) { robot.to_json(out); }, r);
  return out;
}

}  // namespace csl
