#pragma once
// A roadmap G = (V, E), as PRM and its variants build it: configurations, the clearance known at
// each, edges (straight lines, or a local connector's path kept aside), and its hash, by which
// every build and the tests tell one roadmap from another.
#include <cstdint>
#include <string>
#include <vector>

#include "core/base/config.hpp"

namespace csl {

/// 24 bytes: roadmaps hold tens of thousands, nearly all straight lines, so a connector's
/// waypoints live aside in Roadmap::paths.
struct RoadmapEdge {
  int a, b;  ///< vertex indices, a < b
  double length;  ///< in the space's metric (of the whole polyline, for a connector's path)
  bool alive = true;  ///< false once removed by the path re-check
  int path = -1;  ///< index in Roadmap::paths of its waypoints; -1: the straight line
};
static_assert(sizeof(RoadmapEdge) == 24, "RoadmapEdge: 24 bytes in both builds (see above)");

struct Roadmap {
  std::vector<Config> vertices;  ///< V: 0 = q_init, 1 = q_final, then accepted samples in order
  /// eta per vertex: for bisection, of every vertex; for the grid checkers, of those an edge
  /// needed it for (see EdgeChecker::check_known_free); NaN where not computed.
  std::vector<double> clearance;
  std::vector<RoadmapEdge> edges;  ///< E in the order they were added
  /// Local connectors' paths from a to b, endpoints excluded (never empty), in the order added.
  std::vector<std::vector<Config>> paths;
  /// The waypoints of edge e from e.a to e.b; empty for a straight line.
  const std::vector<Config>& waypoints(const RoadmapEdge& e) const;
};

/// FNV-1a hash of the roadmap: vertex coordinates (bits), then edges (a, b, alive, and for an
/// edge with waypoints their number and bits: straight-line roadmaps hash as they always did).
std::uint64_t roadmap_hash(const Roadmap& r);
/// The hash as the lab writes it: 16 hex digits (the JSON field "roadmap_hash").
std::string roadmap_hash_text(const Roadmap& r);

}  // namespace csl
