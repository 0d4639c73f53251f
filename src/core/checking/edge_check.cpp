#include "core/checking/edge_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "core/base/params.hpp"
#include "core/base/text.hpp"

namespace csl {

EdgeCheckerSpec EdgeCheckerSpec::parse(const std::string& text) {
  // Numbers in the one syntax of core/base/text.hpp: "grid: 5" and "step:0x1p-3" are refused here
  // as --from refuses them.
  if (text == "bisection") return {Kind::Bisection, 0};
  if (text.rfind("grid:", 0) == 0) {
    const auto n = parse_integer(std::string_view(text).substr(5));
    if (n && in_range(kCheckerGridN, static_cast<double>(*n))) return {Kind::Grid, static_cast<int>(*n)};
    throw std::invalid_argument("checker '" + printable(text, 40) + "': N must be " + range_text(kCheckerGridN));
  }
  if (text.rfind("step:", 0) == 0) {
    const auto d = parse_decimal(std::string_view(text).substr(5));
    if (d && in_range(kCheckerStepD, *d)) return {Kind::Step, 0, *d};
    throw std::invalid_argument("checker '" + printable(text, 40) + "': D must be " + range_text(kCheckerStepD));
  }
  throw std::invalid_argument("unknown checker '" + printable(text, 40) + "' (bisection, grid:N or step:D)");
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
  if (certifies(lambda, piece.eta0, piece.eta1)) {
    e.kind = EdgeEvent::Kind::Certify;
  } else if (piece.t1 - piece.t0 < kMinBisectionPiece || evaluations_ >= max_evaluations_) {
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

MinGridResult min_grid_search(const CollisionWorld& world, const Config& p, const Config& q, int max_n,
                              long long max_evaluations, const EdgeCheckResult* exact) {
  MinGridResult result;
  // An edge the exact check proves free has no configuration in collision, so no grid finds
  // one: answered at once.
  const EdgeCheckResult own = exact ? EdgeCheckResult{} : check_edge(world, {EdgeCheckerSpec::Kind::Bisection, 0}, p, q);
  if (!exact) exact = &own;
  result.evaluations = exact->evaluations;
  if (!exact->collision) return result;

  // [0, 1] cut at configurations evaluated so far, all free (one in collision ends the search).
  // A gap between two cuts is dropped once their balls prove it free, as bisection certifies a
  // piece; the rest stay open, and only the grid's configurations inside them are evaluated.
  // The grid's t and configuration are computed exactly as the grid checker computes them
  // (step_grid(), evaluate()), so each evaluation is the grid's own; and a configuration
  // proven free by a gap is free, so skipping it never changes an answer.
  const Space& space = world.space();
  const Config delta = space.difference(p, q);
  const EdgeChecker rules(world, {EdgeCheckerSpec::Kind::Bisection, 0});
  const auto at = [&](double t) { return t == 0.0 ? p : (t == 1.0 ? q : space.along(p, delta, t)); };
  struct Gap {
    double t0, eta0, t1, eta1;
  };
  const auto proven = [&](const Gap& g) {
    return rules.certifies(world.motion_bound(at(g.t0), at(g.t1)), g.eta0, g.eta1);
  };
  // The endpoints are the grid's first and last configurations for every N.
  const double eta_p = world.clearance(p), eta_q = world.clearance(q);
  result.evaluations += 2;
  if (!(eta_p > 0.0) || !(eta_q > 0.0)) {
    if (max_n >= 2) result.n = 2;
    return result;
  }
  std::vector<Gap> open, next;
  if (const Gap whole{0.0, eta_p, 1.0, eta_q}; !proven(whole)) open.push_back(whole);
  for (int n = 3; n <= max_n && !open.empty(); ++n) {
    const double last = static_cast<double>(n - 1);
    next.clear();
    for (Gap g : open) {
      // Grid indices whose t may fall inside (t0, t1): a step wider on each side, as the
      // division may round either way; each t is then compared exactly.
      const long first = std::max(1L, static_cast<long>(std::floor(g.t0 * last)) - 1);
      const long final = std::min(static_cast<long>(n) - 2, static_cast<long>(std::ceil(g.t1 * last)) + 1);
      bool gap_open = true;
      for (long i = first; i <= final && gap_open; ++i) {
        const double t = static_cast<double>(i) / last;  // as step_grid() computes it
        if (!(t > g.t0 && t < g.t1)) continue;
        if (result.evaluations >= max_evaluations) {
          result.exhausted = true;
          return result;
        }
        ++result.evaluations;
        const double eta = world.clearance(at(t));
        if (!(eta > 0.0)) {  // the grid's is_free() is exactly clearance() > 0
          result.n = n;
          return result;
        }
        const Gap left{g.t0, g.eta0, t, eta}, right{t, eta, g.t1, g.eta1};
        if (!proven(left)) next.push_back(left);
        g = right;
        gap_open = !proven(right);
      }
      if (gap_open) next.push_back(g);
    }
    std::swap(open, next);
  }
  return result;
}

MinGridResult min_interior_grid_search(const CollisionWorld& world, const Config& p, const Config& q, int max_n,
                                       long long max_evaluations, const EdgeCheckResult* exact) {
  const EdgeCheckResult own = exact ? EdgeCheckResult{} : check_edge(world, {EdgeCheckerSpec::Kind::Bisection, 0}, p, q);
  if (!exact) exact = &own;
  MinGridResult result;
  result.evaluations = exact->evaluations;
  if (!exact->collision || max_n < 1) return result;  // nothing on the edge to see
  if (world.is_free(p) && world.is_free(q)) {
    // N interior points are grid N + 2 without its (free) ends: same t, same verdict.
    const int widest = max_n > std::numeric_limits<int>::max() - 2 ? std::numeric_limits<int>::max() : max_n + 2;
    result = min_grid_search(world, p, q, widest, max_evaluations, exact);
    result.evaluations += 2;  // the two is_free() above
    if (result.n) *result.n -= 2;
    return result;
  }
  // An endpoint in collision: grid after grid, each t computed as step_grid() computes it.
  const Space& space = world.space();
  const Config delta = space.difference(p, q);
  for (int n = 1; n <= max_n; ++n) {
    const double last = static_cast<double>(n) + 1.0;
    for (int i = 1; i <= n; ++i) {
      if (result.evaluations >= max_evaluations) {
        result.exhausted = true;
        return result;
      }
      ++result.evaluations;
      if (!world.is_free(space.along(p, delta, static_cast<double>(i) / last))) {
        result.n = n;
        return result;
      }
    }
  }
  return result;
}

std::optional<int> min_grid_resolution(const CollisionWorld& world, const Config& p, const Config& q, int max_n) {
  return min_grid_search(world, p, q, max_n, std::numeric_limits<long long>::max()).n;
}

int bisection_evaluation_limit(const CollisionWorld& world) {
  const double fits = kMaxEdgeCheckWork / world.evaluation_cost();
  return fits >= kMaxBisectionEvaluations ? kMaxBisectionEvaluations : std::max(16, static_cast<int>(fits));
}

}  // namespace csl
