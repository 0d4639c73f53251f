#pragma once
// A lesson's planner on the lesson's scene, shared by the lessons that step a planner (Step PRM,
// the torus), the way Box2D's samples share their base: the world, the planner (any
// core/planning/planner.hpp, made by a factory), rebuilt when the scene or the parameters change and replayed to the step the student
// was at, and moved toward a step in slices of a frame, so that no frame waits for long work
// (issue 27: "Run all" on 20000 samples, a link to step 99999999 or a replay after an edit held
// the page for seconds, and a link's heavy state was autosaved and held every later start).
//
// A request (run to the end, to the phase's end, to a step, a replay after an edit) becomes a
// job; work(ms) advances it for that long, once a frame, and the API finishes it at once unless
// asked not to. While a job replays from the start (a step back, an edit, new parameters), the
// planner from before stays on screen, faded, with the job's progress, until the replay
// reaches its step; a job going forward grows the planner on screen. cancel_work() stops a job: a
// forward run stays where it got to, a step back stays where it was, and a replay for a new
// scene or new parameters keeps what it has built (the old planner belongs to the old scene).
//
// During a drag of an obstacle the planner keeps the scene from before the drag if replaying
// it on every frame would be slow (drag_replay.hpp); world() follows the drag all the same.
#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>

#include "app/lessons/recording_planner.hpp"
#include "app/shell/context.hpp"
#include "app/shell/event_log.hpp"
#include "app/shell/stepper.hpp"
#include "core/planning/planner.hpp"
#include "core/planning/prm.hpp"
#include "core/scene/scene.hpp"

namespace csl::app {

class PlannerSession final : public Stepper {
 public:
  /// A job's target meaning "to the end".
  static constexpr long kToEnd = -1;
  /// The most steps a link or the API asks for (app.cpp's run_to): what a snapshot holds for a
  /// run to the end that is still running, so that a reload comes back to its end.
  static constexpr long kMaxSteps = 100000000;

  /// A planner made by `make` for `scene`, at step 0.
  PlannerSession(const Scene& scene, PlannerFactory make);
  /// PRM with `params`.
  PlannerSession(const Scene& scene, const PrmParams& params) : PlannerSession(scene, prm_factory(params)) {}

  /// The planner on screen (the job's, while it goes forward; the one from before, while a
  /// replay catches up).
  const Planner& shown() const { return *shown_.planner; }
  /// The same, as the planner type the lesson made (what only that type draws: PRM's candidate
  /// pairs), looking through a RecordingPlanner to the planner it watches; throws std::bad_cast
  /// if the lesson made another.
  template <class P>
  const P& shown_as() const {
    const Planner* p = shown_.planner.get();
    if (const auto* r = dynamic_cast<const RecordingPlanner*>(p)) p = &r->inner();
    return dynamic_cast<const P&>(*p);
  }
  /// The recording around the shown planner (a lesson that made it with recorded()), or null.
  const RecordingPlanner* recording() const { return dynamic_cast<const RecordingPlanner*>(shown_.planner.get()); }
  /// The current scene's world (follows a drag; the planner's may be an older scene's). A request
  /// or an edit replaces it: hold no reference to it across one.
  const CollisionWorld& world() const { return *world_; }
  /// The scene the shown planner runs in (its obstacles are what the event log names).
  const Scene& planned_scene() const { return shown_.scene; }
  /// Planners built so far (every rebuild counts): the API's planner_builds.
  long builds() const { return builds_; }
  /// Changes whenever the shown roadmap may have: a step or another planner.
  long long version() const { return (static_cast<long long>(shown_.id) << 32) + shown().steps(); }

  /// A new planner made by `make` for `scene`, replayed to `steps` (kToEnd: run to the end).
  void rebuild(const Scene& scene, PlannerFactory make, long steps);
  void rebuild(const Scene& scene, const PrmParams& params, long steps) { rebuild(scene, prm_factory(params), steps); }
  /// The editor changed the scene: replay to the same step now, or, during a drag that would
  /// make that slow, when the drag ends (call again with dragging = false at the release).
  void edited(const Scene& scene, bool dragging);
  /// A drag holds the planner from before it (drawn faded; replayed at the release).
  bool replay_pending() const { return world_ != shown_.world && !next_; }

  // ---- Stepper: requests (each replaces any job)
  long steps() const override { return shown().steps(); }
  bool finished() const override { return shown().done(); }
  void step_forward() override;
  /// One step before the one the student asked for (pressed again during the replay, one more;
  /// during a run forward, one before where the run got to). At step 0, nothing.
  void step_back() override;
  void run_to(long steps) override;
  void run_all() override;
  void finish_phase() override;
  void reset() override;

  // ---- Stepper: the job
  bool busy() const override { return job_ != Job::None; }
  /// A replay from the start is catching up: the planner on screen is the one from before.
  bool replaying() const { return next_.has_value(); }
  /// The steps the job heads for (kToEnd, or the phase's end: -1), or the shown planner's.
  long target() const;
  /// The step the student asked to be at: where a job heads, or where a step, a run or a cancel
  /// left the planner. An edit replays to it, and a snapshot holds it. It is not lowered when an
  /// edit makes the planner end sooner (an obstacle dragged over the start ends the run at step
  /// 1): undoing the edit brings the whole run back (issue 21).
  long wanted_steps() const override;
  /// How far the job is, in [0, 1].
  double progress() const override;
  /// One line for the progress bar: "replaying to step 120000", "running to the end".
  std::string busy_text() const override;
  /// Advances the job for about `ms` milliseconds of work (infinite: to its end).
  void work(double ms) override;
  void cancel_work() override;

  /// Once a frame: Play's steps for this frame (it stops at the end) and the log (log_steps()).
  void update(LabContext& ctx, const std::string& ready);
  /// Brings `log` up to the planner on screen: each new step's describe(); after a replay, a
  /// jump or another planner, the log starts again with where the planner stands (or, at step
  /// 0, `ready`). Call once a frame; forget_log() makes the next call start again.
  void log_steps(EventLog& log, const std::string& ready);
  void forget_log() { logged_version_ = -1; }

 private:
  struct Run {
    std::shared_ptr<const CollisionWorld> world;  // the planner references it
    std::unique_ptr<Planner> planner;
    Scene scene;
    long id = 0;
    Run() = default;
    Run(Run&&) = default;
    // The old planner goes before the world it references (the default would release the world
    // first).
    Run& operator=(Run&& o) noexcept {
      planner.reset();
      world = std::move(o.world);
      planner = std::move(o.planner);
      scene = std::move(o.scene);
      id = o.id;
      return *this;
    }
  };
  enum class Job { None, Forward, Phase, Replay };

  Run make_run(std::shared_ptr<const CollisionWorld> world, const Scene& scene);
  // A replay for a new scene or new parameters is running (the planner on screen is stale).
  bool rebuilding() const { return next_ && keep_on_cancel_; }
  void start(Job job, long target);
  // The planner the job advances.
  Planner& worked() { return next_ ? *next_->planner : *shown_.planner; }
  const Planner& worked() const { return next_ ? *next_->planner : *shown_.planner; }
  bool job_done() const;
  void finish_job();

  std::shared_ptr<const CollisionWorld> world_;
  Run shown_;
  std::optional<Run> next_;  // a replay catching up (shown_ stays on screen meanwhile)
  PlannerFactory make_;
  Job job_ = Job::None;
  long target_ = 0;
  long from_ = 0;                         // the worked planner's steps when the job started
  long desired_ = 0;                      // wanted_steps() when no job has a target
  std::string phase_;                     // Job::Phase: the phase to finish
  bool keep_on_cancel_ = false;           // Job::Replay: the replay replaces shown_ even unfinished
  long builds_ = 0;
  long long logged_version_ = -1;  // log_steps(): the version() it logged
  long logged_steps_ = -1;
};

/// `line` (a planner's event in words) with every "length <number>" made "length hidden": what the
/// log shows while an instructor hides the path's length (instructor.hpp); PRM's, the trees' and
/// Lazy PRM's lines all name it so.
std::string without_lengths(std::string line);

/// The job for a lesson's state(): null, or {"target": steps|null (to the end), "progress"}.
nlohmann::json running_json(const PlannerSession& session);
/// The line over the faded planner while a replay catches up: "replaying to step 1200: 45%".
std::string replaying_text(const PlannerSession& session);

}  // namespace csl::app
