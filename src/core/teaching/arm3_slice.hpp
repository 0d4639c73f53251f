#pragma once
// The exact C-obstacle of the planar 3-link arm (T^3) in slices of fixed theta1.
//
// The arm's angles are relative (arm_robot.hpp): link 2's absolute angle is theta1 + theta2,
// link 3's theta1 + theta2 + theta3. At a fixed theta1, link 1 is fixed: if it touches an
// obstacle, the whole (theta2, theta3) square is blocked. Otherwise links 2 and 3 are a 2-link
// arm based at link 1's end e1 = base + l1 (cos theta1, sin theta1) whose first angle is the
// absolute phi = theta1 + theta2 and whose second is theta3 (relative to link 2, as before): its
// exact map is ArmCSpaceMap's (closed-form angle intervals), read at phi = theta1 + theta2.
#include <cstdint>
#include <vector>

#include "core/teaching/cspace_map.hpp"

namespace csl {

class Arm3Slices {
 public:
  /// The arm must have 3 links (std::invalid_argument otherwise).
  Arm3Slices(const ArmRobot& arm, const std::vector<Obstacle>& obstacles);

  const ArmRobot& arm() const { return arm_; }
  /// Whether link 1 touches an obstacle at theta1 (then the whole slice is blocked).
  bool link1_blocked_at(double theta1) const { return link1_.link1_blocked_at(theta1); }

  /// One slice: the (theta2, theta3) square at a fixed theta1.
  class Slice {
   public:
    double theta1() const { return theta1_; }
    /// Whether link 1 collides here (every (theta2, theta3) blocked).
    bool all_blocked() const { return all_blocked_; }
    /// The blocked theta3 at theta2, as sorted disjoint closed intervals in [-pi, pi].
    void blocked_theta3(double theta2, std::vector<AngleInterval>& out) const;
    /// Whether (theta2, theta3) is blocked.
    bool blocked(double theta2, double theta3) const;

   private:
    friend class Arm3Slices;
    Slice(double theta1, bool all_blocked, ArmCSpaceMap links23)
        : theta1_(theta1), all_blocked_(all_blocked), links23_(std::move(links23)) {}
    double theta1_;
    bool all_blocked_;
    ArmCSpaceMap links23_;  // links 2 and 3 from link 1's end, first angle absolute
  };
  Slice slice(double theta1) const;

  /// Whether the configuration (theta1, theta2, theta3) is blocked.
  bool blocked(double theta1, double theta2, double theta3) const { return slice(theta1).blocked(theta2, theta3); }

 private:
  ArmRobot arm_;
  std::vector<Obstacle> obstacles_;
  ArmCSpaceMap link1_;  // the arm of links 1 and 2: its link-1 arcs are this arm's
};

}  // namespace csl
