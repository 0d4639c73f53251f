#pragma once
// The base of the lessons that run PRM through a PlannerSession (Step PRM, the torus): the
// stepping and long-work calls of Lesson, answered by the session, written once.
#include "app/lesson.hpp"
#include "app/planner_session.hpp"

namespace csl::app {

class PlannerLesson : public Lesson {
 public:
  bool steppable() const override { return true; }
  long steps() const override { return planner().prm().steps(); }
  bool finished() const override { return planner().prm().done(); }
  void step_forward() override { planner().step_forward(); }
  void step_back() override {
    if (planner().wanted_steps() > 0) planner().step_back();
  }
  void finish_phase() override { planner().finish_phase(); }
  void run_all() override { planner().run_to_end(); }
  void reset() override { planner().reset(); }
  void run_to(long steps) override { planner().go_to(steps); }
  bool busy() const override { return planner().busy(); }
  void work(double ms) override { planner().work(ms); }
  void cancel_work() override { planner().cancel(); }
  double progress() const override { return planner().progress(); }
  std::string busy_text() const override { return planner().job_text(); }
  long wanted_steps() const override { return planner().wanted_steps(); }

 protected:
  /// The lesson's session (a member of the derived lesson, built after its scene).
  virtual PlannerSession& planner() = 0;
  virtual const PlannerSession& planner() const = 0;
};

}  // namespace csl::app
