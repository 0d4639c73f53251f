#include "core/planning/roadmap.hpp"

#include <cstdio>
#include <cstring>

namespace csl {

const std::vector<Config>& Roadmap::waypoints(const RoadmapEdge& e) const {
  static const std::vector<Config> kStraight;
  return e.path < 0 ? kStraight : paths.at(static_cast<std::size_t>(e.path));  // at: an edge of another roadmap throws
}

std::uint64_t roadmap_hash(const Roadmap& r) {
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a, 64 bit
  const auto mix = [&h](std::uint64_t word) {
    for (int i = 0; i < 8; ++i) {
      h ^= (word >> (8 * i)) & 0xffu;
      h *= 0x100000001b3ull;
    }
  };
  const auto mix_config = [&mix](const Config& q) {
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      std::uint64_t bits;
      std::memcpy(&bits, &q[i], sizeof bits);
      mix(bits);
    }
  };
  mix(r.vertices.size());
  for (const Config& q : r.vertices) mix_config(q);
  mix(r.edges.size());
  for (const RoadmapEdge& e : r.edges) {
    mix(static_cast<std::uint64_t>(e.a));
    mix(static_cast<std::uint64_t>(e.b));
    mix(e.alive ? 1u : 0u);
    const std::vector<Config>& waypoints = r.waypoints(e);
    if (waypoints.empty()) continue;  // straight lines: the hash of before connectors existed
    mix(waypoints.size());
    for (const Config& w : waypoints) mix_config(w);
  }
  return h;
}

std::string roadmap_hash_text(const Roadmap& r) {
  char text[32];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(roadmap_hash(r)));
  return text;
}

}  // namespace csl
