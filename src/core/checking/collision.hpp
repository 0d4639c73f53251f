#pragma once
// Collision queries of one robot among a scene's obstacles: the clearance eta(q), whether q is
// free, which obstacle is nearest, and the motion bound lambda(p, q).
#include <cstdint>
#include <vector>

#include "core/geometry/obstacles.hpp"
#include "core/robots/robot.hpp"
#include "core/spaces/space.hpp"

namespace csl {

struct Scene;

class CollisionWorld {
 public:
  CollisionWorld(Robot robot, std::vector<Obstacle> obstacles, const Vec2& workspace_min,
                 const Vec2& workspace_max);
  explicit CollisionWorld(const Scene& scene);

  const Space& space() const { return space_; }
  const Robot& robot() const { return robot_; }
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }

  /// The clearance and the obstacle (scene index) that attains it; -1 when there are none.
  struct Nearest {
    double clearance;
    int obstacle;
  };
  Nearest nearest(const Config& q) const;
  /// nearest(q).obstacle, not counted in configurations_tested(): for naming the obstacle of a
  /// configuration is_free() or clearance() refused already (the event log's words), which
  /// tests nothing new.
  int obstacle_hit(const Config& q) const { return nearest_of(q).obstacle; }

  /// eta(q): the least distance from the robot at q to any obstacle (+infinity with none).
  /// <= 0 means collision; negative values, where cheap to know, tell how deep.
  double clearance(const Config& q) const;

  /// Whether q is collision-free: exactly clearance(q) > 0, but faster (it stops at the first
  /// hit and mostly compares squared distances).
  bool is_free(const Config& q) const;

  /// Configurations given to this world's checker so far: every is_free(), clearance() and
  /// nearest() call (clearance() that asks nearest() counts once; obstacle_hit() not at all).
  /// The one place the
  /// planners' "configurations tested" is counted, so that it means the same for every planner
  /// (Planner::configurations_tested() takes its differences). Counts only: no answer changes.
  /// Unsigned and 64-bit: it only grows while the world lives (an experiment's many runs), and
  /// differences of it stay exact past any wrap, in wasm as natively.
  std::uint64_t configurations_tested() const { return tested_; }

  /// The largest coordinate magnitude the scene reaches (workspace, obstacles, the arm's reach):
  /// rounding errors in poses and distances scale with it.
  double scale() const { return scale_; }

  /// What evaluating one configuration (clearance() or is_free()) costs at most, in units of
  /// one primitive distance test (the robot's point, link or edge against a disk, a wall or one
  /// polygon edge), plus one bounding-box test per obstacle: the measure of work the lab's
  /// budgets count in (work.hpp). An upper estimate: the boxes prune most obstacles far from
  /// the robot. At least 1.
  double evaluation_cost() const { return evaluation_cost_; }

  /// lambda(p, q) for this robot (see motion_bound in robot.hpp).
  double motion_bound(const Config& p, const Config& q) const { return csl::motion_bound(robot_, p, q); }
  /// The same, given the space's distance from p to q (Space::distance(p, q)): for the point
  /// robot that is lambda itself, bit for bit (the square root of the same sum of the same
  /// squares), so it is not computed again; the other robots compute theirs.
  double motion_bound(const Config& p, const Config& q, double distance) const {
    return kind_ == RobotKind::Point ? distance : csl::motion_bound(robot_, p, q);
  }

 private:
  // Disks get a fast path (most scenes are mostly disks): centre, radius, and the squared
  // distance beyond which the robot certainly clears the disk without taking a square root.
  struct DiskData {
    double x, y, r, far2;
    Box box;
    int index;
  };
  // Polygons and walls: the general path, behind a bounding-box test.
  struct ShapeData {
    Box box;
    int index;
  };
  // nearest(), uncounted (clearance() and obstacle_hit() call it).
  Nearest nearest_of(const Config& q) const;
  // The robot's shape at q, in scratch storage (the world is not for concurrent use).
  void pose(const Config& q) const;
  // Point robot and arm: squared distance from c to the robot (its point or its links).
  // Called for the robot kinds without an area (point, arm): the polygon's is polygon_.
  double skeleton_squared_distance(const Vec2& c) const;
  double disk_clearance(const DiskData& d) const;
  double clearance_to(const Obstacle& o) const;

  Robot robot_;
  RobotKind kind_;  // robot_kind(robot_), switched on in the hot loops (no default: each kind)
  int links_ = 0;   // the arm's
  std::vector<Obstacle> obstacles_;
  std::vector<DiskData> disks_;
  // The disks' centres and radii again, each in an array of its own: clearance() of the point
  // robot measures all of them in a loop the compiler vectorises (two square roots at once).
  std::vector<double> disk_x_, disk_y_, disk_r_;
  std::vector<ShapeData> shapes_;

  Space space_;
  double scale_ = 0.0;
  double evaluation_cost_ = 1.0;
  mutable Vec2 point_;           // point robot
  mutable Vec2 joints_[ArmRobot::kMaxLinks + 1];  // arm: base, the end of each link
  mutable Polygon polygon_;      // polygon robot
  mutable Box robot_box_;
  mutable std::uint64_t tested_ = 0;  // see configurations_tested()
};

}  // namespace csl
