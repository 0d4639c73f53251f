#pragma once
// How PRM joins two close vertices (homework section 2.4, "local connection strategies"). The
// homework's PRM uses the straight line; a LocalConnector may take any path it can prove free,
// e.g. a descent on a potential field (potential_connector.hpp). PrmParams::connector holds one;
// null means the straight line, checked by PrmParams::checker exactly as before.
#include <cstdint>
#include <string>
#include <vector>

#include "core/checking/collision.hpp"

namespace csl {

/// A connector's answer for one pair.
struct LocalPath {
  bool connected = false;
  /// The configurations strictly between p and q, in order from p to q. Every straight piece
  /// p -> w_1 -> ... -> w_m -> q must be free (the connector proves it; PRM re-checks the
  /// pieces of the path it returns with the exact bisection check).
  std::vector<Config> waypoints;
  double length = 0.0;   ///< length of that polyline in the space's metric (if connected)
  long evaluations = 0;  ///< configurations the connector evaluated (for statistics)
};

/// The interface. connect() must be a function of its arguments only (no hidden state), so that
/// PRM's replay to step k reproduces the roadmap exactly.
class LocalConnector {
 public:
  virtual ~LocalConnector() = default;
  /// A short name for output, e.g. "potential".
  virtual std::string name() const = 0;
  /// Tries to join p to q, both free configurations of `world`. `seed` is for randomized
  /// connectors: PRM derives it from its own seed and the pair of vertices.
  virtual LocalPath connect(const CollisionWorld& world, const Config& p, const Config& q,
                            std::uint64_t seed) const = 0;
  /// Configurations (or the like: field evaluations) one connect() is expected to evaluate at
  /// most, for the work budget (work.hpp).
  virtual double expected_evaluations() const = 0;
};

/// The length of p -> waypoints -> q in the space's metric (a sum in path order).
double polyline_length(const Space& space, const Config& p, const std::vector<Config>& waypoints, const Config& q);

}  // namespace csl
