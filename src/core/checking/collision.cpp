#include "core/checking/collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/scene/scene.hpp"

namespace csl {
namespace {

// Squared distance between two boxes: a lower bound on the distance between their contents.
double box_gap2(const Box& a, const Box& b) {
  const double gx = a.min.x() - b.max.x() > b.min.x() - a.max.x() ? a.min.x() - b.max.x() : b.min.x() - a.max.x();
  const double gy = a.min.y() - b.max.y() > b.min.y() - a.max.y() ? a.min.y() - b.max.y() : b.min.y() - a.max.y();
  const double dx = gx > 0.0 ? gx : 0.0, dy = gy > 0.0 ? gy : 0.0;
  return dx * dx + dy * dy;
}

// Pruning by squared distances must never change a result: compare against bounds inflated
// by far more than the rounding of the squares (relative 1e-12 against ~1e-16).
constexpr double kSafe = 1.0 + 1e-12;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Whether something at squared distance >= d2 from a shape of reach r cannot beat `best`.
bool cannot_beat(double d2, double r, double best) {
  const double reach = best + r;
  return reach <= 0.0 || d2 > reach * reach * kSafe;
}

}  // namespace

CollisionWorld::CollisionWorld(Robot robot, std::vector<Obstacle> obstacles, const Vec2& workspace_min,
                               const Vec2& workspace_max)
    : robot_(std::move(robot)),
      kind_(robot_kind(robot_)),
      obstacles_(std::move(obstacles)),
      space_(robot_space(robot_, workspace_min, workspace_max)) {
  const auto reach = [this](const Vec2& v) { scale_ = std::max({scale_, std::fabs(v.x()), std::fabs(v.y())}); };
  reach(workspace_min);
  reach(workspace_max);
  // The robot's parts each test against each obstacle's: a point (1), the arm's links, or the
  // polygon robot's edges.
  double parts = 1.0;
  switch (kind_) {
    case RobotKind::Point:
      break;
    case RobotKind::Arm: {
      const ArmRobot& arm = std::get<ArmRobot>(robot_);
      if (arm.links() < 1 || arm.links() > ArmRobot::kMaxLinks)
        throw std::invalid_argument("an arm has 1 to " + std::to_string(ArmRobot::kMaxLinks) + " links");
      links_ = arm.links();
      double extent = std::fabs(arm.base.x()) + std::fabs(arm.base.y());
      for (double l : arm.lengths) extent += l;
      scale_ = std::max(scale_, extent);
      parts = static_cast<double>(links_);
      break;
    }
    case RobotKind::RigidPolygon: {
      const PolygonRobot& poly = std::get<PolygonRobot>(robot_);
      scale_ += poly.radius;
      parts = static_cast<double>(poly.body.size());
      break;
    }
  }
  evaluation_cost_ = 1.0;
  for (const Obstacle& o : obstacles_) {
    const auto* poly = std::get_if<PolygonObstacle>(&o);
    evaluation_cost_ += 1.0 + parts * (poly ? static_cast<double>(poly->vertices.size()) : 1.0);
  }
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const Box box = obstacle_bounds(obstacles_[i]);
    reach(box.min);
    reach(box.max);
    if (const auto* d = std::get_if<Disk>(&obstacles_[i])) {
      const double far = d->radius * kSafe;
      disks_.push_back({d->center.x(), d->center.y(), d->radius, far * far * kSafe, box, static_cast<int>(i)});
      disk_x_.push_back(d->center.x());
      disk_y_.push_back(d->center.y());
      disk_r_.push_back(d->radius);
    } else {
      shapes_.push_back({box, static_cast<int>(i)});
    }
  }
}

CollisionWorld::CollisionWorld(const Scene& scene)
    : CollisionWorld(scene.robot, scene.obstacles, scene.workspace_min, scene.workspace_max) {}

void CollisionWorld::pose(const Config& q) const {
  switch (kind_) {
    case RobotKind::Point:
      point_ = Vec2(q[0], q[1]);
      robot_box_ = Box{point_, point_};
      break;
    case RobotKind::Arm: {
      arm_joints(std::get<ArmRobot>(robot_), q, joints_);
      Box box{joints_[0], joints_[0]};
      for (int i = 1; i <= links_; ++i) box = Box{box.min.cwiseMin(joints_[i]), box.max.cwiseMax(joints_[i])};
      robot_box_ = box;
      break;
    }
    case RobotKind::RigidPolygon:
      polygon_pose(std::get<PolygonRobot>(robot_), q, polygon_);
      robot_box_ = bounding_box(polygon_);
      break;
  }
}

double CollisionWorld::skeleton_squared_distance(const Vec2& c) const {
  // A switch without a default, here and below: a new robot kind is a compile error
  // (-Werror=switch) in each place that must decide what it is, not the arm's branch by default.
  switch (kind_) {
    case RobotKind::Point: {
      const double dx = point_.x() - c.x(), dy = point_.y() - c.y();
      return dx * dx + dy * dy;
    }
    case RobotKind::RigidPolygon:  // has no skeleton: its callers measure the polygon instead
    case RobotKind::Arm:
      break;
  }
  // The least over the links, each compared as "b < a ? b : a" from the base outwards (two
  // links: the expression of the 2-link arm, to the bit). The 2-link arm, which every lesson
  // shows, written out: the loop cost it 5-8 % of a roadmap's time (bench.prm).
  double least = point_segment_squared_distance(c, joints_[0], joints_[1]);
  if (links_ == 2) {
    const double b = point_segment_squared_distance(c, joints_[1], joints_[2]);
    return b < least ? b : least;
  }
  for (int i = 1; i < links_; ++i) {
    const double b = point_segment_squared_distance(c, joints_[i], joints_[i + 1]);
    least = b < least ? b : least;
  }
  return least;
}

// The same formulas as point_clearance / segment_clearance / polygon_clearance for a disk
// (sqrt of the least squared distance, minus r), so both paths give identical bits.
double CollisionWorld::disk_clearance(const DiskData& d) const {
  const Vec2 c(d.x, d.y);
  switch (kind_) {
    case RobotKind::RigidPolygon:
      return polygon_disk_distance(polygon_, c, d.r);
    case RobotKind::Point:
    case RobotKind::Arm:
      break;
  }
  return std::sqrt(skeleton_squared_distance(c)) - d.r;
}

double CollisionWorld::clearance_to(const Obstacle& o) const {
  switch (kind_) {
    case RobotKind::Point:
      return point_clearance(o, point_);
    case RobotKind::Arm: {
      double least = segment_clearance(o, joints_[0], joints_[1]);
      for (int i = 1; i < links_; ++i) least = std::fmin(least, segment_clearance(o, joints_[i], joints_[i + 1]));
      return least;
    }
    case RobotKind::RigidPolygon:
      return polygon_clearance(o, polygon_);
  }
  return 0.0;
}

CollisionWorld::Nearest CollisionWorld::nearest(const Config& q) const {
  ++tested_;
  return nearest_of(q);
}

CollisionWorld::Nearest CollisionWorld::nearest_of(const Config& q) const {
  pose(q);
  Nearest best{std::numeric_limits<double>::infinity(), -1};
  auto consider = [&best](double d, int index) {
    // Ties go to the lower scene index, whatever order the loops visit obstacles in.
    if (d < best.clearance || (d == best.clearance && index < best.obstacle)) best = {d, index};
  };
  switch (kind_) {
    case RobotKind::Point: {
      // The point robot (every roadmap vertex's clearance): disk_clearance() written out, the
      // same arithmetic without a call per disk.
      const double x = point_.x(), y = point_.y();
      for (const DiskData& d : disks_) {
        const double dx = x - d.x, dy = y - d.y;
        const double d2 = dx * dx + dy * dy;
        if (cannot_beat(d2, d.r, best.clearance)) continue;
        consider(std::sqrt(d2) - d.r, d.index);
      }
      break;
    }
    case RobotKind::Arm:  // pruned by the distance from its links to the disk's centre
      for (const DiskData& d : disks_) {
        if (cannot_beat(skeleton_squared_distance(Vec2(d.x, d.y)), d.r, best.clearance)) continue;
        consider(disk_clearance(d), d.index);
      }
      break;
    case RobotKind::RigidPolygon:  // pruned by the gap between its box and the disk's
      for (const DiskData& d : disks_) {
        if (cannot_beat(box_gap2(robot_box_, d.box), 0.0, best.clearance)) continue;
        consider(disk_clearance(d), d.index);
      }
      break;
  }
  for (const ShapeData& s : shapes_) {
    // Walls reach kWallTolerance beyond their box.
    if (cannot_beat(box_gap2(robot_box_, s.box), kWallTolerance, best.clearance)) continue;
    consider(clearance_to(obstacles_[static_cast<std::size_t>(s.index)]), s.index);
  }
  return best;
}

double CollisionWorld::clearance(const Config& q) const {
  ++tested_;
  switch (kind_) {
    case RobotKind::Arm:
    case RobotKind::RigidPolygon:
      return nearest_of(q).clearance;
    case RobotKind::Point:
      break;
  }
  // The point robot (every roadmap vertex's eta). The least of sqrt(d2) - r over the disks is
  // the same whichever order they are taken in, and without the obstacle's index to track no
  // disk needs a branch: each disk's eta in a loop without one (vectorised: square roots two at
  // a time), then four running minima. nearest()'s pruning only ever skips disks that cannot
  // be the least, so the value is its value, and so are the bits but for a zero: equal values
  // differ only in the sign of a zero (a polygon or a wall can give -0, a disk +0), and there
  // nearest()'s tie between obstacles, by index, decides.
  pose(q);
  const double x = point_.x(), y = point_.y();
  const auto least = [](double a, double b) { return b < a ? b : a; };  // keeps a when b is NaN
  double m[4] = {kInfinity, kInfinity, kInfinity, kInfinity};
  constexpr std::size_t kChunk = 32;
  double eta[kChunk];
  for (std::size_t from = 0; from < disk_x_.size(); from += kChunk) {
    const std::size_t count = std::min(kChunk, disk_x_.size() - from);
    const double *cx = &disk_x_[from], *cy = &disk_y_[from], *r = &disk_r_[from];
    for (std::size_t i = 0; i < count; ++i) {
      const double dx = x - cx[i], dy = y - cy[i];
      eta[i] = std::sqrt(dx * dx + dy * dy) - r[i];
    }
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4)
      for (std::size_t l = 0; l < 4; ++l) m[l] = least(m[l], eta[i + l]);
    for (; i < count; ++i) m[0] = least(m[0], eta[i]);
  }
  double best = least(least(m[0], m[1]), least(m[2], m[3]));
  for (const ShapeData& s : shapes_) {  // as nearest() takes them, from the disks' least
    if (cannot_beat(box_gap2(robot_box_, s.box), kWallTolerance, best)) continue;
    best = least(best, clearance_to(obstacles_[static_cast<std::size_t>(s.index)]));
  }
  return best == 0.0 ? nearest_of(q).clearance : best;
}

bool CollisionWorld::is_free(const Config& q) const {
  ++tested_;
  pose(q);
  // Disks, one loop per robot kind (this is the innermost loop of every planner). Each computes
  // exactly what disk_clearance() computes, so is_free(q) == (clearance(q) > 0) bit for bit.
  switch (kind_) {
    case RobotKind::Point: {
      const double x = point_.x(), y = point_.y();
      for (const DiskData& d : disks_) {
        const double dx = x - d.x, dy = y - d.y;
        const double d2 = dx * dx + dy * dy;
        if (d2 > d.far2) continue;
        if (std::sqrt(d2) - d.r <= 0.0) return false;
      }
      break;
    }
    case RobotKind::Arm:
      for (const DiskData& d : disks_) {
        const double d2 = skeleton_squared_distance(Vec2(d.x, d.y));
        if (d2 > d.far2) continue;
        if (std::sqrt(d2) - d.r <= 0.0) return false;
      }
      break;
    case RobotKind::RigidPolygon:
      for (const DiskData& d : disks_) {
        if (box_gap2(robot_box_, d.box) > 0.0) continue;
        if (disk_clearance(d) <= 0.0) return false;
      }
      break;
  }
  for (const ShapeData& s : shapes_) {
    if (box_gap2(robot_box_, s.box) > kWallTolerance * kWallTolerance * kSafe) continue;
    if (clearance_to(obstacles_[static_cast<std::size_t>(s.index)]) <= 0.0) return false;
  }
  return true;
}

}  // namespace csl
