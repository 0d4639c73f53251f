#include "core/planning/local_connector.hpp"

namespace csl {

double polyline_length(const Space& space, const Config& p, const std::vector<Config>& waypoints, const Config& q) {
  double length = 0.0;
  const Config* prev = &p;
  for (const Config& w : waypoints) {
    length += space.distance(*prev, w);
    prev = &w;
  }
  return length + space.distance(*prev, q);
}

}  // namespace csl
