#pragma once
// A lesson's PRM planner on the lesson's scene, shared by the lessons that run PRM (Step PRM, the
// torus): rebuilt when the scene or the parameters change and replayed to the step the student
// was at, and moved toward a step in slices of a frame, so that no frame waits for long work
// (issue 27: "Run all" on 20000 samples, a link to step 99999999 or a replay after an edit held
// the page for seconds, and a link's heavy state was autosaved and held every later start).
//
// A request (run to the end, to the phase's end, to a step, a replay after an edit) becomes a
// job; work(ms) advances it for that long, once a frame, and the API finishes it at once unless
// asked not to. While a job replays from the start (a step back, an edit, new parameters), the
// planner from before stays on screen, faded, with the job's progress, until the replay
// reaches its step; a job going forward grows the planner on screen. cancel() stops a job: a
// forward run stays where it got to, a step back stays where it was, and a replay for a new
// scene or new parameters keeps what it has built (the old planner belongs to the old scene).
//
// During a drag of an obstacle the planner keeps the scene from before the drag if replaying
// it on every frame would be slow (drag_replay.hpp); world() follows the drag all the same.
#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>

#include "core/prm.hpp"
#include "core/scene.hpp"

namespace csl::app {

class PlannerSession {
 public:
  /// A job's target meaning "to the end".
  static constexpr long kToEnd = -1;
  /// The most steps a link or the API asks for (app.cpp's run_to): what a snapshot holds for a
  /// run to the end that is still running, so that a reload comes back to its end.
  static constexpr long kMaxSteps = 100000000;

  /// A planner for `scene` and `params` at step 0.
  PlannerSession(const Scene& scene, const PrmParams& params);

  /// The planner on screen (the job's, while it goes forward; the one from before, while a
  /// replay catches up).
  const Prm& prm() const { return *shown_.prm; }
  Prm& prm() { return *shown_.prm; }
  /// The current scene's world (follows a drag; the planner's may be an older scene's). A request
  /// or an edit replaces it: hold no reference to it across one.
  const CollisionWorld& world() const { return *world_; }
  /// The scene the shown planner runs in (its obstacles are what the event log names).
  const Scene& planned_scene() const { return shown_.scene; }
  /// Planners built so far (every rebuild counts): the API's planner_builds.
  long builds() const { return builds_; }
  /// Changes whenever the shown roadmap may have: a step or another planner.
  long long version() const { return (static_cast<long long>(shown_.id) << 32) + prm().steps(); }

  /// A new planner for `scene` and `params`, replayed to `steps` (kToEnd: run to the end).
  void rebuild(const Scene& scene, const PrmParams& params, long steps);
  /// The editor changed the scene: replay to the same step now, or, during a drag that would
  /// make that slow, when the drag ends (call again with dragging = false at the release).
  void edited(const Scene& scene, bool dragging);
  /// A drag holds the planner from before it (drawn faded; replayed at the release).
  bool replay_pending() const { return world_ != shown_.world && !next_; }

  // ---- requests (each replaces any job)
  void step_forward();
  /// One step before the one the student asked for (pressed again during the replay, one more;
  /// during a run forward, one before where the run got to).
  void step_back();
  void go_to(long steps);
  void run_to_end();
  void finish_phase();
  void reset();

  // ---- the job
  bool busy() const { return job_ != Job::None; }
  /// A replay from the start is catching up: the planner on screen is the one from before.
  bool replaying() const { return next_.has_value(); }
  /// The steps the job heads for (kToEnd, or the phase's end: -1), or the shown planner's.
  long target() const;
  /// The step the student asked to be at: where a job heads, or where a step, a run or a cancel
  /// left the planner. An edit replays to it, and a snapshot holds it. It is not lowered when an
  /// edit makes the planner end sooner (an obstacle dragged over the start ends the run at step
  /// 1): undoing the edit brings the whole run back (issue 21).
  long wanted_steps() const;
  /// How far the job is, in [0, 1].
  double progress() const;
  /// One line for the progress bar: "replaying to step 120000", "running to the end".
  std::string job_text() const;
  /// Advances the job for about `ms` milliseconds of work (infinite: to its end).
  void work(double ms);
  void cancel();

 private:
  struct Run {
    std::shared_ptr<const CollisionWorld> world;  // the planner references it
    std::unique_ptr<Prm> prm;
    Scene scene;
    long id = 0;
    Run() = default;
    Run(Run&&) = default;
    // The old planner goes before the world it references (the default would release the world
    // first).
    Run& operator=(Run&& o) noexcept {
      prm.reset();
      world = std::move(o.world);
      prm = std::move(o.prm);
      scene = std::move(o.scene);
      id = o.id;
      return *this;
    }
  };
  enum class Job { None, Forward, Phase, Replay };

  Run make_run(std::shared_ptr<const CollisionWorld> world, const Scene& scene, const PrmParams& params);
  // A replay for a new scene or new parameters is running (the planner on screen is stale).
  bool rebuilding() const { return next_ && keep_on_cancel_; }
  void start(Job job, long target);
  // The planner the job advances.
  Prm& worked() { return next_ ? *next_->prm : *shown_.prm; }
  const Prm& worked() const { return next_ ? *next_->prm : *shown_.prm; }
  bool job_done() const;
  void finish_job();

  std::shared_ptr<const CollisionWorld> world_;
  Run shown_;
  std::optional<Run> next_;  // a replay catching up (shown_ stays on screen meanwhile)
  PrmParams params_;
  Job job_ = Job::None;
  long target_ = 0;
  long from_ = 0;                         // the worked planner's steps when the job started
  long desired_ = 0;                      // wanted_steps() when no job has a target
  PrmPhase phase_ = PrmPhase::Endpoints;  // Job::Phase: the phase to finish
  bool keep_on_cancel_ = false;           // Job::Replay: the replay replaces shown_ even unfinished
  long builds_ = 0;
};

/// The job for a lesson's state(): null, or {"target": steps|null (to the end), "progress"}.
nlohmann::json running_json(const PlannerSession& session);
/// The line over the faded planner while a replay catches up: "replaying to step 1200: 45%".
std::string replaying_text(const PlannerSession& session);

}  // namespace csl::app
