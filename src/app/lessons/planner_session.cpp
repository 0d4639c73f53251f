#include "app/lessons/planner_session.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "app/shell/instructor.hpp"
#include "app/views/drag_replay.hpp"
#include "imgui.h"

namespace csl::app {

namespace {
// A request's first slice runs at once, in the call: most jobs (a step back on a few hundred
// samples, a replay after a small edit) end within it, and nothing is seen to wait.
constexpr double kRequestSliceMs = 30.0;

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

PlannerSession::PlannerSession(const Scene& scene, PlannerFactory make) : make_(std::move(make)) {
  world_ = std::make_shared<const CollisionWorld>(scene);
  shown_ = make_run(world_, scene);
}

PlannerSession::Run PlannerSession::make_run(std::shared_ptr<const CollisionWorld> world, const Scene& scene) {
  Run run;
  run.planner = make_(*world, scene.start, scene.goal);
  run.world = std::move(world);
  run.scene = scene;
  run.id = ++builds_;
  return run;
}

void PlannerSession::rebuild(const Scene& scene, PlannerFactory make, long steps) {
  make_ = std::move(make);
  world_ = std::make_shared<const CollisionWorld>(scene);
  next_ = make_run(world_, scene);
  desired_ = steps == kToEnd ? desired_ : steps;
  start(Job::Replay, steps);
  keep_on_cancel_ = true;  // the planner from before belongs to another scene or other parameters
  work(kRequestSliceMs);
}

void PlannerSession::edited(const Scene& scene, bool dragging) {
  // A drag back to where it was pressed gives back the scene the planner ran in, exactly (see
  // SceneEditor::continue_drag): its world again, and nothing to replay.
  if (same_content(scene, shown_.scene)) {  // (its name may say "(edited)" meanwhile: app/shell/scene_name)
    world_ = shown_.world;
    if (next_) {  // a replay for another scene: the one on screen is this scene's again
      next_.reset();
      job_ = Job::None;
    }
    return;
  }
  if (!dragging || replay_is_live(shown())) return rebuild(scene, make_, wanted_steps());
  // (A drag keeps the step the student asked for: wanted_steps() is not where the planner of
  // some frame of the drag ended.)
  if (next_) {  // a replay for a scene the drag has left behind
    next_.reset();
    job_ = Job::None;
  }
  world_ = std::make_shared<const CollisionWorld>(scene);
}

void PlannerSession::step_forward() {
  cancel_work();
  if (!shown().done()) shown_.planner->step();
  desired_ = shown().steps();
}

void PlannerSession::step_back() {
  if (wanted_steps() <= 0) return;
  if (job_ == Job::Forward || job_ == Job::Phase) cancel_work();
  run_to(wanted_steps() - 1);
}

void PlannerSession::run_to(long steps) {
  steps = std::max(0L, steps);
  desired_ = steps;
  if (next_ && (rebuilding() || steps < shown().steps())) {
    // A replay is running (for a new scene, or back in this one) and still the way there: it
    // heads for this step instead, from the start again only if it is already past it (a step
    // back pressed again keeps the replay's progress).
    if (steps < next_->planner->steps()) next_ = make_run(next_->world, next_->scene);
    target_ = steps;
    from_ = next_->planner->steps();
    return work(kRequestSliceMs);
  }
  if (steps >= shown().steps()) {
    start(Job::Forward, steps);
  } else {
    // Back: a replay from the start in a second planner; this one stays on screen meanwhile.
    next_ = make_run(shown_.world, shown_.scene);
    start(Job::Replay, steps);
  }
  work(kRequestSliceMs);
}

void PlannerSession::run_all() {
  start(Job::Forward, kToEnd);
  work(kRequestSliceMs);
}

void PlannerSession::finish_phase() {
  start(Job::Phase, 0);
  phase_ = shown().phase_label();
  work(kRequestSliceMs);
}

void PlannerSession::reset() {
  cancel_work();
  shown_.planner->reset();
  desired_ = 0;
}

void PlannerSession::start(Job job, long target) {
  if (job != Job::Replay && next_) {
    // A forward job goes on from the new scene's replay where it got to (the planner on screen
    // belongs to the old scene); a step back's replay is simply dropped.
    if (keep_on_cancel_) shown_ = std::move(*next_);
    next_.reset();
  }
  job_ = job;
  target_ = target;
  keep_on_cancel_ = false;
  from_ = worked().steps();
}

long PlannerSession::target() const {
  if (job_ == Job::Forward || job_ == Job::Replay) return target_;
  if (job_ == Job::Phase) return kToEnd;
  return shown().steps();
}

long PlannerSession::wanted_steps() const {
  if (job_ == Job::Forward || job_ == Job::Replay) return target_ == kToEnd ? kMaxSteps : target_;
  return busy() ? worked().steps() : desired_;
}

double PlannerSession::progress() const {
  if (!busy()) return 1.0;
  const Planner& p = worked();
  if ((job_ == Job::Forward || job_ == Job::Replay) && target_ != kToEnd) {
    const double span = static_cast<double>(target_ - from_);
    return span > 0 ? std::clamp(static_cast<double>(p.steps() - from_) / span, 0.0, 1.0) : 1.0;
  }
  // To the end (or a phase's end): the planner's own estimate.
  return p.progress();
}

std::string PlannerSession::busy_text() const {
  switch (job_) {
    case Job::Replay:
      return target_ == kToEnd ? "replaying to the end" : "replaying to step " + std::to_string(target_);
    case Job::Forward:
      return target_ == kToEnd ? "running to the end" : "running to step " + std::to_string(target_);
    case Job::Phase:
      return "finishing the " + phase_ + " phase";
    case Job::None:
      break;
  }
  return "";
}

bool PlannerSession::job_done() const {
  const Planner& p = worked();
  if (p.done()) return true;
  switch (job_) {
    case Job::Forward:
    case Job::Replay:
      return target_ != kToEnd && p.steps() >= target_;
    case Job::Phase:
      return p.phase_label() != phase_;
    case Job::None:
      break;
  }
  return true;
}

void PlannerSession::finish_job() {
  if (next_) {
    shown_ = std::move(*next_);
    next_.reset();
  }
  // A run to the end or to a phase's end asked for wherever it ended; a run to a step (or a
  // replay) for that step, even where the planner ended before it.
  if (job_ == Job::Phase || target_ == kToEnd) desired_ = shown().steps();
  job_ = Job::None;
}

void PlannerSession::work(double ms) {
  if (!busy()) return;
  if (!std::isfinite(ms)) {
    // All of it, at once (the API): the planner's own bulk paths, whose state is the one stepping
    // leaves (Prm::finish_phase()).
    Planner& p = worked();
    if (job_ == Job::Phase) {
      if (p.phase_label() == phase_) p.finish_phase();
    } else if (target_ == kToEnd) {
      p.run();
    } else {
      p.run_to(target_);
    }
    finish_job();
    return;
  }
  // Step by step with a look at the clock every few steps: one step is one unit of the
  // planner's work (a sample, a vertex's neighbours, one edge check, bounded by
  // kMaxEdgeCheckWork), so a slice ends within a few steps of its time, whatever the phase
  // (sampling steps are cheap, connecting steps may be dear).
  // In a dense scene (a configuration past 64 units) a single step may take a while: the clock
  // after every one.
  const int steps_per_look = worked().world().evaluation_cost() > 64.0 ? 1 : 16;
  const double start = now_ms();
  while (!job_done()) {
    if (now_ms() - start >= ms) return;
    Planner& p = worked();
    for (int i = 0; i < steps_per_look && !job_done(); ++i) p.step();
  }
  finish_job();
}

void PlannerSession::cancel_work() {
  if (job_ == Job::None) return;
  if (job_ == Job::Replay && next_) {
    if (keep_on_cancel_) shown_ = std::move(*next_);
    next_.reset();
  }
  // Stopped here: this is where the student is now (a step back's replay left the planner where
  // it was).
  desired_ = shown().steps();
  job_ = Job::None;
}

void PlannerSession::update(LabContext& ctx, const std::string& ready) {
  const int due = ctx.playback.due(static_cast<double>(ImGui::GetIO().DeltaTime));
  for (int i = 0; i < due && !finished() && !busy(); ++i) step_forward();
  if (finished()) ctx.playback.playing = false;
  log_steps(ctx.log, ready);
}

void PlannerSession::log_steps(EventLog& log, const std::string& ready) {
  if (logged_version_ == version()) return;
  const Planner& p = shown();
  const bool same_planner = (logged_version_ >> 32) == (version() >> 32);
  if (!same_planner || logged_steps_ < 0 || p.steps() == 0 || p.steps() < logged_steps_ ||
      p.steps() > logged_steps_ + 1) {
    log.clear();
    log.add(0, p.steps() == 0 ? ready : "at step " + std::to_string(p.steps()) + " (" + p.phase_label() + ")");
  }
  if (p.steps() > 0) {
    std::string line = p.describe(p.last_event(), shown_.scene);
    if (instructor::hidden("path_length")) line = without_lengths(line);
    log.add(p.steps(), line);
  }
  logged_steps_ = p.steps();
  logged_version_ = version();
}

nlohmann::json running_json(const PlannerSession& session) {
  if (!session.busy()) return nullptr;
  const long target = session.target();
  return {{"target", target == PlannerSession::kToEnd ? nlohmann::json(nullptr) : nlohmann::json(target)},
          {"progress", session.progress()},
          {"text", session.busy_text()}};
}

std::string without_lengths(std::string line) {
  const std::string word = "length ";
  for (std::size_t at = line.find(word); at != std::string::npos; at = line.find(word, at + 1)) {
    const std::size_t from = at + word.size();
    const std::size_t to = line.find_first_not_of("0123456789.e-+", from);
    if (to == from) continue;  // "length" followed by words: no number to hide
    line.replace(from, (to == std::string::npos ? line.size() : to) - from, "hidden");
  }
  return line;
}

std::string replaying_text(const PlannerSession& session) {
  return "the roadmap from before: " + session.busy_text() + ", " +
         std::to_string(static_cast<int>(100.0 * session.progress())) + "% (Esc cancels)";
}

}  // namespace csl::app
