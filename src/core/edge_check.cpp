#include "core/edge_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace csl {

EdgeCheckerSpec EdgeCheckerSpec::parse(const std::string& text) {
  if (text == "bisection") return {Kind::Bisection, 0};
  if (text.rfind("grid:", 0) == 0) {
    const std::string digits = text.substr(5);
    char* end = nullptr;
    const long n = digits.empty() ? 0 : std::strtol(digits.c_str(), &end, 10);
    if (!digits.empty() && end == digits.c_str() + digits.size() && n >= 2 && n <= kMaxGridResolution)
      return {Kind::Grid, static_cast<int>(n)};
    throw std::invalid_argument("checker '" + text + "': N must be an integer in [2, " +
                                std::to_string(kMaxGridResolution) + "]");
  }
  if (text.rfind("step:", 0) == 0) {
    const std::string digits = text.substr(5);
    char* end = nullptr;
    const double d = digits.empty() ? 0.0 : std::strtod(digits.c_str(), &end);
    if (!digits.empty() && end == digits.c_str() + digits.size() && std::isfinite(d) && d > 0.0)
      return {Kind::Step, 0, d};
    throw std::invalid_argument("checker '" + text + "': D must be a number > 0");
  }
  throw std::invalid_argument("unknown checker '" + text + "' (bisection, grid:N or step:D)");
}

std::string EdgeCheckerSpec::name() const {
  if (kind == Kind::Bisection) return "bisection";
  if (kind == Kind::Grid) return "grid:" + std::to_string(resolution);
  char text[40];
  std::snprintf(text, sizeof text, "step:%.17g", step);
  return text;
}

void EdgeChecker::reset(const Config& p, const Config& q, bool endpoints_known_free, double eta_p, double eta_q) {
  p_ = p;
  q_ = q;
  delta_ = world_->space().difference(p, q);
  verdict_ = Verdict::Pending;
  evaluations_ = 0;
  skipped_ = 0;
  collision_t_.reset();
  known_free_ = endpoints_known_free;
  eta_p_ = eta_p;
  eta_q_ = eta_q;
  queue_.clear();
  head_ = 0;
  const bool bisection = spec_.kind == EdgeCheckerSpec::Kind::Bisection;
  if (!bisection) n_ = grid_configurations(world_->space().norm(delta_));
  // Known-free endpoints need no evaluation: start after them.
  next_ = known_free_ ? (bisection ? 2 : 1) : 0;
  if (known_free_ && bisection) queue_.push_back({0.0, eta_p_, 1.0, eta_q_, 0});
  if (known_free_ && !bisection && n_ <= 2) verdict_ = Verdict::Free;  // nothing in between
}

int EdgeChecker::grid_configurations(double length) const {
  if (spec_.kind != EdgeCheckerSpec::Kind::Step) return spec_.resolution;
  // No longer than a step: length / step rounds to at most 1 (division is monotone), so ceil
  // gives at most 1 and the edge gets its two ends, without a division (most roadmap edges).
  if (length <= spec_.step) return 2;
  const double segments = std::ceil(length / spec_.step);
  return segments >= kMaxGridResolution ? kMaxGridResolution : std::max(2, static_cast<int>(segments) + 1);
}

void EdgeChecker::check_known_free(const Config& p, const Config& q, double length, double eta_p, double eta_q) {
  if (spec_.kind == EdgeCheckerSpec::Kind::Bisection) {
    reset(p, q, true, eta_p, eta_q);
    while (!done()) step();
    return;
  }
  check_grid_known_free(p, q, length, eta_p, eta_q);
}

void EdgeChecker::walk_grid(const Config& p, const Config& q, double lambda, double eta_p, double eta_q) {
  const Space& space = world_->space();
  n_ = next_ = grid_configurations(length_);
  const double last = static_cast<double>(n_ - 1);
  int first = 1, final = n_ - 2;
  if (lambda > 0.0) {
    const auto proven = [&](double t, double eta) { return t * lambda < eta * (1.0 - 1e-6) - slack_; };
    while (first <= final && proven(static_cast<double>(first) / last, eta_p)) ++first;
    while (final >= first && proven(1.0 - static_cast<double>(final) / last, eta_q)) --final;
  }
  skipped_ = (first - 1) + (n_ - 2 - final);  // all n_ - 2 when the balls cover the edge
  if (first > final) return;
  const Config delta = space.difference(p, q);
  for (int i = first; i <= final; ++i) {
    const double t = static_cast<double>(i) / last;  // as step_grid() computes it
    ++evaluations_;
    if (!world_->is_free(space.along(p, delta, t))) {
      verdict_ = Verdict::Collision;
      collision_t_ = t;
      return;
    }
  }
}

void EdgeChecker::evaluate(double t, bool need_clearance) {
  EdgeEvent& e = event_;
  e.kind = EdgeEvent::Kind::Evaluate;
  e.t = e.t0 = e.t1 = t;
  e.lambda = e.eta0 = e.eta1 = 0.0;
  e.depth = 0;
  e.q = t == 0.0 ? p_ : (t == 1.0 ? q_ : world_->space().along(p_, delta_, t));
  if (need_clearance) {
    e.eta = world_->clearance(e.q);
    e.free = e.eta > 0.0;
  } else {
    e.free = world_->is_free(e.q);
    e.eta = e.free ? 1.0 : 0.0;  // sign only: the grid checker needs no distances
  }
  ++evaluations_;
  if (!e.free) {
    verdict_ = Verdict::Collision;
    collision_t_ = t;
  }
}

void EdgeChecker::step_grid() {
  const int n = n_;
  const int i = next_++;
  const double t = i == n - 1 ? 1.0 : static_cast<double>(i) / static_cast<double>(n - 1);
  evaluate(t, report_clearance_);
  const int last = known_free_ ? n - 2 : n - 1;
  if (verdict_ == Verdict::Pending && i >= last) verdict_ = Verdict::Free;
}

void EdgeChecker::step_bisection() {
  if (next_ < 2) {  // the endpoints, p then q
    const double t = next_ == 0 ? 0.0 : 1.0;
    evaluate(t, true);
    (next_ == 0 ? eta_p_ : eta_q_) = event_.eta;
    if (++next_ == 2 && verdict_ == Verdict::Pending) queue_.push_back({0.0, eta_p_, 1.0, eta_q_, 0});
    return;
  }
  const Piece piece = queue_[head_++];
  const Config a = piece.t0 == 0.0 ? p_ : world_->space().along(p_, delta_, piece.t0);
  const Config b = piece.t1 == 1.0 ? q_ : world_->space().along(p_, delta_, piece.t1);
  const double lambda = world_->motion_bound(a, b);

  EdgeEvent& e = event_;
  if (lambda <= piece.eta0 + piece.eta1) {
    e.kind = EdgeEvent::Kind::Certify;
  } else if (piece.t1 - piece.t0 < kMinBisectionPiece || evaluations_ >= kMaxBisectionEvaluations) {
    e.kind = EdgeEvent::Kind::Unresolved;
    verdict_ = Verdict::Collision;
    collision_t_ = 0.5 * (piece.t0 + piece.t1);
  } else {
    const double m = 0.5 * (piece.t0 + piece.t1);
    evaluate(m, true);
    if (e.free) {
      queue_.push_back({piece.t0, piece.eta0, m, e.eta, piece.depth + 1});
      queue_.push_back({m, e.eta, piece.t1, piece.eta1, piece.depth + 1});
    }
  }
  e.t0 = piece.t0;
  e.t1 = piece.t1;
  e.lambda = lambda;
  e.eta0 = piece.eta0;
  e.eta1 = piece.eta1;
  e.depth = piece.depth;
  if (verdict_ == Verdict::Pending && head_ == queue_.size()) verdict_ = Verdict::Free;
  // Keep the queue compact when long runs have consumed much of it.
  if (head_ > 1024 && head_ * 2 > queue_.size()) {
    queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(head_));
    head_ = 0;
  }
}

const EdgeEvent& EdgeChecker::step() {
  if (done()) throw std::logic_error("EdgeChecker::step() after done()");
  if (spec_.kind == EdgeCheckerSpec::Kind::Bisection)
    step_bisection();
  else
    step_grid();
  return event_;
}

EdgeCheckResult check_edge(const CollisionWorld& world, const EdgeCheckerSpec& spec, const Config& p,
                           const Config& q, bool want_trace) {
  EdgeChecker checker(world, spec);
  checker.reset(p, q);
  EdgeCheckResult result;
  while (!checker.done()) {
    const EdgeEvent& e = checker.step();
    if (want_trace) result.trace.push_back(e);
  }
  result.collision = checker.verdict() == Verdict::Collision;
  result.evaluations = checker.evaluations();
  result.collision_t = checker.collision_t();
  return result;
}

std::optional<int> min_grid_resolution(const CollisionWorld& world, const Config& p, const Config& q, int max_n) {
  // An edge the exact check proves free has no configuration in collision, so no grid finds
  // one: answered at once rather than by checking every N up to max_n (N^2 / 2 evaluations in
  // all, minutes for max_n = 100000).
  if (!check_edge(world, {EdgeCheckerSpec::Kind::Bisection, 0}, p, q).collision) return std::nullopt;
  for (int n = 2; n <= max_n; ++n) {
    EdgeChecker checker(world, {EdgeCheckerSpec::Kind::Grid, n}, /*report_clearance=*/false);
    checker.reset(p, q);
    while (!checker.done()) checker.step();
    if (checker.verdict() == Verdict::Collision) return n;
  }
  return std::nullopt;
}

}  // namespace csl
