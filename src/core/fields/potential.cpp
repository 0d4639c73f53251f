#include "core/fields/potential.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/base/detmath.hpp"

namespace csl {
namespace {

Config zeros(int n) {
  Config z(n);
  for (int i = 0; i < n; ++i) z[i] = 0.0;
  return z;
}

// a += b, coordinate by coordinate (a plain loop: the same order in every build).
void add_to(Config& a, const Config& b) {
  for (Eigen::Index i = 0; i < a.size(); ++i) a[i] += b[i];
}

}  // namespace

std::string PotentialParams::problem() const {
  if (!(std::isfinite(zeta) && zeta >= 0.0)) return "zeta must be a finite number >= 0";
  if (!(std::isfinite(switch_distance) && switch_distance > 0.0)) return "the switch distance d must be > 0";
  if (!(std::isfinite(eta) && eta >= 0.0)) return "eta must be a finite number >= 0";
  if (!(std::isfinite(rho0) && rho0 > 0.0)) return "rho0 must be > 0";
  return "";
}

FieldValue attractive_field(const Vec2& x, const Vec2& goal, double zeta, double d) {
  const Vec2 e = x - goal;
  const double e2 = squared_length(e);
  if (e2 <= d * d) return {0.5 * zeta * e2, Vec2(-zeta * e.x(), -zeta * e.y())};  // quadratic
  const double len = std::sqrt(e2);
  const double k = d * zeta / len;  // conic: a force of constant length d zeta
  return {d * zeta * len - 0.5 * zeta * d * d, Vec2(-k * e.x(), -k * e.y())};
}

FieldValue repulsive_field(const ObstacleDistance& r, double eta, double rho0) {
  if (r.rho > rho0) return {};
  if (r.rho == 0.0) {  // on or inside: U = +inf and an infinite push along grad rho
    const auto inf_along = [](double c) { return c == 0.0 ? 0.0 : (c > 0.0 ? kInf : -kInf); };
    return {kInf, Vec2(inf_along(r.grad.x()), inf_along(r.grad.y()))};
  }
  const double a = 1.0 / r.rho - 1.0 / rho0;
  const double k = eta * a / (r.rho * r.rho);  // (5.6): eta (1/rho - 1/rho0) (1/rho^2)
  return {0.5 * eta * a * a, Vec2(k * r.grad.x(), k * r.grad.y())};
}

Config generalized_force(const PointJacobian& jacobian, const Vec2& force) {
  Config tau(jacobian.cols());
  for (Eigen::Index j = 0; j < jacobian.cols(); ++j)
    tau[j] = jacobian(0, j) * force.x() + jacobian(1, j) * force.y();
  return tau;
}

PotentialField::PotentialField(const CollisionWorld& world, const Config& goal, PotentialParams params)
    : world_(&world), goal_(goal), params_(params) {
  if (const std::string p = params.problem(); !p.empty()) throw std::invalid_argument(p);
  if (goal.size() != world.space().dim())
    throw std::invalid_argument("the goal must have " + std::to_string(world.space().dim()) + " coordinates");
  for (const ControlPoint& c : control_points(world.robot(), goal)) goal_positions_.push_back(c.position);
  for (const Obstacle& o : world.obstacles()) boxes_.push_back(obstacle_bounds(o));
}

PotentialField::Gradient PotentialField::gradient(const Config& q) const {
  control_points(world_->robot(), q, scratch_);
  const auto& obstacles = world_->obstacles();
  Gradient g{0.0, zeros(static_cast<int>(q.size()))};
  for (std::size_t i = 0; i < scratch_.size(); ++i) {
    const ControlPoint& c = scratch_[i];
    const FieldValue att = attractive_field(c.position, goal_positions_[i], params_.zeta, params_.switch_distance);
    FieldValue rep;  // summed over obstacles first, then added to att: as evaluate() does
    for (std::size_t j = 0; j < obstacles.size(); ++j) {
      if (boxes_[j].distance(c.position) > params_.rho0) continue;  // beyond its influence
      const FieldValue one = repulsive_field(obstacle_distance(obstacles[j], c.position), params_.eta, params_.rho0);
      rep.U += one.U;
      rep.F += one.F;
    }
    g.U += att.U + rep.U;
    add_to(g.tau, generalized_force(c.jacobian, att.F + rep.F));
  }
  return g;
}

PotentialReport PotentialField::evaluate(const Config& q) const {
  const std::vector<ControlPoint> points = control_points(world_->robot(), q);
  const auto& obstacles = world_->obstacles();
  const int n = static_cast<int>(q.size());
  PotentialReport r;
  r.tau_att = r.tau_rep = r.tau = zeros(n);
  for (std::size_t i = 0; i < points.size(); ++i) {
    ControlPointReport p;
    p.position = points[i].position;
    p.goal = goal_positions_[i];
    p.jacobian = points[i].jacobian;
    p.nearest.rho = kInf;
    p.attractive = attractive_field(p.position, p.goal, params_.zeta, params_.switch_distance);
    for (std::size_t j = 0; j < obstacles.size(); ++j) {
      const ObstacleDistance d = obstacle_distance(obstacles[j], p.position);
      if (d.rho < p.nearest.rho) {  // strictly: ties keep the lower index
        p.nearest = d;
        p.nearest_obstacle = static_cast<int>(j);
      }
      // The same test as gradient() (a box farther than rho0 holds no point within rho0), so
      // that the sums agree bit for bit.
      if (boxes_[j].distance(p.position) > params_.rho0 || d.rho > params_.rho0) continue;
      RepulsiveTerm t{static_cast<int>(j), d, repulsive_field(d, params_.eta, params_.rho0)};
      p.repulsive.U += t.field.U;
      p.repulsive.F += t.field.F;
      r.contact = r.contact || d.inside;
      p.terms.push_back(t);
    }
    const Config tau_att = generalized_force(p.jacobian, p.attractive.F);
    const Config tau_rep = generalized_force(p.jacobian, p.repulsive.F);
    p.tau = generalized_force(p.jacobian, p.attractive.F + p.repulsive.F);
    r.U_att += p.attractive.U;
    r.U_rep += p.repulsive.U;
    r.U += p.attractive.U + p.repulsive.U;
    r.F_att += p.attractive.F;
    r.F_rep += p.repulsive.F;
    r.F += p.attractive.F + p.repulsive.F;
    add_to(r.tau_att, tau_att);
    add_to(r.tau_rep, tau_rep);
    add_to(r.tau, p.tau);
    r.points.push_back(std::move(p));
  }
  return r;
}

}  // namespace csl
