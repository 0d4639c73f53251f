#include "core/scene/narrow_passage.hpp"

#include <stdexcept>

namespace csl {

Scene narrow_passage_scene(double width) {
  if (!in_range(kPassageWidth, width)) throw std::invalid_argument(param_error(kPassageWidth));
  const double x0 = 0.5 - 0.5 * kPassageWallThickness, x1 = 0.5 + 0.5 * kPassageWallThickness;
  const double low = 0.5 - 0.5 * width, high = 0.5 + 0.5 * width;
  Scene s;
  s.name = "A narrow passage of width " + param_value_text(kPassageWidth, width);
  s.workspace_min = Vec2(0.0, 0.0);
  s.workspace_max = Vec2(1.0, 1.0);
  s.robot = PointRobot{};
  s.obstacles.push_back(PolygonObstacle{{Vec2(x0, 0.0), Vec2(x1, 0.0), Vec2(x1, low), Vec2(x0, low)}});
  s.obstacles.push_back(PolygonObstacle{{Vec2(x0, high), Vec2(x1, high), Vec2(x1, 1.0), Vec2(x0, 1.0)}});
  s.start = config({0.1, 0.8});
  s.goal = config({0.9, 0.2});
  return s;
}

}  // namespace csl
