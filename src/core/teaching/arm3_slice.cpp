#include "core/teaching/arm3_slice.hpp"

#include <stdexcept>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"

namespace csl {
namespace {

ArmRobot first_two(const ArmRobot& arm) {
  if (arm.links() != 3) throw std::invalid_argument("the exact slices are of the 3-link arm (T^3)");
  return ArmRobot(arm.base, arm.length(0), arm.length(1));
}

}  // namespace

Arm3Slices::Arm3Slices(const ArmRobot& arm, const std::vector<Obstacle>& obstacles)
    : arm_(arm), obstacles_(obstacles), link1_(first_two(arm), obstacles) {}

Arm3Slices::Slice Arm3Slices::slice(double theta1) const {
  const double t1 = wrap_angle(theta1);
  double s, c;
  det::sincos(t1, s, c);
  // Link 1's end exactly as arm_joints computes it.
  const Vec2 end1(arm_.base.x() + arm_.length(0) * c, arm_.base.y() + arm_.length(0) * s);
  return Slice(t1, link1_.link1_blocked_at(t1), ArmCSpaceMap(ArmRobot(end1, arm_.length(1), arm_.length(2)), obstacles_));
}

void Arm3Slices::Slice::blocked_theta3(double theta2, std::vector<AngleInterval>& out) const {
  if (all_blocked_) {
    out.assign(1, {-kPi, kPi});
    return;
  }
  links23_.blocked_theta2(theta1_ + theta2, out);
}

bool Arm3Slices::Slice::blocked(double theta2, double theta3) const {
  if (all_blocked_) return true;
  return links23_.blocked(theta1_ + theta2, theta3);
}

}  // namespace csl
