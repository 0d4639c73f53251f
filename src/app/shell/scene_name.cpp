#include "app/shell/scene_name.hpp"

#include <cstring>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/shell/bundled_scenes.hpp"
#include "core/base/overloaded.hpp"

namespace csl::app {

namespace {

const std::string kEdited = " (edited)";

std::string without_mark(const std::string& name) {
  const bool marked = name.size() >= kEdited.size() && name.compare(name.size() - kEdited.size(), kEdited.size(), kEdited) == 0;
  return marked ? name.substr(0, name.size() - kEdited.size()) : name;
}

// FNV-1a over the numbers of the scene (its name aside): what refresh() compares each frame,
// instead of the JSON of a scene that may hold 1000 polygons.
struct Print {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  void num(double v) {
    if (v == 0.0) v = 0.0;  // -0 is 0 to the JSON comparison too
    bytes(&v, sizeof v);
  }
  void vec(const Vec2& v) {
    num(v.x());
    num(v.y());
  }
  void text(const std::string& s) { bytes(s.data(), s.size()); }
};

std::uint64_t content_print(const Scene& s) {
  Print p;
  p.vec(s.workspace_min);
  p.vec(s.workspace_max);
  p.text(robot_to_json(s.robot).dump());  // a few numbers (a robot is small)
  for (Eigen::Index i = 0; i < s.start.size(); ++i) p.num(s.start[i]);
  for (Eigen::Index i = 0; i < s.goal.size(); ++i) p.num(s.goal[i]);
  for (const Obstacle& o : s.obstacles) {
    p.num(static_cast<double>(o.index()));
    std::visit(Overloaded{[&](const Disk& d) {
                            p.vec(d.center);
                            p.num(d.radius);
                          },
                          [&](const PolygonObstacle& poly) {
                            for (const Vec2& v : poly.vertices) p.vec(v);
                          },
                          [&](const Wall& w) {
                            p.vec(w.a);
                            p.vec(w.b);
                          }},
               o);
  }
  return p.h;
}

// The bundled scene whose "name" is `name`, or null.
const Scene* bundled_named(const std::string& name) {
  static const std::vector<Scene> scenes = [] {
    std::vector<Scene> out;
    for (const BundledScene& b : bundled_scenes()) out.push_back(scene_from_string(b.json));
    return out;
  }();
  if (name.empty()) return nullptr;
  for (const Scene& s : scenes)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace

std::string edited_name(const std::string& name) {
  std::string base = without_mark(name);
  if (base.empty()) return base;
  if (base.size() + kEdited.size() > kMaxNameLength) {
    base.resize(kMaxNameLength - kEdited.size());
    while (!base.empty() && (static_cast<unsigned char>(base.back()) & 0xC0) == 0x80) base.pop_back();  // a whole character
    if (!base.empty() && (static_cast<unsigned char>(base.back()) & 0x80)) base.pop_back();                // its lead byte
  }
  return base + kEdited;
}

void SceneName::loaded(const Scene& scene) {
  const std::string base = without_mark(scene.name);
  bundled_ = bundled_named(base);
  if (bundled_) {
    origin_name_ = base;
  } else {
    own_ = scene;
    origin_name_ = scene.name;
  }
  has_origin_ = true;
  origin_print_ = content_print(origin());
  named_ = scene.name;
  seen_print_ = 0;  // refresh() looks at the content once more
}

void SceneName::refresh(Scene& scene) {
  if (!has_origin_ || scene.name != named_) loaded(scene);
  const std::uint64_t print = content_print(scene);
  if (print == seen_print_) return;
  const bool original = print == origin_print_ && same_content(scene, origin());
  scene.name = original ? origin_name_ : edited_name(origin_name_);
  named_ = scene.name;
  seen_print_ = print;
}

}  // namespace csl::app
