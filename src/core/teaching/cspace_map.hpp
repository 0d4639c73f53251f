#pragma once
// The exact C-space map of the planar 2-link arm: the C-obstacle region in T^2 = [-pi, pi)^2,
// computed analytically as angle intervals, and its rasterisation.
//
// Link 1 (base -> elbow) depends on theta1 only: the theta1 where it meets an obstacle form a
// few closed arcs, computed once. For each theta1 where link 1 is free, link 2 (elbow -> tip)
// is a segment of length l2 rotating about the elbow e, at the absolute angle
// phi = theta1 + theta2; the phi where it meets each obstacle are arcs derived in closed form
// (cspace_map.cpp documents each case), shifted by -theta1 into theta2. Where link 1 collides,
// every theta2 is forbidden. Decisions are those of CollisionWorld::is_free (obstacles closed,
// walls widened by kWallTolerance), up to the rounding of the boundary angles.
#include <cstdint>
#include <vector>

#include "core/geometry/obstacles.hpp"
#include "core/robots/robot.hpp"

namespace csl {

/// A closed interval of angles, -pi <= lo <= hi <= pi. A set of angles that wraps across
/// -pi/pi is split in two: [lo, pi] and [-pi, hi].
struct AngleInterval {
  double lo, hi;
};

/// The angle at the centre of pixel `index` of `resolution` across [-pi, pi):
/// -pi + (index + 1/2) 2pi / resolution. Rasterisation, tests and the CLI all use this one.
double cspace_pixel_angle(int index, int resolution);
/// The pixels whose centre angles (cspace_pixel_angle) lie in the closed [lo, hi]: [j0, j1),
/// empty when j1 <= j0. Decided by comparing with the centres themselves, not by rounding.
void cspace_pixel_span(double lo, double hi, int resolution, int& j0, int& j1);

class ArmCSpaceMap {
 public:
  /// Precomputes the obstacles' pieces and link 1's blocked arcs (O(obstacle size)). The arm
  /// must have 2 links (std::invalid_argument otherwise): its map is the torus square.
  ArmCSpaceMap(const ArmRobot& arm, const std::vector<Obstacle>& obstacles);

  const ArmRobot& arm() const { return arm_; }

  /// The theta1 where link 1 meets an obstacle: sorted, disjoint, merged closed intervals.
  const std::vector<AngleInterval>& link1_blocked() const { return link1_; }
  /// Whether link 1 meets an obstacle at theta1 (any angle; wrapped first).
  bool link1_blocked_at(double theta1) const;

  /// The forbidden theta2 at theta1 (sorted, disjoint, merged, written into `out`): all of
  /// [-pi, pi] where link 1 collides, else where link 2 does (closed-form arcs per obstacle).
  void blocked_theta2(double theta1, std::vector<AngleInterval>& out) const;

  /// Whether (theta1, theta2) lies in the C-obstacle (any angles; wrapped first).
  bool blocked(double theta1, double theta2) const;

  /// Rasterises to a resolution x resolution image, row-major: pixel (column i, row j) is at
  /// pixels[j * resolution + i], column i is theta1 = cspace_pixel_angle(i, resolution), row j
  /// is theta2 = cspace_pixel_angle(j, resolution), row 0 first; 255 = free, 0 = C-obstacle.
  /// One interval computation per column, then runs are filled. Returns the free fraction.
  /// resolution >= 1.
  double rasterize(int resolution, std::vector<std::uint8_t>& pixels) const;

 private:
  // A disk piece: a disk obstacle, or an end cap of a wall (radius kWallTolerance).
  struct DiskPiece {
    double x, y, r;
  };
  // A closed chain of segments: a polygon's boundary, or the rectangle of a wall's capsule.
  // `containment` says which set covering the pivot forbids every direction: the polygon, or
  // the wall's whole capsule.
  struct Chain {
    enum class Containment { InPolygon, InCapsule };
    int first, count;     // vertices_[first, first + count)
    Containment containment;
    int shape;            // index into polygons_ (Polygon) or walls_ (Capsule)
    Vec2 center;          // bounding circle: no vertex farther than radius from center
    double radius;
  };
  struct Scratch;

  // Forbidden arcs of directions of a segment of length `length` from `pivot` (link 1 from the
  // base, or link 2 from the elbow) shifted by -offset into [-pi, pi] intervals, unmerged, into
  // `out`; returns true when every direction is forbidden.
  bool pivot_arcs(const Vec2& pivot, double length, double offset, Scratch& scratch,
                  std::vector<AngleInterval>& out) const;
  void link2_intervals(double theta1, Scratch& scratch, std::vector<AngleInterval>& out) const;

  ArmRobot arm_;
  std::vector<DiskPiece> disks_;
  std::vector<Chain> chains_;
  std::vector<Vec2> vertices_;
  std::vector<Polygon> polygons_;
  std::vector<Wall> walls_;
  std::vector<AngleInterval> link1_;
};

}  // namespace csl
