#include "core/robots/arm_robot.hpp"

#include <cmath>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/geometry/json_fields.hpp"

namespace csl {

Space ArmRobot::space(const Vec2&, const Vec2&) const { return Space::torus(links()); }

double ArmRobot::motion_bound(const Config& p, const Config& q) const {
  // The running sum and the total from 0 (0 + x is x exactly: two links give
  // l1|d1| + l2|d1 + d2| to the bit, as before).
  double rate = 0.0, total = 0.0;
  for (int i = 0; i < links(); ++i) {
    rate += angle_difference(p[i], q[i]);
    total += length(i) * std::fabs(rate);
  }
  return total;
}

double ArmRobot::motion_lipschitz() const {
  // |a|, a_j = l_j + ... + l_N, summed from the tip (two links: a = (l1 + l2, l2)) and squared
  // from the base, as sqrt((l1 + l2)^2 + l2^2) always was.
  double a[kMaxLinks] = {};
  double tail = 0.0;
  for (int j = links() - 1; j >= 0; --j) a[j] = tail = length(j) + tail;
  double sum = 0.0;
  for (int j = 0; j < links(); ++j) sum += a[j] * a[j];
  return std::sqrt(sum);
}

void ArmRobot::control_points(const Config& q, std::vector<ControlPoint>& out) const {
  // Summed from link j outwards, from 0 (two links: the 2-link arm's expressions,
  // -l1 s1 - l2 s12 and so on, to the bit).
  const int n = links();
  Vec2 joints[kMaxLinks + 1];
  arm_joints(*this, q, joints);
  double sine[kMaxLinks], cosine[kMaxLinks];
  double angle = 0.0;
  for (int i = 0; i < n; ++i) {
    angle += q[i];
    det::sincos(angle, sine[i], cosine[i]);
  }
  out.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    ControlPoint& p = out[static_cast<std::size_t>(k)];
    p.position = joints[k + 1];
    p.jacobian.setZero(2, n);
    for (int j = 0; j <= k; ++j) {
      double x = 0.0, y = 0.0;
      for (int i = j; i <= k; ++i) {
        x += -length(i) * sine[i];
        y += length(i) * cosine[i];
      }
      p.jacobian(0, j) = x;
      p.jacobian(1, j) = y;
    }
  }
}

std::string ArmRobot::control_point_name(int i) const {
  if (i + 1 == links()) return "tip";
  return links() == 2 ? "elbow" : "joint " + std::to_string(i + 2);
}

ArmRobot ArmRobot::from_json(const nlohmann::json& r, const std::string& type) {
  using namespace json_fields;
  // "arm2": the 2-link arm of the lessons, two lengths; "arm": 1 to kMaxLinks links.
  expect_object(r, "robot", {"type", "base", "lengths"});
  ArmRobot arm;
  arm.base = point(field(r, "base", "robot"), "robot.base");
  const nlohmann::json& l = field(r, "lengths", "robot");
  const std::size_t most = type == "arm2" ? 2 : static_cast<std::size_t>(kMaxLinks);
  const std::size_t least = type == "arm2" ? 2 : 1;
  if (!l.is_array() || l.size() < least || l.size() > most)
    fail("robot.lengths", type == "arm2" ? std::string("must be an array of 2 numbers")
                                         : "must be an array of 1 to " + std::to_string(most) + " numbers");
  arm.lengths.clear();
  for (std::size_t i = 0; i < l.size(); ++i) {
    arm.lengths.push_back(number(l[i], "robot.lengths[" + std::to_string(i) + "]"));
    if (!(arm.lengths.back() > 0.0)) fail("robot.lengths", "link lengths must be > 0");
  }
  // A 2-link "arm" is the "arm2" it writes back as (type_name() names it by its links).
  return arm;
}

void ArmRobot::to_json(nlohmann::json& r) const {
  r["base"] = json_fields::point_json(base);
  r["lengths"] = lengths;
}

void arm_joints(const ArmRobot& arm, const Config& q, Vec2* out) {
  out[0] = arm.base;
  double angle = 0.0;  // 0 + theta1 is theta1 exactly: the 2-link arm's bits as they always were
  for (int i = 0; i < arm.links(); ++i) {
    angle += q[i];
    double s, c;
    det::sincos(angle, s, c);
    const double l = arm.length(i);
    out[i + 1] = Vec2(out[i].x() + l * c, out[i].y() + l * s);
  }
}

ArmPose arm_pose(const ArmRobot& arm, const Config& q) {
  Vec2 joints[ArmRobot::kMaxLinks + 1];
  arm_joints(arm, q, joints);
  return {joints[0], joints[1], joints[arm.links()]};
}

}  // namespace csl
