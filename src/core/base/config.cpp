#include "core/base/config.hpp"

#include <cstdio>

namespace csl {

std::string format_config(const Config& q) {
  std::string out = "(";
  char buf[32];
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%.3f", i ? ", " : "", q[i]);
    out += buf;
  }
  return out + ")";
}

}  // namespace csl
