#pragma once
// Gradient descent on a potential field with randomized escapes from local minima (SHV section
// 5.2.4 and 5.3), as a stepper: step() does one unit of work and returns what it did.
//
// Descent step. With tau = tau(q_k) = -grad U(q_k), the step goes along the steepest-descent
// direction of the configuration space's metric, D = W^-1 tau with W = diag(w_i^2) the metric's
// weights, normalised to length s in that metric:  q_{k+1} = q_k + s D / |D|_W,
//   s = min(alpha, d(q_k, q_goal))  (so that the descent does not overshoot the goal).
// For R^2 and the arm's torus (unit weights) this is SHV's q_{k+1} = q_k + alpha tau / |tau|;
// for SE(2) the angle's weight (the polygon's radius R) turns the torque into a turn of
// torque / R^2, so that a step moves the robot's farthest point about alpha, whatever R is.
// Angles are wrapped after each step.
//
// Never into collision. A step (descent or random walk) is taken only if the straight piece
// q_k -> q_{k+1} stays in the space's bounds and is proven free by the exact bisection check
// (edge_check.hpp). A blocked descent step is halved, at most max_halvings times; still blocked,
// the descent is stuck there, which counts as a local minimum. So the trajectory is a polyline
// of certified-free pieces, and every configuration on it is free.
//
// Stopping rules, checked before each step in this order:
//   1. d(q, q_goal) <= tolerance: ReachedGoal (outcome Goal, or Escaped after a random walk);
//   2. max_steps motion steps (descent and random walk together) taken: GaveUp (MaxSteps);
//   3. a local minimum: |tau| <= min_force (a critical point), or the last `window` descent
//      steps (since the start or the last random walk) moved q less than min_progress * alpha
//      in all (the descent oscillates in a basin: SHV's |q_k - q_{k+window}| < epsilon), or a
//      blocked step (above). With escapes left: LocalMinimum, then a random walk; without:
//      GaveUp (outcome LocalMinimum).
// Random walk (SHV section 5.3): walk_steps steps, each adding to every coordinate i a number
// uniform in [-v / w_i, v / w_i] (csl::Rng seeded with `seed`, coordinates in order); a draw that
// would leave the space or collide is drawn again (at most kMaxWalkDraws times, then the step
// stays in place). Then the descent starts again from where the walk ended.
#include <cstdint>
#include <vector>

#include "core/base/params.hpp"
#include "core/base/rng.hpp"
#include "core/checking/edge_check.hpp"
#include "core/fields/potential.hpp"

namespace csl {

inline constexpr int kMaxWalkDraws = 20;

struct DescentParams {
  double step = kDescentStep.def;  ///< alpha: length of a descent step in the C-space metric
  double tolerance = 0.01;    ///< the goal is reached within this distance
  int max_steps = 2000;       ///< budget of motion steps (descent + random walk)
  double min_force = 1e-9;    ///< |tau| at most this: a critical point
  int window = 20;            ///< descent steps over which progress is measured
  double min_progress = 2.0;  ///< less than min_progress * step over the window: stuck
  int max_halvings = 6;       ///< a blocked step is halved at most this many times
  int escapes = static_cast<int>(kDescentEscapes.def);  ///< random walks allowed (0: plain descent)
  // A walk of 40 steps of up to 0.1 per coordinate wanders about 0.1 sqrt(40/3) ~ 0.37 (RMS per
  // coordinate): in a unit workspace, enough to leave a basin a few tenths across (the cup of
  // the tests), mostly within a few escapes.
  int walk_steps = 40;        ///< steps of one random walk
  double walk_step = 0.1;     ///< v: each coordinate moves uniformly in [-v/w, v/w] per walk step
  std::uint64_t seed = 1;
  /// What is wrong, or "" if usable.
  std::string problem() const;
};

enum class DescentOutcome { Running, Goal, Escaped, LocalMinimum, MaxSteps };
/// "running", "goal", "escaped", "local_minimum", "max_steps".
const char* outcome_name(DescentOutcome o);

/// What one step did. q, U and force describe the configuration after the step.
struct DescentEvent {
  enum class Kind {
    Descend,       ///< a descent step to q (halvings: how often it was halved)
    RandomWalk,    ///< a random-walk step to q (stayed put if every draw was blocked)
    ReachedGoal,   ///< d(q, goal) <= tolerance: done
    LocalMinimum,  ///< stuck at q, with escapes left: a random walk follows
    GaveUp,        ///< done without the goal: outcome LocalMinimum or MaxSteps
  };
  Kind kind = Kind::Descend;
  long step = 0;       ///< 1-based number of this step
  Config q;
  double U = 0.0;      ///< U(q)
  double force = 0.0;  ///< |tau(q)| (Euclidean norm of the coordinates)
  int halvings = 0;    ///< Descend: times the step was halved to stay free
  bool blocked = false;  ///< LocalMinimum/GaveUp: because even the shortest step collided
};
/// "descend", "random_walk", "reached_goal", "local_minimum", "gave_up".
const char* descent_event_name(DescentEvent::Kind k);

class Descent {
 public:
  /// The field (and its world) must outlive the descent. Throws std::invalid_argument for bad
  /// parameters, a start of the wrong dimension, or a start that is not free.
  Descent(const PotentialField& field, const Config& start, DescentParams params = {});
  Descent(PotentialField&&, const Config&, DescentParams = {}) = delete;

  bool done() const { return outcome_ != DescentOutcome::Running; }
  /// One step (see the file comment); the event stays valid until the next step.
  const DescentEvent& step();
  /// Steps to the end.
  void run();
  /// Back to the state before step 1 (the random walks replay identically).
  void reset();

  DescentOutcome outcome() const { return outcome_; }
  /// q_0 (the start), then every configuration moved to, in order.
  const std::vector<Config>& trajectory() const { return trajectory_; }
  const Config& q() const { return trajectory_.back(); }
  double potential() const { return U_; }
  const Config& tau() const { return tau_; }
  double force() const;
  double distance_to_goal() const;
  long steps() const { return steps_; }
  int descent_steps() const { return descent_steps_; }
  int walk_steps() const { return walk_steps_taken_; }
  int escapes_used() const { return escapes_used_; }
  int local_minima() const { return local_minima_; }
  /// Configurations whose clearance or freeness was evaluated (edge checks included).
  long evaluations() const { return evaluations_; }
  const DescentParams& params() const { return params_; }
  const PotentialField& field() const { return *field_; }
  const DescentEvent& last_event() const { return event_; }

 private:
  void descend();
  void walk();
  bool stuck() const;
  // A local minimum at q(): LocalMinimum and a random walk next, or GaveUp without escapes.
  void local_minimum();
  // Whether the piece from q() to `next` is inside the space and proven free; sets eta_next.
  bool piece_free(const Config& next, double& eta_next);
  void move_to(const Config& next, double eta_next);
  void finish(DescentEvent::Kind kind, DescentOutcome outcome);

  const PotentialField* field_;
  Config start_;
  DescentParams params_;
  Rng rng_;
  EdgeChecker checker_;
  DescentEvent event_;
  DescentOutcome outcome_ = DescentOutcome::Running;
  std::vector<Config> trajectory_;
  double eta_ = 0.0;  // clearance of q()
  double U_ = 0.0;
  Config tau_;
  long steps_ = 0, evaluations_ = 0;
  int descent_steps_ = 0, walk_steps_taken_ = 0, escapes_used_ = 0, local_minima_ = 0;
  int walk_left_ = 0;               // random-walk steps still to take
  std::size_t descent_from_ = 0;    // trajectory index where the current descent began
  bool blocked_ = false;            // the last descent attempt could not move
};

}  // namespace csl
