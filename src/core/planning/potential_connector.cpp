#include "core/planning/potential_connector.hpp"

#include <stdexcept>

namespace csl {

PotentialParams connector_field_params() {
  PotentialParams p;
  p.eta = 1e-6;
  p.rho0 = 0.05;
  return p;
}

DescentParams connector_descent_params() {
  DescentParams d;
  d.step = 0.01;
  d.tolerance = 0.02;
  d.max_steps = 200;
  d.escapes = 0;
  return d;
}

PotentialConnector::PotentialConnector(PotentialParams field, DescentParams descent)
    : field_(field), descent_(descent) {
  if (const std::string p = field.problem(); !p.empty()) throw std::invalid_argument(p);
  if (const std::string p = descent.problem(); !p.empty()) throw std::invalid_argument(p);
}

LocalPath PotentialConnector::connect(const CollisionWorld& world, const Config& p, const Config& q,
                                      std::uint64_t seed) const {
  LocalPath out;
  const PotentialField field(world, q, field_);
  DescentParams params = descent_;
  params.seed = seed;
  Descent descent(field, p, params);
  descent.run();
  out.evaluations = descent.evaluations();
  if (descent.outcome() != DescentOutcome::Goal && descent.outcome() != DescentOutcome::Escaped) return out;
  const std::vector<Config>& t = descent.trajectory();
  // The last piece, from where the descent stopped to q itself (unless it stopped exactly there).
  const Config& last = t.back();
  const bool at_q = world.space().distance(last, q) == 0.0;
  if (!at_q) {
    const EdgeCheckResult r = check_edge(world, EdgeCheckerSpec::parse("bisection"), last, q);
    out.evaluations += r.evaluations;
    if (r.collision) return out;
  }
  out.connected = true;
  if (t.size() > 1) out.waypoints.assign(t.begin() + 1, at_q ? t.end() - 1 : t.end());
  out.length = polyline_length(world.space(), p, out.waypoints, q);
  return out;
}

}  // namespace csl
