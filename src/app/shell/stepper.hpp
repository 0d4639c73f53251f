#pragma once
// What the shared playback controls (Back, Step, Finish phase, Run all, Play, Reset, the
// progress bar and Cancel), the keys and the JS API's stepping calls drive: a lesson's
// algorithm, stepped. A lesson that runs one hands out its stepper (Lesson::stepper()); the
// planner lessons hand out their PlannerSession, so no lesson forwards these calls one by one.
#include <string>

namespace csl::app {

class Stepper {
 public:
  virtual ~Stepper() = default;
  /// Whether the panel shows the playback controls for it (the analysis lesson's experiment is
  /// run by the API's "run" and its own button, not stepped).
  virtual bool shows_controls() const { return true; }
  virtual long steps() const = 0;
  virtual bool finished() const = 0;
  virtual void step_forward() = 0;
  virtual void step_back() = 0;
  virtual void finish_phase() = 0;
  virtual void run_all() = 0;
  virtual void reset() = 0;
  virtual void run_to(long steps) = 0;

  /// Long work (a run to the end, a replay after an edit) goes on over several frames, so that
  /// no frame waits for it: work() advances it for about `ms` milliseconds, once a frame (an
  /// infinite `ms`: to its end, as the API does unless asked not to).
  virtual bool busy() const { return false; }
  virtual void work(double /*ms*/) {}
  virtual void cancel_work() {}
  /// How far the work is, in [0, 1], and what it is ("replaying to step 1200").
  virtual double progress() const { return 1.0; }
  virtual std::string busy_text() const { return ""; }
  /// The step a snapshot holds: where running work heads, else steps().
  virtual long wanted_steps() const { return steps(); }
};

/// A stepper with nothing to step: at step 0 and done, no controls. The app answers for a
/// lesson without a stepper with one; the analysis lesson is one whose run_all() (the API's
/// "run") finishes its experiment.
class NoSteps : public Stepper {
 public:
  bool shows_controls() const override { return false; }
  long steps() const override { return 0; }
  bool finished() const override { return true; }
  void step_forward() override {}
  void step_back() override {}
  void finish_phase() override {}
  void run_all() override {}
  void reset() override {}
  void run_to(long) override {}
};

}  // namespace csl::app
