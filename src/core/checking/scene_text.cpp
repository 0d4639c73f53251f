#include "core/checking/scene_text.hpp"

#include <variant>

#include "core/base/overloaded.hpp"
#include "core/base/text.hpp"

namespace csl {
namespace {

std::string point_text(const Vec2& p) { return "(" + significant(p.x()) + ", " + significant(p.y()) + ")"; }

std::string robot_text(const Robot& r) {
  switch (robot_kind(r)) {
    case RobotKind::Point:
      return "a point robot (its configuration is its position)";
    case RobotKind::Arm:
      return "an arm of " + std::to_string(robot_dof(r)) + " links (a configuration is its joint angles in radians)";
    case RobotKind::RigidPolygon:
      return "a polygon robot (a configuration is x, y and its angle in radians)";
  }
  return "";
}

std::string obstacle_text(const Obstacle& o, std::size_t i) {
  const std::string n = std::to_string(i + 1);
  return std::visit(Overloaded{[&](const Disk& d) {
                                 return "disk " + n + " at " + point_text(d.center) + ", radius " + significant(d.radius);
                               },
                               [&](const PolygonObstacle& p) {
                                 Vec2 mean(0.0, 0.0);
                                 for (const Vec2& v : p.vertices) mean += v;
                                 if (!p.vertices.empty()) mean /= static_cast<double>(p.vertices.size());
                                 return "polygon " + n + " with " + std::to_string(p.vertices.size()) +
                                        " vertices around " + point_text(mean);
                               },
                               [&](const Wall& w) {
                                 return "wall " + n + " from " + point_text(w.a) + " to " + point_text(w.b);
                               }},
                    o);
}

}  // namespace

std::string config_text(const Config& q) {
  std::string out = "(";
  for (Eigen::Index i = 0; i < q.size(); ++i) out += (i ? ", " : "") + significant(q[i]);
  return out + ")";
}

std::string describe_scene(const Scene& s, const CollisionWorld& world) {
  std::string out = "The workspace spans x from " + significant(s.workspace_min.x()) + " to " +
                    significant(s.workspace_max.x()) + " and y from " + significant(s.workspace_min.y()) + " to " +
                    significant(s.workspace_max.y()) + ". The robot is " + robot_text(s.robot) + ". ";
  if (s.obstacles.empty()) {
    out += "There are no obstacles.";
  } else {
    out += std::to_string(s.obstacles.size()) + (s.obstacles.size() == 1 ? " obstacle: " : " obstacles: ");
    for (std::size_t i = 0; i < s.obstacles.size(); ++i) out += (i ? "; " : "") + obstacle_text(s.obstacles[i], i);
    out += ".";
  }
  const auto where = [&](const char* name, const Config& q) {
    return std::string(" ") + name + " at " + config_text(q) + ", " +
           (world.is_free(q) ? "free." : "in collision (inside an obstacle).");
  };
  return out + where("Start", s.start) + where("Goal", s.goal);
}

}  // namespace csl
