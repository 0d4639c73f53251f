#pragma once
// The scenes in assets/scenes, compiled into the app (cmake/EmbedScenesScript.cmake): lessons
// start from them and URLs name them (?scene=p12).
#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace csl::app {

struct BundledScene {
  const char* name;  ///< the file name without .json, e.g. "p12"
  const char* json;
};
const std::vector<BundledScene>& bundled_scenes();

/// The bundled scene of that name, parsed; throws SceneError if there is none (or it is bad).
Scene bundled_scene(const std::string& name);

}  // namespace csl::app
