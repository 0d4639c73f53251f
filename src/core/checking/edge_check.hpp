#pragma once
// Checking the straight-line path from p to q, q(t) = interpolate(p, q, t), t in [0, 1], in two
// ways (homework P12), each a stepper: step() does one unit of work and returns what it did, so
// the app can animate exactly what the tests assert; check_edge() just runs it to the end.
//
// - Grid ("grid:N"): the N >= 2 configurations t_i = i / (N - 1), both endpoints included, in
//   order of i; stops at the first one in collision. Approximate: it can miss a collision
//   between two of them.
// - Step ("step:D"): the grid with N = max(2, ceil(|pq| / D) + 1) for each edge, i.e. tested
//   configurations at most D apart in the space's metric (what OMPL's DiscreteMotionValidator
//   does with its resolution), so long and short edges get the same density.
// - Bisection: exact, after Schwarzer, Saha and Latombe (2005). A piece [t0, t1] of the path is
//   free if lambda(q(t0), q(t1)) < eta(q(t0)) + eta(q(t1)), by more than a margin for rounding
//   (certifies()); otherwise its midpoint m is evaluated: in collision ends the check, free
//   splits the piece into [t0, m] and [m, t1]. The handout writes (1) with <=, which proves a
//   path free of the obstacles' interiors; the lab's obstacles are closed sets (touching is a
//   collision: a disk of radius 0 is a point to avoid), and equality allows a path through the
//   point where the two balls touch, so the lab asks for <. Order: the endpoints (t = 0, then
//   t = 1), then pieces first-in first-out, left before right, i.e. breadth first: all pieces
//   of one depth before the next, coarse before fine. A piece shorter than kMinBisectionPiece
//   that still cannot be certified (the path grazes an obstacle) is reported as a collision:
//   the checker never accepts what it has not proven. So is a piece still uncertified after
//   bisection_evaluation_limit() configurations: a path along an obstacle at clearance eta
//   needs about length / eta of them, and breadth first holds a whole depth in the queue (an
//   edge along a wall of the wall-gap scene at a clearance of 3e-17 heads for 2^40: before this
//   limit it passed 20 s and 1.4 GB and kept going).
#include <optional>
#include <string>
#include <vector>

#include "core/base/params.hpp"
#include "core/checking/collision.hpp"

namespace csl {

inline constexpr double kMinBisectionPiece = 1e-12;
/// Configurations one bisection check evaluates at most before it gives up (as a collision)...
inline constexpr int kMaxBisectionEvaluations = 1 << 20;
/// ...and fewer in scenes where one configuration costs much (work.hpp's units): one check
/// does at most about this much work, what the app does within a frame, so that no single step
/// of a planner holds a browser's frame for long (1000 polygons of 256 vertices: 65
/// configurations rather than 2^20, which took minutes).
inline constexpr double kMaxEdgeCheckWork = 1 << 24;
/// The evaluations one bisection check of this world may make: kMaxBisectionEvaluations, or
/// fewer where kMaxEdgeCheckWork runs out first (at least 16: past 2^20 units a configuration,
/// more than kMaxEdgeCheckWork).
int bisection_evaluation_limit(const CollisionWorld& world);

/// What one step of an edge checker did. t, q, eta and free describe the configuration of an
/// Evaluate step only; the piece fields describe bisection steps.
struct EdgeEvent {
  enum class Kind {
    Evaluate,    ///< a configuration q(t) was tested: t, q, eta, free
    Certify,     ///< bisection: piece [t0, t1] proven free, lambda < eta0 + eta1 (certifies())
    Unresolved,  ///< bisection: piece too short to split further (or out of budget), a collision
  };
  Kind kind = Kind::Evaluate;
  double t = 0.0;      ///< Evaluate: parameter along the edge
  Config q;            ///< Evaluate: the configuration tested
  double eta = 0.0;    ///< Evaluate: its clearance (grid without report_clearance: 1 or 0)
  bool free = true;    ///< Evaluate: eta > 0
  // Bisection pieces (for the endpoint evaluations: t0 = t1 = t, lambda = 0).
  double t0 = 0.0, t1 = 0.0;
  double lambda = 0.0;           ///< motion bound of the piece
  double eta0 = 0.0, eta1 = 0.0; ///< clearances at its ends
  int depth = 0;                 ///< 0 for [0, 1], 1 for its halves, ...
};

enum class Verdict { Pending, Free, Collision };

/// Which checker: "bisection", "grid:N" or "step:D".
struct EdgeCheckerSpec {
  enum class Kind { Grid, Step, Bisection } kind = Kind::Bisection;
  int resolution = 0;  ///< N for the grid checker
  double step = 0.0;   ///< D for the step checker
  /// Parses "bisection", "grid:N" (2 <= N <= kMaxGridResolution) or "step:D" (D > 0, at most
  /// kMaxGridResolution configurations per edge); throws std::invalid_argument.
  static EdgeCheckerSpec parse(const std::string& text);
  std::string name() const;
};
inline constexpr int kMaxGridResolution = static_cast<int>(kCheckerGridN.max);  // the spec's (core/base/params.hpp)

/// A reusable checker of either kind: reset() for each edge, then step() until done().
/// Reusing one object avoids allocating per edge (the bisection queue keeps its capacity).
class EdgeChecker {
 public:
  /// `report_clearance`: the grid checker computes eta at each configuration (for traces and
  /// the lesson); without it, only whether each is free (faster, for roadmaps). Bisection
  /// always needs eta.
  EdgeChecker(const CollisionWorld& world, EdgeCheckerSpec spec, bool report_clearance = true)
      : world_(&world),
        spec_(spec),
        report_clearance_(report_clearance),
        slack_(1e-9 + 1e-13 * world.scale()),
        max_evaluations_(bisection_evaluation_limit(world)) {}
  EdgeChecker(CollisionWorld&&, EdgeCheckerSpec, bool = true) = delete;  // the world must outlive it

  /// Starts checking p -> q. With `endpoints_known_free`, the caller vouches that p and q are
  /// free with clearances eta_p and eta_q (a roadmap's vertices): they are not evaluated again.
  void reset(const Config& p, const Config& q, bool endpoints_known_free = false, double eta_p = 0.0,
             double eta_q = 0.0);
  /// The whole check of p -> q at once, without events, for roadmaps: p and q are known free
  /// with clearances eta_p and eta_q (NaN: not known), and `length` is the space's distance from
  /// p to q (what Space::distance computes). The verdict and collision_t are those of
  /// reset(p, q, true, eta_p, eta_q) and step() to the end, and so are bisection's evaluations.
  /// The grid and step checkers skip the configurations the endpoints' clearances prove free
  /// (lambda(p, q(t)) = t lambda(p, q) < eta_p, likewise from q): the same verdict from fewer
  /// evaluations, as the grid's configurations are only ever skipped, never replaced.
  void check_known_free(const Config& p, const Config& q, double length, double eta_p, double eta_q);
  /// The same for the grid and step checkers (what check_known_free() runs for them). Inline:
  /// a roadmap checks every close pair with it, and most are settled here without a
  /// configuration (no interior, or the ends' balls overlap); the rest walk the grid.
  [[gnu::always_inline]] void check_grid_known_free(const Config& p, const Config& q, double length, double eta_p,
                                                     double eta_q) {
    verdict_ = Verdict::Free;
    evaluations_ = 0;
    skipped_ = 0;
    length_ = length;
    collision_t_.reset();
    if (!has_interior(length)) return;
    // Configurations near p or q are proven free by the endpoints' balls: the robot at q(t) is
    // within lambda(p, q(t)) = t lambda of where it is at p, and eta_p clears that. The margins
    // keep rounding in t, lambda, eta and the pose on the safe side: relative ones, and
    // slack_, which grows with the scene's coordinates (poses round to ~1e-16 of them).
    if (!(eta_p > 0.0 || eta_q > 0.0)) return walk_grid(p, q, 0.0, eta_p, eta_q);  // NaN: none skipped
    const double lambda = world_->motion_bound(p, q, length) * (1.0 + 1e-6) + slack_;
    // Balls that overlap along the edge prove every t (t lambda + (1 - t) lambda = lambda <
    // both radii's sum): the common case, without walking the grid (or counting it).
    const double reach_p = eta_p * (1.0 - 1e-6) - slack_, reach_q = eta_q * (1.0 - 1e-6) - slack_;
    if (lambda < reach_p + reach_q && reach_p > 0.0 && reach_q > 0.0) {
      skipped_ = -1;  // every configuration between the ends: counted by skipped() if asked
      return;
    }
    walk_grid(p, q, lambda, eta_p, eta_q);
  }
  /// Grid and step checkers: how many configurations (endpoints included) an edge of this
  /// length gets.
  int grid_configurations(double length) const;
  /// Grid and step checkers: whether grid_configurations(length) > 2, i.e. the edge has
  /// configurations between its ends (only these need the ends' clearances), without its
  /// division.
  bool has_interior(double length) const {
    if (spec_.kind != EdgeCheckerSpec::Kind::Step) return spec_.resolution > 2;
    // A length above the step is at least the next double, step + ulp(step), and ulp(s) / s >
    // 2^-53 for every s: so length / step > 1 + 2^-53 rounds up, past 1, and its ceiling, 2 or
    // more, gives 3 configurations or more. No division: its latency was on every roadmap edge.
    return length > spec_.step;
  }
  /// Bisection's test of a piece whose ends have clearances eta0 and eta1 and whose motion
  /// bound is lambda: lambda < eta0 + eta1 with room for rounding (relative 1e-12 in lambda,
  /// and the scene's slack per end, as check_grid_known_free() allows), so that a piece whose
  /// balls only touch, or touch up to rounding, is split rather than certified.
  bool certifies(double lambda, double eta0, double eta1) const {
    return lambda * (1.0 + 1e-12) + 2.0 * slack_ < eta0 + eta1;
  }
  bool done() const { return verdict_ != Verdict::Pending; }
  /// One unit of work (see the file comment); call only while !done(). The event stays valid
  /// until the next step() or reset() (no copy per step: roadmaps check millions of edges).
  const EdgeEvent& step();

  Verdict verdict() const { return verdict_; }
  /// Configurations evaluated so far (clearance or freeness computations).
  int evaluations() const { return evaluations_; }
  /// check_grid_known_free: the grid's configurations between the ends it did not test because
  /// the endpoints' clearances prove them free (0 otherwise).
  int skipped() const { return skipped_ >= 0 ? skipped_ : grid_configurations(length_) - 2; }
  /// Where the collision was found (t of the configuration), once verdict() == Collision.
  std::optional<double> collision_t() const { return collision_t_; }
  const EdgeCheckerSpec& spec() const { return spec_; }

 private:
  struct Piece {
    double t0, eta0, t1, eta1;
    int depth;
  };
  // check_grid_known_free() past its shortcuts: the grid's configurations between the ends,
  // but those the balls of radius eta_p and eta_q prove free (lambda: the padded motion bound,
  // 0 when neither ball is known), in order until one is in collision.
  void walk_grid(const Config& p, const Config& q, double lambda, double eta_p, double eta_q);
  // Tests q(t) and writes the Evaluate fields of event_.
  void evaluate(double t, bool need_clearance);
  void step_grid();
  void step_bisection();

  const CollisionWorld* world_;
  EdgeCheckerSpec spec_;
  bool report_clearance_;
  double slack_;  // an absolute margin for rounding, from the scene's scale
  int max_evaluations_;  // bisection_evaluation_limit(world)
  Config p_, q_, delta_;  // delta_ = q - p the short way round
  Verdict verdict_ = Verdict::Free;
  int evaluations_ = 0;
  int skipped_ = 0;           // -1: all of the grid between the ends (counted when asked)
  double length_ = 0.0;       // check_grid_known_free: the edge's length, for skipped()
  std::optional<double> collision_t_;
  bool known_free_ = false;
  int n_ = 0;                 // grid/step: configurations on this edge (check_grid_known_free
                              // sets it only where it walks the grid: step() follows a reset())
  double eta_p_ = 0.0, eta_q_ = 0.0;
  int next_ = 0;              // grid: next index; bisection: 0/1 = endpoints, 2 = pieces
  std::vector<Piece> queue_;  // bisection FIFO: queue_[head_..]
  std::size_t head_ = 0;
  EdgeEvent event_;
};

/// The outcome of a whole check, with its events if asked for.
struct EdgeCheckResult {
  bool collision = false;
  int evaluations = 0;
  std::optional<double> collision_t;
  std::vector<EdgeEvent> trace;
};
/// Runs a checker on p -> q to the end (p and q are evaluated like any configuration).
EdgeCheckResult check_edge(const CollisionWorld& world, const EdgeCheckerSpec& spec, const Config& p,
                           const Config& q, bool want_trace = false);

/// The smallest N in [2, max_n] for which the grid checker finds a collision on p -> q.
struct MinGridResult {
  std::optional<int> n;    ///< none: no grid up to max_n sees it (or the edge is proven free)
  long long evaluations = 0;  ///< configurations evaluated (the bisection check's included)
  bool exhausted = false;  ///< gave up after max_evaluations: n is not known
};
/// None, at once, when the exact bisection check proves the edge free. Otherwise N = 2, 3, ...
/// in turn, but a configuration of grid N is evaluated only where the configurations evaluated
/// so far do not already prove it free (their clearances' balls cover it, as bisection
/// certifies pieces): the same answer as checking every grid in full (max_n^2 / 2 evaluations,
/// minutes for max_n = 100000 and a thin wall), from about one evaluation per N near each
/// collision. Stops with `exhausted` after `max_evaluations`. `exact`: the bisection check of
/// p -> q (check_edge()), where the caller has done it already; else it is done here.
MinGridResult min_grid_search(const CollisionWorld& world, const Config& p, const Config& q, int max_n,
                              long long max_evaluations, const EdgeCheckResult* exact = nullptr);
/// The same question with the endpoints not counted: the smallest N in [1, max_n] for which
/// the N configurations strictly between p and q, t_i = i / (N + 1), i = 1..N, include one in
/// collision (P12 read as "N points between p and q"). Those t are the grid checker's
/// i / (N' - 1) for N' = N + 2 to the bit, so with p and q free the answer is
/// min_grid_search()'s N' - 2 (and searched that way); with an endpoint in collision, where
/// that grid stops at once, the interior grids are tested one by one. The same
/// `max_evaluations` and `exact` as min_grid_search().
MinGridResult min_interior_grid_search(const CollisionWorld& world, const Config& p, const Config& q, int max_n,
                                       long long max_evaluations, const EdgeCheckResult* exact = nullptr);
/// min_grid_search() without a limit: its N.
std::optional<int> min_grid_resolution(const CollisionWorld& world, const Config& p, const Config& q, int max_n);

}  // namespace csl
