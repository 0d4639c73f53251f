#pragma once
// A PRM local connector made of a potential field (homework section 2.4): descend from p on the
// field whose goal is q (q's attractive field plus every obstacle's repulsive field) and accept
// the descent's trajectory if it reaches q within the tolerance. The descent only takes pieces
// the exact bisection check proves free (descent.hpp); the last piece, from where the descent
// stopped to q itself, is checked the same way. So every piece of a connected path is free.
#include "core/fields/descent.hpp"
#include "core/planning/local_connector.hpp"

namespace csl {

/// The field for connecting close vertices: weaker and shorter-ranged than the defaults (eta =
/// 1e-6, rho0 = 0.05), so that the repulsion only matches the largest pull (d zeta = 0.2) at
/// rho ~ 0.015. Why: a vertex near an obstacle is a goal the descent cannot reach when the
/// obstacle pushes harder than the goal pulls there (the field's minimum moves off the goal);
/// with the defaults of PotentialParams, PRM's roadmaps lose about half their edges to this.
/// The pieces are proven free anyway, so a gentle field costs no safety.
PotentialParams connector_field_params();
/// Descent settings for connecting close roadmap vertices: short steps (0.01), a small budget
/// (200: close vertices need few steps; a long detour is better left to other vertices), a
/// tolerance of 0.02 (the last piece to q is checked exactly), no escapes.
DescentParams connector_descent_params();

class PotentialConnector final : public LocalConnector {
 public:
  /// Throws std::invalid_argument for bad parameters. descent.seed is replaced per pair by the
  /// seed PRM passes to connect().
  explicit PotentialConnector(PotentialParams field = connector_field_params(),
                              DescentParams descent = connector_descent_params());

  std::string name() const override { return "potential"; }
  LocalPath connect(const CollisionWorld& world, const Config& p, const Config& q, std::uint64_t seed) const override;
  /// Each motion step evaluates the field and proves its piece free (a few configurations):
  /// about 4 per step, max_steps steps.
  double expected_evaluations() const override { return 4.0 * descent_.max_steps; }

  const PotentialParams& field_params() const { return field_; }
  const DescentParams& descent_params() const { return descent_; }

 private:
  PotentialParams field_;
  DescentParams descent_;
};

}  // namespace csl
