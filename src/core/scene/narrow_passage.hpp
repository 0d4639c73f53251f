#pragma once
// The narrow-passage scene whose gap is a parameter (the Compare planners lesson's slider, and
// tests): a wall across the unit square with a gap of width w in its middle, start and goal on
// either side. Uniform sampling lands in the gap with a chance proportional to w, which is what
// the lesson lets a student see starve a planner. Pure geometry, so that tests build the same
// scene the lesson shows.
#include "core/base/params.hpp"
#include "core/scene/scene.hpp"

namespace csl {

/// w: the gap's width (0: a closed wall, no path). The wall is kPassageWallThickness thick.
inline constexpr ParamSpec kPassageWidth{"passage", "", false, 0.0, 0.5, 0.08, 0.005, "",
                                         "the width of the gap in the wall (0: closed)"};
inline constexpr double kPassageWallThickness = 0.2;

/// The scene for gap width `width`: workspace [0, 1]^2, a point robot, two rectangles
/// x in [0.4, 0.6] from y = 0 up to 0.5 - w/2 and from 0.5 + w/2 up to 1, start (0.1, 0.8) and
/// goal (0.9, 0.2). Throws std::invalid_argument (kPassageWidth's one-line error) for a width
/// outside its range.
Scene narrow_passage_scene(double width);

}  // namespace csl
