#include "core/fields/descent.hpp"

#include <cmath>
#include <stdexcept>

namespace csl {

std::string DescentParams::problem() const {
  if (!(std::isfinite(step) && step > 0.0)) return "the step must be > 0";
  if (!(std::isfinite(tolerance) && tolerance >= 0.0)) return "the tolerance must be >= 0";
  if (max_steps < 0) return "max_steps must be >= 0";
  if (!(std::isfinite(min_force) && min_force >= 0.0)) return "min_force must be >= 0";
  if (window < 1) return "the window must be at least 1 step";
  if (!(std::isfinite(min_progress) && min_progress >= 0.0)) return "min_progress must be >= 0";
  if (max_halvings < 0 || max_halvings > 60) return "max_halvings must be in [0, 60]";
  if (escapes < 0) return "escapes must be >= 0";
  if (walk_steps < 1) return "a random walk needs at least 1 step";
  if (!(std::isfinite(walk_step) && walk_step > 0.0)) return "the random-walk step must be > 0";
  return "";
}

const char* outcome_name(DescentOutcome o) {
  static const char* const kNames[] = {"running", "goal", "escaped", "local_minimum", "max_steps"};
  return kNames[static_cast<int>(o)];
}

const char* descent_event_name(DescentEvent::Kind k) {
  static const char* const kNames[] = {"descend", "random_walk", "reached_goal", "local_minimum", "gave_up"};
  return kNames[static_cast<int>(k)];
}

Descent::Descent(const PotentialField& field, const Config& start, DescentParams params)
    : field_(&field),
      start_(start),
      params_(params),
      checker_(field.world(), EdgeCheckerSpec::parse("bisection")) {
  if (const std::string p = params.problem(); !p.empty()) throw std::invalid_argument(p);
  const Space& space = field.world().space();
  if (start.size() != space.dim())
    throw std::invalid_argument("the start must have " + std::to_string(space.dim()) + " coordinates");
  start_ = space.wrap(start);
  if (!space.contains(start_)) throw std::invalid_argument("the start lies outside the configuration space");
  if (!(field.world().clearance(start_) > 0.0)) throw std::invalid_argument("the start is not free");
  reset();
}

void Descent::reset() {
  rng_.reseed(params_.seed);
  event_ = DescentEvent{};
  outcome_ = DescentOutcome::Running;
  trajectory_.assign(1, start_);
  eta_ = field_->world().clearance(start_);
  const PotentialField::Gradient g = field_->gradient(start_);
  U_ = g.U;
  tau_ = g.tau;
  steps_ = 0;
  evaluations_ = 1;
  descent_steps_ = walk_steps_taken_ = escapes_used_ = local_minima_ = 0;
  walk_left_ = 0;
  descent_from_ = 0;
  blocked_ = false;
}

double Descent::force() const {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < tau_.size(); ++i) sum += tau_[i] * tau_[i];
  return std::sqrt(sum);
}

double Descent::distance_to_goal() const { return field_->world().space().distance(q(), field_->goal()); }

void Descent::run() {
  while (!done()) step();
}

const DescentEvent& Descent::step() {
  if (done()) throw std::logic_error("Descent::step() after done()");
  event_ = DescentEvent{};
  event_.step = ++steps_;
  const bool budget_spent = descent_steps_ + walk_steps_taken_ >= params_.max_steps;
  if (walk_left_ > 0) {
    if (budget_spent)
      finish(DescentEvent::Kind::GaveUp, DescentOutcome::MaxSteps);
    else
      walk();
  } else if (distance_to_goal() <= params_.tolerance) {
    finish(DescentEvent::Kind::ReachedGoal, escapes_used_ > 0 ? DescentOutcome::Escaped : DescentOutcome::Goal);
  } else if (budget_spent) {
    finish(DescentEvent::Kind::GaveUp, DescentOutcome::MaxSteps);
  } else if (blocked_ || stuck()) {
    local_minimum();
  } else {
    descend();
  }
  event_.q = q();
  event_.U = U_;
  event_.force = force();
  return event_;
}

bool Descent::stuck() const {
  if (force() <= params_.min_force) return true;
  const std::size_t last = trajectory_.size() - 1;
  const auto window = static_cast<std::size_t>(params_.window);
  if (last - descent_from_ < window) return false;
  return field_->world().space().distance(trajectory_[last], trajectory_[last - window]) <
         params_.min_progress * params_.step;
}

void Descent::local_minimum() {
  ++local_minima_;
  event_.blocked = blocked_;
  blocked_ = false;
  if (escapes_used_ >= params_.escapes) {
    finish(DescentEvent::Kind::GaveUp, DescentOutcome::LocalMinimum);
    return;
  }
  event_.kind = DescentEvent::Kind::LocalMinimum;
  ++escapes_used_;
  walk_left_ = params_.walk_steps;
}

void Descent::descend() {
  const Space& space = field_->world().space();
  const Eigen::Index n = tau_.size();
  // D = W^-1 tau and |D|_W = sqrt(sum tau_i^2 / w_i^2): the metric's steepest descent.
  Config direction(n);
  double norm2 = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = space.coordinate(static_cast<int>(i)).weight;
    direction[i] = tau_[i] / (w * w);
    norm2 += tau_[i] * tau_[i] / (w * w);
  }
  const double norm = std::sqrt(norm2);
  if (norm > 0.0 && std::isfinite(norm)) {
    double s = std::fmin(params_.step, distance_to_goal());
    for (int h = 0; h <= params_.max_halvings; ++h, s *= 0.5) {
      const double scale = s / norm;
      Config next(n);
      for (Eigen::Index i = 0; i < n; ++i) next[i] = q()[i] + scale * direction[i];
      next = space.wrap(next);
      double eta_next = 0.0;
      if (!piece_free(next, eta_next)) continue;
      move_to(next, eta_next);
      ++descent_steps_;
      event_.kind = DescentEvent::Kind::Descend;
      event_.halvings = h;
      return;
    }
  }
  blocked_ = true;  // even the shortest step collides (or there is no direction): stuck here
  local_minimum();
}

void Descent::walk() {
  const Space& space = field_->world().space();
  const Eigen::Index n = tau_.size();
  for (int draw = 0; draw < kMaxWalkDraws; ++draw) {
    Config next(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double v = params_.walk_step / space.coordinate(static_cast<int>(i)).weight;
      next[i] = q()[i] + rng_.uniform(-v, v);
    }
    next = space.wrap(next);
    double eta_next = 0.0;
    if (piece_free(next, eta_next)) {
      move_to(next, eta_next);
      break;
    }
  }
  ++walk_steps_taken_;
  event_.kind = DescentEvent::Kind::RandomWalk;
  if (--walk_left_ == 0) descent_from_ = trajectory_.size() - 1;  // progress counts from here
}

bool Descent::piece_free(const Config& next, double& eta_next) {
  const CollisionWorld& world = field_->world();
  if (!world.space().contains(next)) return false;
  eta_next = world.clearance(next);
  ++evaluations_;
  if (!(eta_next > 0.0)) return false;
  checker_.reset(q(), next, /*endpoints_known_free=*/true, eta_, eta_next);
  while (!checker_.done()) checker_.step();
  evaluations_ += checker_.evaluations();
  return checker_.verdict() == Verdict::Free;
}

void Descent::move_to(const Config& next, double eta_next) {
  trajectory_.push_back(next);
  eta_ = eta_next;
  const PotentialField::Gradient g = field_->gradient(next);
  U_ = g.U;
  tau_ = g.tau;
}

void Descent::finish(DescentEvent::Kind kind, DescentOutcome outcome) {
  event_.kind = kind;
  outcome_ = outcome;
}

}  // namespace csl
