#pragma once
// The scene in words, for the page's text description of what the lab shows (web/lab-access.js
// reads it through the app's "describe" command): a screen reader gets from it what the canvas
// draws. Numbers to 4 significant digits (significant()).
#include <string>

#include "core/checking/collision.hpp"
#include "core/scene/scene.hpp"

namespace csl {

/// "(0.1, 0.2)": a configuration's coordinates to 4 significant digits.
std::string config_text(const Config& q);

/// Sentences: the workspace's bounds, the robot, each obstacle (disk: centre and radius;
/// polygon: vertex count and the mean of its vertices; wall: its ends), then start and goal
/// and whether each is free in `world` (the scene's collision world).
std::string describe_scene(const Scene& scene, const CollisionWorld& world);

}  // namespace csl
