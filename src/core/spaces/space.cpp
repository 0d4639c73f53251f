#include "core/spaces/space.hpp"

#include <cmath>
#include <stdexcept>

#include "core/base/angles.hpp"

namespace csl {

double unit_ball_volume(int d) {
  if (d < 1) throw std::invalid_argument("unit_ball_volume: d >= 1");
  // V_d = 2 pi / d * V_{d-2}, with V_0 = 1 and V_1 = 2: exact recurrences, no Gamma function.
  double v = d % 2 == 0 ? 1.0 : 2.0;
  for (int k = d % 2 == 0 ? 2 : 3; k <= d; k += 2) v *= kTwoPi / k;
  return v;
}

Space Space::box(const std::vector<double>& lo, const std::vector<double>& hi) {
  if (lo.size() != hi.size() || lo.empty() || lo.size() > static_cast<std::size_t>(kMaxDim))
    throw std::invalid_argument("Space::box: bounds of equal size 1.." + std::to_string(kMaxDim) + " needed");
  Space s;
  for (std::size_t i = 0; i < lo.size(); ++i) {
    if (!(lo[i] < hi[i])) throw std::invalid_argument("Space::box: lo < hi needed");
    s.coords_.push_back({false, lo[i], hi[i], 1.0});
  }
  const int d = static_cast<int>(lo.size());
  s.factors_.push_back({d == 1 ? "R" : "R^" + std::to_string(d), 0, d});
  return s.classify();
}

Space Space::circle(double weight) {
  Space s;
  s.coords_.push_back({true, -kPi, kPi, weight});
  s.factors_.push_back({"S^1", 0, 1});
  return s.classify();
}

Space Space::torus(int n) {
  if (n < 1 || n > kMaxDim) throw std::invalid_argument("Space::torus: 1 <= n <= " + std::to_string(kMaxDim));
  Space s;
  for (int i = 0; i < n; ++i) s.coords_.push_back({true, -kPi, kPi, 1.0});
  s.factors_.push_back({n == 1 ? "S^1" : "T^" + std::to_string(n), 0, n});
  return s.classify();
}

Space Space::se2(double x_lo, double y_lo, double x_hi, double y_hi, double angular_weight) {
  Space s = box({x_lo, y_lo}, {x_hi, y_hi});
  s.coords_.push_back({true, -kPi, kPi, angular_weight});
  s.factors_ = {{"SE(2)", 0, 3}};
  return s.classify();
}

Space Space::product(const Space& a, const Space& b) {
  if (a.dim() + b.dim() > kMaxDim) throw std::invalid_argument("Space::product: too many coordinates");
  Space s = a;
  s.coords_.insert(s.coords_.end(), b.coords_.begin(), b.coords_.end());
  for (SpaceFactor f : b.factors_) {
    f.first += a.dim();
    s.factors_.push_back(f);
  }
  return s.classify();
}

Space& Space::classify() {
  unit_linear_ = !coords_.empty();
  for (const Coordinate& c : coords_) unit_linear_ = unit_linear_ && !c.angular && c.weight == 1.0;
  return *this;
}

std::string Space::notation() const {
  std::string out;
  for (const SpaceFactor& f : factors_) out += (out.empty() ? "" : " x ") + f.name;
  return out;
}

Config Space::difference(const Config& p, const Config& q) const {
  Config d(dim());
  for (int i = 0; i < dim(); ++i)
    d[i] = coords_[static_cast<std::size_t>(i)].delta(p[i], q[i]);
  return d;
}

double Space::distance(const Config& p, const Config& q) const { return std::sqrt(squared_distance(p, q)); }

Config Space::along(const Config& p, const Config& delta, double t) const {
  Config r(dim());
  for (int i = 0; i < dim(); ++i) {
    const double v = p[i] + t * delta[i];
    r[i] = coords_[static_cast<std::size_t>(i)].angular ? wrap_angle(v) : v;
  }
  return r;
}

Config Space::wrap(const Config& q) const {
  Config r = q;
  for (int i = 0; i < dim(); ++i)
    if (coords_[static_cast<std::size_t>(i)].angular) r[i] = wrap_angle(q[i]);
  return r;
}

bool Space::contains(const Config& q) const {
  if (q.size() != dim()) return false;
  for (int i = 0; i < dim(); ++i) {
    const Coordinate& c = coords_[static_cast<std::size_t>(i)];
    if (!std::isfinite(q[i])) return false;
    if (!c.angular && (q[i] < c.lo || q[i] > c.hi)) return false;
  }
  return true;
}

Config Space::sample(Rng& rng) const {
  Config q(dim());
  for (int i = 0; i < dim(); ++i) {
    const Coordinate& c = coords_[static_cast<std::size_t>(i)];
    q[i] = c.angular ? wrap_angle(rng.uniform(-kPi, kPi)) : rng.uniform(c.lo, c.hi);
  }
  return q;
}

double Space::volume() const {
  double v = 1.0;
  for (const Coordinate& c : coords_) v *= (c.angular ? kTwoPi : c.hi - c.lo) * c.weight;
  return v;
}

}  // namespace csl
