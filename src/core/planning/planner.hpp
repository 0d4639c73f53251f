#pragma once
// A steppable sampling-based planner, as the app, the CLI and experiments see one (OMPL's
// base::Planner plays this part there; ours steps instead of solving in one call, so that a
// lesson can draw every step and a test can assert it). PRM (core/planning/prm.hpp), RRT and
// RRT-Connect (core/planning/rrt.hpp, rrt_connect.hpp) implement it; the tree planners store
// their trees as a Roadmap whose edges join a child to its parent.
//
// The contract every planner keeps:
// - step() does one unit of work and returns what it did; the event stays valid until the next
//   step. Steps are deterministic from (world, start, goal, parameters, seed), so going back is
//   a replay: run_to(k) from the start gives the identical state after k steps.
// - finish_phase() reaches the state of stepping until phase_label() changes (or done()), emitting
//   only the last event, so that runs of many thousands of samples build no text on the way.
// - roadmap(), path() and the counters describe the state after steps() steps.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/base/config.hpp"
#include "core/checking/collision.hpp"
#include "core/planning/roadmap.hpp"
#include "core/scene/scene.hpp"

namespace csl {

/// What one step did. The kinds are PRM's (and two of Lazy PRM's: EdgeChecked, PathCandidate);
/// the tree planners (core/planning/tree_planner.hpp)
/// reuse them: a tree's new vertex comes with its edge to its parent, one SampleAccepted with
/// `vertex` the new one and `other` its parent (`sample` -1 for RRT-Connect's connect steps);
/// an edge between vertices already there (the trees' join) is an EdgeAdded; an extension
/// whose end q is in collision is a SampleRejected, one whose edge is, an EdgeRejected with
/// `other` -1 (q: the end; `vertex`: the tree vertex it left from).
struct PlannerEvent {
  enum class Kind {
    AddEndpoint,          ///< vertex (0 = q_init, 1 = q_final) added
    EndpointInCollision,  ///< q_init or q_final is not free: no path; obstacle = which
    SampleAccepted,       ///< sample (1..n) q is free: became `vertex`
    SampleRejected,       ///< sample q is in collision with `obstacle`
    Neighbors,            ///< `vertex` is being connected: `candidates` new pairs to check
    EdgeAdded,            ///< (vertex, other) proven free and added to E
    EdgeRejected,         ///< (vertex, other) in collision at collision_t (NaN: the local
                          ///< connector found no path)
    PathEdgeRemoved,      ///< an edge of the found path failed the exact re-check: removed
                          ///< (collision_t: on the failing straight piece of the edge)
    PathFound,            ///< q_init and q_final connected: path_length
    NoPath,               ///< not connected: the planner declares no path
    // Lazy PRM's (core/planning/lazy_prm.hpp), whose edges go in unchecked (EdgeAdded with no
    // evaluation) and are checked only when a shortest path uses them:
    EdgeChecked,          ///< (vertex, other), an edge of the candidate path, proven free by the exact check
    PathCandidate,        ///< the search found a path (path_length) with `candidates` edges still unchecked
  };
  Kind kind = Kind::AddEndpoint;
  long step = 0;      ///< 1-based number of this step
  int sample = -1;    ///< 1..n for sample events
  int vertex = -1;
  int other = -1;
  Config q;           ///< the sample or endpoint
  int obstacle = -1;  ///< the obstacle hit (rejected sample, endpoint in collision)
  int candidates = 0;
  int seen = 0;         ///< Neighbors: close pairs left out, checked already from the other vertex
  int evaluations = 0;  ///< configurations the edge check (or the connector) evaluated
  int skipped = 0;      ///< grid checkers: configurations the endpoints' clearances prove free, untested
  double collision_t = std::numeric_limits<double>::quiet_NaN();
  double path_length = 0.0;
};
const char* event_kind_name(PlannerEvent::Kind k);

class Planner {
 public:
  virtual ~Planner() = default;

  /// A short name: "prm".
  virtual const char* name() const = 0;

  // ---- stepping
  virtual const PlannerEvent& step() = 0;
  /// Steps to the end of the current phase (see the file comment).
  virtual void finish_phase() = 0;
  /// Steps to the end, phase by phase.
  void run() {
    while (!done()) finish_phase();
  }
  /// Back to the state before step 1.
  virtual void reset() = 0;
  /// To the state after `steps` steps (replaying from the start if that is behind us).
  void run_to(long steps) {
    if (steps < this->steps()) reset();
    while (this->steps() < steps && !done()) step();
  }
  virtual bool done() const = 0;
  virtual long steps() const = 0;
  /// The phase's name as the API and the log show it ("sampling", "connecting", "done").
  virtual const char* phase_label() const = 0;
  virtual const PlannerEvent& last_event() const = 0;
  /// How far a run to the end has come, in [0, 1] (a progress bar's, by phase: not a promise
  /// about time).
  virtual double progress() const = 0;
  /// One line describing the event in words, obstacles named as `scene` lists them (the event log).
  virtual std::string describe(const PlannerEvent& e, const Scene& scene) const = 0;

  // ---- what it built
  virtual const CollisionWorld& world() const = 0;
  /// The graph (or tree) built so far.
  virtual const Roadmap& roadmap() const = 0;
  /// Edges of roadmap() still in the graph (an edge removed by a re-check stays listed, dead).
  virtual long edges_alive() const = 0;
  /// Connected components of the live graph.
  virtual int components() const = 0;
  /// A dense component number per vertex of roadmap(), ordered by each component's smallest
  /// vertex (what the lessons colour by). By default from the live edges; a planner that keeps
  /// its components as it grows answers from them.
  virtual std::vector<int> component_labels() const;
  virtual bool solved() const = 0;
  /// Vertex indices from q_init to q_final (empty unless solved()).
  virtual const std::vector<int>& path() const = 0;
  /// The path as configurations, with any local connector's waypoints between its vertices.
  virtual std::vector<Config> path_configurations() const = 0;
  virtual double path_length() const = 0;

  // ---- what it cost
  virtual long edge_checks() const = 0;
  /// Configurations the collision checker evaluated.
  virtual long evaluations() const = 0;
  /// Configurations given to the collision checker by this planner's steps: every is_free()
  /// and clearance() of world() (CollisionWorld::configurations_tested()): samples, the
  /// bridge and Gaussian samplers' partner draws, endpoints, edge checks' points, bisection's
  /// midpoints, the ends' clearances and the path's exact re-check. The same measure for every
  /// planner (evaluations() is each planner's own: PRM's leaves its samples out), taken at one
  /// place, the world, by TestTally around step() and finish_phase(). Virtual only so that a
  /// wrapper passes its inner planner's on.
  virtual long long configurations_tested() const { return tested_; }
  virtual int samples_drawn() const = 0;
  /// For a planner that puts edges into its roadmap on trust (Lazy PRM checks one only when a
  /// shortest path uses it): per entry of roadmap().edges, 1 once the exact check examined it.
  /// Null for the planners that prove every edge before adding it. A virtual, not a cast to the
  /// type, so that a wrapper (the app's RecordingPlanner) passes it on and the JSON and the
  /// drawing need not know which planner they have.
  virtual const std::vector<unsigned char>* checked_edge_flags() const { return nullptr; }
  /// Live edges never checked (0 where checked_edge_flags() is null).
  virtual long edges_unchecked() const { return 0; }
  /// What replaying to the current step costs, in samples drawn plus edges checked: the app
  /// replays on every frame of a drag only while this is small (app/views/drag_replay.hpp).
  long replay_work() const { return static_cast<long>(samples_drawn()) + edge_checks(); }

 protected:
  /// Adds to configurations_tested() what world() counts while it lives: a planner makes one
  /// at the top of step() and finish_phase(). Nested ones (finish_phase() ending in step())
  /// count once, by the outermost. Differences of the world's counter, so that planners
  /// sharing a world (the compare lesson's two, an experiment's trials) each count their own.
  class TestTally {
   public:
    explicit TestTally(Planner& p) : p_(p) {
      if (p_.tally_depth_++ == 0) p_.tally_from_ = p_.world().configurations_tested();
    }
    ~TestTally() {
      if (--p_.tally_depth_ == 0)
        p_.tested_ += static_cast<long long>(p_.world().configurations_tested() - p_.tally_from_);
    }
    TestTally(const TestTally&) = delete;
    TestTally& operator=(const TestTally&) = delete;

   private:
    Planner& p_;
  };
  /// For reset(): back to nothing tested.
  void reset_tested() { tested_ = 0; }

 private:
  long long tested_ = 0;
  int tally_depth_ = 0;
  std::uint64_t tally_from_ = 0;
};

/// Makes a planner from start to goal in `world` (which must outlive it), with parameters the
/// factory holds: how the app's sessions and experiments get a planner without naming its type.
using PlannerFactory =
    std::function<std::unique_ptr<Planner>(const CollisionWorld& world, const Config& start, const Config& goal)>;

}  // namespace csl
