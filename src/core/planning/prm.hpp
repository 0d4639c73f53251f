#pragma once
// The probabilistic roadmap method as the homework states it (section 2), as a stepper:
//   1. add q_init and q_final to V;
//   2. n times: sample q uniformly in Q, add it to V if it is free;
//   3. for each p in V, for each q != p close to p: add (p, q) to E if the straight line is free
//      (or, with a local connector, if the connector finds a path it proves free: section 2.4);
//   4. if q_init and q_final are connected, that sequence of edges is the path; else no path.
// step() does one unit of work and returns what it did: add one endpoint, draw one sample,
// find one vertex's neighbours, check one candidate edge (with the chosen edge checker or local
// connector, run to its end), or search the graph once. Budgets are counts, never time; nothing runs in threads.
// Steps are deterministic from (world, start, goal, params), so going back to step k is a
// replay of k steps from the start and gives the identical state.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/base/params.hpp"
#include "core/checking/edge_check.hpp"
#include "core/planning/graph.hpp"
#include "core/planning/local_connector.hpp"
#include "core/planning/nearest.hpp"
#include "core/planning/nearest_grid.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/roadmap.hpp"
#include "core/planning/sampler.hpp"

namespace csl {

/// Which vertices are "close": the k nearest, all within a radius, or PRM*'s k(n).
struct NeighborRule {
  enum class Kind { Nearest, Radius, PrmStar } kind = Kind::Nearest;
  int k = 10;
  double radius = 0.1;
  /// PRM* (Karaman and Frazzoli 2011): k(n) = ceil(e (1 + 1/d) ln n) for n vertices in d dims.
  static int prm_star_k(int n, int d);
  /// "k:10", "radius:0.1" or "prm*"; throws std::invalid_argument.
  static NeighborRule parse(const std::string& text);
  std::string name() const;
};

struct PrmParams {
  int samples = 200;  ///< n, the number of samples drawn: draws of `sampler`, each keeping at most one
  /// Where samples come from (core/planning/sampler.hpp); uniform: the homework's PRM.
  SamplerSpec sampler;
  NeighborRule neighbors;
  EdgeCheckerSpec checker;  ///< default: exact bisection
  std::uint64_t seed = 1;
  /// How close pairs are joined: null (the default) = the straight line, checked by `checker`;
  /// otherwise the connector's path, with seed pair_seed(seed, a, b) for the pair a < b.
  std::shared_ptr<const LocalConnector> connector;
};
/// The most samples PRM takes: the spec's limit (core/base/params.hpp), which the parsers use.
inline constexpr int kMaxPrmSamples = static_cast<int>(kPrmSamples.max);

/// How many candidate pairs PRM is expected to check with `rule` and `samples` samples in
/// `space`, counting every sample as free (obstacles only lower it). A rule of k: each of the
/// n + 2 vertices proposes at most k others. A radius r: each of the (n+2)(n+1)/2 pairs is within
/// r with probability mu(B_r) / mu(Q), less where a ball sticks out of Q. A radius makes the work
/// grow with n^2, so a UI checks this before it lets a run take minutes and gigabytes.
double expected_candidate_pairs(const Space& space, const NeighborRule& rule, int samples);
/// The radius whose expected_candidate_pairs() for `samples` is `pairs` (inverse of the above);
/// infinite when even every pair is no more than `pairs`.
double radius_for_pairs(const Space& space, int samples, double pairs);
/// Whether PRM with `rule` and `samples` is expected to check at most `max_pairs` candidate
/// pairs. A radius up to radius_for_pairs() passes as well: r -> pairs -> r may come back a hair
/// over the limit, and the radius a UI or an error offers from that inverse must pass.
bool within_pairs_budget(const Space& space, const NeighborRule& rule, int samples, double max_pairs);
/// radius_for_pairs() rounded down to 4 significant digits, as text ("0.03989") that, read
/// back, is no more than it: the radius an error message can name and a user can type.
std::string radius_for_pairs_text(const Space& space, int samples, double pairs);

/// The seed a local connector gets for vertices a < b: splitmix64 of the PRM seed and the pair.
std::uint64_t pair_seed(std::uint64_t seed, int a, int b);

enum class PrmPhase { Endpoints, Sampling, Connecting, Query, Done };
const char* phase_name(PrmPhase p);

/// PRM's events are the planners' (core/planning/planner.hpp).
using PrmEvent = PlannerEvent;

class Prm final : public Planner {
 public:
  /// The world must outlive the planner (it is referenced, not copied).
  Prm(const CollisionWorld& world, Config start, Config goal, PrmParams params);
  Prm(CollisionWorld&&, Config, Config, PrmParams) = delete;

  const char* name() const override { return "prm"; }
  bool done() const override { return phase_ == PrmPhase::Done; }
  /// One step (see the file comment); the event stays valid until the next step.
  const PrmEvent& step() override;
  /// Steps to the end of the current phase: the state and step count of step() repeated until
  /// the phase changes (or done()), and last_event() that of its last step, but the steps before
  /// the last build no events (roadmaps of many thousands of samples: the CLI, experiments).
  void finish_phase() override;
  /// Back to the state before step 1.
  void reset() override;

  long steps() const override { return steps_; }
  PrmPhase phase() const { return phase_; }
  const char* phase_label() const override { return phase_name(phase_); }
  const PrmParams& params() const { return params_; }
  const CollisionWorld& world() const override { return *world_; }
  const Roadmap& roadmap() const override { return roadmap_; }
  const PrmEvent& last_event() const override { return event_; }
  double progress() const override;
  std::string describe(const PlannerEvent& e, const Scene& scene) const override;

  bool solved() const override { return !path_.empty(); }
  /// Vertex indices from q_init to q_final (empty unless solved()).
  const std::vector<int>& path() const override { return path_; }
  /// The roadmap edges of the path, in order from q_init (empty unless solved()).
  const std::vector<int>& path_edges() const { return path_edges_; }
  /// The path as configurations: its vertices with each edge's waypoints in between, in order
  /// from q_init to q_final (the straight pieces between consecutive ones are all free).
  std::vector<Config> path_configurations() const override;
  double path_length() const override { return path_length_; }
  /// Number of connected components of (V, E).
  int components() const override { return components_.sets(); }
  /// From the union-find PRM keeps as it connects (the interface's default counts again).
  std::vector<int> component_labels() const override;
  long edge_checks() const override { return edge_checks_; }
  long evaluations() const override { return evaluations_; }
  long edges_alive() const override { return edges_alive_; }
  /// Samples drawn so far (accepted + rejected).
  int samples_drawn() const override { return samples_drawn_; }
  /// The vertex being connected and its candidate neighbours (Connecting phase).
  int connecting_vertex() const { return p_; }
  const std::vector<Neighbor>& candidates() const { return candidates_; }

 private:
  // The units of work of step(); kEmit: describe it in event_ (finish_phase() runs most units
  // without, and must leave the same state).
  template <bool kEmit>
  void draw_sample();
  template <bool kEmit>
  void draw_from_sampler();
  void begin_connecting();
  template <bool kEmit>
  void find_candidates();
  template <bool kEmit>
  void check_candidate();
  // E gets (p_, q), proven free, of this length: the straight line, or the connector's path
  // `path` (its index in Roadmap::paths).
  void add_edge(int q, double length, int path = -1);
  // check_candidate() with params_.connector: the connector's path or nothing.
  template <bool kEmit>
  void connect_candidate(int q);
  void query();
  // Whether every straight piece of edge r is free by the exact check; on failure, the
  // collision's t on the failing piece.
  bool verify_edge(const RoadmapEdge& r, double& collision_t);

  const CollisionWorld* world_;
  Config start_, goal_;
  PrmParams params_;
  Rng rng_;
  Sampler sampler_;
  EdgeChecker checker_;
  EdgeChecker exact_;  // re-verifies paths
  NeighborIndex index_;
  PrmPhase phase_ = PrmPhase::Endpoints;
  PrmEvent event_;
  long steps_ = 0;
  Roadmap roadmap_;
  mutable UnionFind components_;  // find() compresses paths: a cache, not state
  int samples_drawn_ = 0;
  int k_ = 0;                     // neighbours per vertex for the k rules
  std::vector<NearNeighbor> knn_;  // the k_ nearest of every vertex (flat; index -1 pads short rows)
  // Per entry of knn_: 1 if the pair was already a candidate of the smaller vertex (computed
  // once in begin_connecting(), which also counts the candidates to size the edge list).
  std::vector<unsigned char> seen_;
  int p_ = -1;                    // vertex being connected
  std::vector<Neighbor> candidates_;
  std::size_t next_candidate_ = 0;
  std::vector<Neighbor> scratch_;
  std::vector<int> path_;
  std::vector<int> path_edges_;
  double path_length_ = 0.0;
  long edge_checks_ = 0, evaluations_ = 0, edges_alive_ = 0;
};

/// Makes Prm planners with `params`.
PlannerFactory prm_factory(PrmParams params);

}  // namespace csl
