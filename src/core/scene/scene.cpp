#include "core/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <nlohmann/json.hpp>

#include "core/base/angles.hpp"
#include "core/base/overloaded.hpp"
#include "core/base/text.hpp"
#include "core/geometry/json_fields.hpp"

namespace csl {
namespace {

using json = nlohmann::json;

using namespace json_fields;

Obstacle obstacle(const json& o, const std::string& path) {
  if (!o.is_object()) fail(path, "must be an object");
  const json& type = field(o, "type", path);
  if (type == "disk") {
    expect_object(o, path, {"type", "center", "radius"});
    Disk d{point(field(o, "center", path), path + ".center"), number(field(o, "radius", path), path + ".radius")};
    if (d.radius < 0.0) fail(path + ".radius", "must be >= 0");
    return d;
  }
  if (type == "polygon") {
    expect_object(o, path, {"type", "vertices"});
    return PolygonObstacle{polygon(field(o, "vertices", path), path + ".vertices", kMaxPolygonVertices)};
  }
  if (type == "segment") {
    expect_object(o, path, {"type", "a", "b"});
    return Wall{point(field(o, "a", path), path + ".a"), point(field(o, "b", path), path + ".b")};
  }
  fail(path + ".type", "unknown obstacle type " + value_text(type) + " (disk, polygon or segment)");
}

Config configuration(const json& j, const char* name, const Robot& r, const Vec2& lo, const Vec2& hi) {
  const int dof = robot_dof(r);
  const std::string path = name;
  if (!j.is_array() || static_cast<int>(j.size()) != dof)
    fail(path, std::string("must be an array of ") + std::to_string(dof) + " numbers for robot type '" +
                   robot_type_name(r) + "'");
  Config q(dof);
  for (int i = 0; i < dof; ++i) q[i] = number(j[static_cast<std::size_t>(i)], path + "[" + std::to_string(i) + "]");
  switch (robot_kind(r)) {
    case RobotKind::Arm:
      for (int i = 0; i < dof; ++i) q[i] = wrap_angle(q[i]);
      break;
    case RobotKind::Point:
    case RobotKind::RigidPolygon:
      if (q[0] < lo.x() || q[0] > hi.x() || q[1] < lo.y() || q[1] > hi.y())
        fail(path, "must lie inside the workspace");
      if (robot_kind(r) == RobotKind::RigidPolygon) q[2] = wrap_angle(q[2]);
      break;
  }
  return q;
}

}  // namespace

std::string obstacle_problem(const Obstacle& o, const std::string& path) {
  try {
    (void)obstacle(obstacle_to_json(o), path);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

json config_to_json(const Config& q) {
  json out = json::array();
  for (Eigen::Index i = 0; i < q.size(); ++i) out.push_back(q[i]);
  return out;
}

json obstacle_to_json(const Obstacle& o) {
  return std::visit(
      Overloaded{[](const Disk& d) -> json { return {{"type", "disk"}, {"center", point_json(d.center)}, {"radius", d.radius}}; },
                 [](const PolygonObstacle& p) -> json { return {{"type", "polygon"}, {"vertices", polygon_json(p.vertices)}}; },
                 [](const Wall& w) -> json { return {{"type", "segment"}, {"a", point_json(w.a)}, {"b", point_json(w.b)}}; }},
      o);
}

Scene scene_from_json(const json& j) {
  expect_object(j, "", {"version", "name", "workspace", "robot", "obstacles", "start", "goal"});
  const json& version = field(j, "version", "");
  if (!version.is_number_integer() || version.get<long long>() != 1) fail("version", "must be 1");

  Scene s;
  if (auto n = j.find("name"); n != j.end()) {
    if (!n->is_string()) fail("name", "must be a string");
    s.name = n->get<std::string>();
    if (s.name.size() > kMaxNameLength) fail("name", "is longer than 200 characters");
  }
  if (auto ws = j.find("workspace"); ws != j.end()) {
    expect_object(*ws, "workspace", {"min", "max"});
    s.workspace_min = point(field(*ws, "min", "workspace"), "workspace.min");
    s.workspace_max = point(field(*ws, "max", "workspace"), "workspace.max");
    if (!(s.workspace_min.x() < s.workspace_max.x() && s.workspace_min.y() < s.workspace_max.y()))
      fail("workspace", "min must be below max in both coordinates");
    const double w = s.workspace_max.x() - s.workspace_min.x(), h = s.workspace_max.y() - s.workspace_min.y();
    if (!(w >= kMinWorkspaceExtent && h >= kMinWorkspaceExtent))
      fail("workspace", "each side must be at least 0.001 long (it is " + shortest(w) + " by " + shortest(h) + ")");
    if (std::max(w, h) > kMaxWorkspaceAspect * std::min(w, h))
      fail("workspace", "one side may be at most 100 times the other (it is " + shortest(w) + " by " + shortest(h) + ")");
  }
  if (auto r = j.find("robot"); r != j.end()) s.robot = robot_from_json(*r);
  if (auto obs = j.find("obstacles"); obs != j.end()) {
    if (!obs->is_array()) fail("obstacles", "must be an array");
    if (obs->size() > kMaxObstacles) fail("obstacles", "more than " + std::to_string(kMaxObstacles) + " obstacles");
    for (std::size_t i = 0; i < obs->size(); ++i)
      s.obstacles.push_back(obstacle((*obs)[i], "obstacles[" + std::to_string(i) + "]"));
  }
  switch (robot_kind(s.robot)) {
    case RobotKind::Arm:  // all joints at 0, and the first turned a quarter
      s.start = Config::Zero(robot_dof(s.robot));
      s.goal = Config::Zero(robot_dof(s.robot));
      s.goal[0] = kPi / 2;
      break;
    case RobotKind::Point:
      s.start = config({s.workspace_min.x(), s.workspace_min.y()});
      s.goal = config({s.workspace_max.x(), s.workspace_max.y()});
      break;
    case RobotKind::RigidPolygon:
      s.start = config({s.workspace_min.x(), s.workspace_min.y(), 0.0});
      s.goal = config({s.workspace_max.x(), s.workspace_max.y(), 0.0});
      break;
  }
  if (auto st = j.find("start"); st != j.end())
    s.start = configuration(*st, "start", s.robot, s.workspace_min, s.workspace_max);
  if (auto g = j.find("goal"); g != j.end())
    s.goal = configuration(*g, "goal", s.robot, s.workspace_min, s.workspace_max);
  return s;
}

json parse_json_text(const std::string& text) {
  // nlohmann's parser reads a NUL byte as the end of the input, so "{...}\0garbage" would pass.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw std::invalid_argument("not valid JSON (a NUL byte at byte " + std::to_string(nul) + ")");
  // The callback sees each value's depth as it is read: past the limit the parse stops there,
  // before anything deep is built.
  struct TooDeep {};
  const json::parser_callback_t depth_limit = [](int depth, json::parse_event_t, json&) {
    if (depth >= kMaxJsonDepth) throw TooDeep{};
    return true;
  };
  try {
    json j = json::parse(text, depth_limit, /*allow_exceptions=*/false);
    if (j.is_discarded()) throw std::invalid_argument("not valid JSON");
    return j;
  } catch (const TooDeep&) {
    throw std::invalid_argument("nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
  }
}

Scene scene_from_string(const std::string& text) {
  if (text.size() > kMaxSceneBytes) throw SceneError("scene: larger than 64 MB, more than any scene within the limits");
  json j;
  try {
    j = parse_json_text(text);
  } catch (const std::invalid_argument& e) {
    throw SceneError(std::string("scene: ") + e.what());
  }
  return scene_from_json(j);
}

bool same_scene(const Scene& a, const Scene& b) { return scene_to_json(a) == scene_to_json(b); }

bool same_content(const Scene& a, const Scene& b) {
  json x = scene_to_json(a), y = scene_to_json(b);
  x.erase("name");
  y.erase("name");
  return x == y;
}

json scene_to_json(const Scene& s) {
  json obstacles = json::array();
  for (const Obstacle& o : s.obstacles) obstacles.push_back(obstacle_to_json(o));
  const json robot_json = robot_to_json(s.robot);
  json out{{"version", 1},
           {"workspace", {{"min", point_json(s.workspace_min)}, {"max", point_json(s.workspace_max)}}},
           {"robot", robot_json},
           {"obstacles", obstacles},
           {"start", config_to_json(s.start)},
           {"goal", config_to_json(s.goal)}};
  if (!s.name.empty()) out["name"] = s.name;
  return out;
}

std::string obstacle_label(const Scene& scene, int index) {
  if (index < 0 || index >= static_cast<int>(scene.obstacles.size())) return "an obstacle";
  std::string type = obstacle_type_name(scene.obstacles[static_cast<std::size_t>(index)]);
  if (type == "segment") type = "wall";
  return type + " " + std::to_string(index + 1);
}

}  // namespace csl
