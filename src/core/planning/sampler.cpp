#include "core/planning/sampler.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/base/text.hpp"

namespace csl {
namespace {

std::vector<int> first_primes(int count) {
  std::vector<int> primes;
  for (int n = 2; static_cast<int>(primes.size()) < count; ++n) {
    bool prime = true;
    for (int p : primes) {
      if (p * p > n) break;
      if (n % p == 0) {
        prime = false;
        break;
      }
    }
    if (prime) primes.push_back(n);
  }
  return primes;
}

/// The shortest of %.15g..%.17g that reads back as v (0.05, not 0.050000000000000003).
std::string shortest_decimal(double v) {
  char text[48];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  return text;
}

}  // namespace

SamplerSpec SamplerSpec::parse(const std::string& text) {
  SamplerSpec s;
  // ",uniform:W" after gaussian:S or bridge:S: the hybrid's uniform share. A comma, not a '+':
  // a link's query turns '+' into a space, and a sigma may be written 1e+2.
  std::string head = text;
  const std::size_t comma = text.find(',');
  if (comma != std::string::npos) {
    head = text.substr(0, comma);
    const std::string tail = text.substr(comma + 1);
    if (tail.rfind("uniform:", 0) != 0)
      throw std::invalid_argument("sampler '" + printable(text, 40) + "': after ',' only uniform:W (the uniform share)");
    const auto w = parse_decimal(std::string_view(tail).substr(8));
    if (!w || !std::isfinite(*w) || !(*w >= 0.0 && *w < 1.0))
      throw std::invalid_argument("sampler '" + printable(text, 40) + "': the uniform share W must be a number in [0, 1)");
    s.uniform_share = *w + 0.0;
  }
  const auto sigma_after = [&](std::size_t prefix) {
    const auto v = parse_decimal(std::string_view(head).substr(prefix));
    if (!v) throw std::invalid_argument("sampler '" + printable(text, 40) + "': not a number after ':'");
    if (!std::isfinite(*v) || !(*v > 0.0))
      throw std::invalid_argument("sampler '" + printable(text, 40) + "': sigma must be a finite number > 0");
    return *v;
  };
  if (head == "uniform") {
    s.kind = Kind::Uniform;
  } else if (head == "halton") {
    s.kind = Kind::Halton;
  } else if (head.rfind("gaussian:", 0) == 0) {
    s.kind = Kind::Gaussian;
    s.sigma = sigma_after(9);
  } else if (head.rfind("bridge:", 0) == 0) {
    s.kind = Kind::Bridge;
    s.sigma = sigma_after(7);
  } else if (head == "gaussian" || head == "bridge") {
    throw std::invalid_argument("sampler '" + printable(text, 40) + "' needs its sigma: " + head + ":S, e.g. " + head + ":0.05");
  } else {
    throw std::invalid_argument("unknown sampler '" + printable(text, 40) +
                                "' (uniform, gaussian:S, bridge:S or halton; a hybrid adds a uniform share: bridge:S,uniform:W)");
  }
  if (comma != std::string::npos && s.kind != Kind::Gaussian && s.kind != Kind::Bridge)
    throw std::invalid_argument("sampler '" + printable(text, 40) + "': only gaussian:S and bridge:S take a uniform share (S,uniform:W)");
  return s;
}

std::string SamplerSpec::name() const {
  switch (kind) {
    case Kind::Uniform: return "uniform";
    case Kind::Halton: return "halton";
    case Kind::Gaussian:
    case Kind::Bridge: break;
  }
  std::string text = std::string(kind == Kind::Gaussian ? "gaussian:" : "bridge:") + shortest_decimal(sigma);
  if (uniform_share > 0.0) text += ",uniform:" + shortest_decimal(uniform_share);
  return text;
}

void normal_deviates(Rng& rng, int count, double* out) {
  for (int i = 0; i < count; i += 2) {
    double u, v, s;
    do {
      u = 2.0 * rng.uniform01() - 1.0;
      v = 2.0 * rng.uniform01() - 1.0;
      s = u * u + v * v;
    } while (!(s > 0.0 && s < 1.0));
    const double f = std::sqrt(-2.0 * det::log(s) / s);
    out[i] = u * f;
    if (i + 1 < count) out[i + 1] = v * f;
  }
}

double radical_inverse(std::uint64_t i, int base) {
  // Digit by digit, each place value 1/base^k by exact division chains (the same bits everywhere).
  const auto b = static_cast<std::uint64_t>(base);
  double r = 0.0, place = 1.0 / base;
  while (i > 0) {
    r += static_cast<double>(i % b) * place;
    i /= b;
    place /= base;
  }
  return r;
}

Config halton_point(const Space& space, std::uint64_t i) {
  static const std::vector<int> kSmall = first_primes(64);
  const std::vector<int> bases = space.dim() <= 64 ? kSmall : first_primes(space.dim());
  Config q(space.dim());
  for (int c = 0; c < space.dim(); ++c) {
    const Coordinate& co = space.coordinate(c);
    const double u = radical_inverse(i, bases[static_cast<std::size_t>(c)]);
    q[c] = co.angular ? wrap_angle(-kPi + kTwoPi * u) : co.lo + (co.hi - co.lo) * u;
  }
  return q;
}

Sampler::Sampler(const CollisionWorld& world, SamplerSpec spec) : world_(&world), spec_(spec) {}

Config Sampler::gaussian_partner(Rng& rng, const Config& q1) const {
  const Space& space = world_->space();
  const int d = space.dim();
  double z[64];
  std::vector<double> big;
  double* dev = z;
  if (d > 64) {
    big.resize(static_cast<std::size_t>(d));
    dev = big.data();
  }
  normal_deviates(rng, d, dev);
  Config q2(d);
  for (int i = 0; i < d; ++i) {
    const Coordinate& c = space.coordinate(i);
    const double x = q1[i] + spec_.sigma * dev[i] / c.weight;
    q2[i] = c.angular ? wrap_angle(x) : std::min(c.hi, std::max(c.lo, x));
  }
  return q2;
}

SamplerDraw Sampler::draw(Rng& rng, int index) const {
  const Space& space = world_->space();
  SamplerDraw out;
  switch (spec_.kind) {
    case SamplerSpec::Kind::Uniform:
    case SamplerSpec::Kind::Halton: {
      out.q = spec_.kind == SamplerSpec::Kind::Uniform ? space.sample(rng)
                                                      : halton_point(space, static_cast<std::uint64_t>(index));
      out.tested = 1;
      out.kept = out.q_free = world_->is_free(out.q);
      return out;
    }
    case SamplerSpec::Kind::Gaussian:
    case SamplerSpec::Kind::Bridge:
      if (spec_.uniform_share > 0.0 && rng.uniform01() < spec_.uniform_share) {
        out.q = space.sample(rng);
        out.tested = 1;
        out.kept = out.q_free = world_->is_free(out.q);
        return out;
      }
      break;
  }
  switch (spec_.kind) {
    case SamplerSpec::Kind::Uniform:
    case SamplerSpec::Kind::Halton:
      break;  // drawn above
    case SamplerSpec::Kind::Gaussian: {
      Config q1 = space.sample(rng);
      Config q2 = gaussian_partner(rng, q1);
      out.tested = 2;
      const bool f1 = world_->is_free(q1), f2 = world_->is_free(q2);
      if (f1 != f2) {
        out.kept = out.q_free = true;
        out.q = f1 ? std::move(q1) : std::move(q2);
      } else {
        out.q = std::move(q1);  // both free or both in collision: q1 tells which
        out.q_free = f1;
      }
      return out;
    }
    case SamplerSpec::Kind::Bridge: {
      Config q1 = space.sample(rng);
      out.tested = 1;
      if (world_->is_free(q1)) {
        out.q = std::move(q1);
        out.q_free = true;
        return out;
      }
      Config q2 = gaussian_partner(rng, q1);
      out.tested = 2;
      if (world_->is_free(q2)) {
        out.q = std::move(q2);
        out.q_free = true;
        return out;
      }
      out.q = space.interpolate(q1, q2, 0.5);
      out.tested = 3;
      out.kept = out.q_free = world_->is_free(out.q);
      return out;
    }
  }
  return out;
}

}  // namespace csl
