#include "core/scene.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace csl {
namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw SceneError(path + ": " + what);
}

const json& field(const json& obj, const char* key, const std::string& path) {
  auto it = obj.find(key);
  if (it == obj.end()) fail(path.empty() ? key : path + "." + key, "missing");
  return *it;
}

double number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, "must be a number");
  double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "must be finite");
  return v;
}

Vec2 point(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 2) fail(path, "must be an array of 2 numbers");
  return {number(j[0], path + "[0]"), number(j[1], path + "[1]")};
}

json point_json(const Vec2& p) { return json::array({p.x(), p.y()}); }

Disk disk(const json& j, const std::string& path) {
  Disk d;
  d.center = point(field(j, "center", path), path + ".center");
  d.radius = number(field(j, "radius", path), path + ".radius");
  if (d.radius < 0.0) fail(path + ".radius", "must be >= 0");
  return d;
}

}  // namespace

Scene scene_from_json(const json& j) {
  if (!j.is_object()) fail("scene", "must be a JSON object");
  const json& version = field(j, "version", "");
  if (!version.is_number_integer() || version.get<int>() != 1) fail("version", "must be 1");

  Scene s;
  if (auto robot = j.find("robot"); robot != j.end()) {
    if (!robot->is_object()) fail("robot", "must be an object");
    const json& type = field(*robot, "type", "robot");
    if (type != "point") fail("robot.type", "unknown robot type " + type.dump());
  }
  if (auto ws = j.find("workspace"); ws != j.end()) {
    s.workspace_min = point(field(*ws, "min", "workspace"), "workspace.min");
    s.workspace_max = point(field(*ws, "max", "workspace"), "workspace.max");
    if (!(s.workspace_min.array() < s.workspace_max.array()).all())
      fail("workspace", "min must be below max in both coordinates");
  }
  if (auto obs = j.find("obstacles"); obs != j.end()) {
    if (!obs->is_array()) fail("obstacles", "must be an array");
    for (std::size_t i = 0; i < obs->size(); ++i) {
      const std::string path = "obstacles[" + std::to_string(i) + "]";
      const json& o = (*obs)[i];
      if (!o.is_object()) fail(path, "must be an object");
      const json& type = field(o, "type", path);
      if (type != "disk") fail(path + ".type", "unknown obstacle type " + type.dump());
      s.disks.push_back(disk(o, path));
    }
  }
  if (auto st = j.find("start"); st != j.end()) s.start = point(*st, "start");
  if (auto g = j.find("goal"); g != j.end()) s.goal = point(*g, "goal");
  return s;
}

Scene scene_from_string(const std::string& text) {
  json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) throw SceneError("scene: not valid JSON");
  return scene_from_json(j);
}

json scene_to_json(const Scene& s) {
  json obstacles = json::array();
  for (const Disk& d : s.disks)
    obstacles.push_back({{"type", "disk"}, {"center", point_json(d.center)}, {"radius", d.radius}});
  return {{"version", 1},
          {"workspace", {{"min", point_json(s.workspace_min)}, {"max", point_json(s.workspace_max)}}},
          {"robot", {{"type", "point"}}},
          {"obstacles", obstacles},
          {"start", point_json(s.start)},
          {"goal", point_json(s.goal)}};
}

}  // namespace csl
