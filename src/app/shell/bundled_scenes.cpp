#include "app/shell/bundled_scenes.hpp"

namespace csl::app {

Scene bundled_scene(const std::string& name) {
  for (const BundledScene& s : bundled_scenes())
    if (name == s.name) return scene_from_string(s.json);
  throw SceneError("no bundled scene named '" + name + "'");
}

}  // namespace csl::app
