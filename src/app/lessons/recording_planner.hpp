#pragma once
// A planner that watches another one step by step (the Compare planners and Step PRM lessons): it keeps the
// samples the planner rejected, which no planner stores (its roadmap holds only the free ones),
// and the wall-clock time its steps took, for the lesson's table only (never a test's figure).
// Everything else is the wrapped planner's: the state after k steps is the same, since
// finish_phase() is done by stepping (the contract: the state stepping leaves).
#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/planning/planner.hpp"

namespace csl::app {

class RecordingPlanner final : public Planner {
 public:
  explicit RecordingPlanner(std::unique_ptr<Planner> inner) : inner_(std::move(inner)) {}

  /// The rejected samples so far (every step's SampleRejected q), in order.
  const std::vector<Config>& rejected() const { return rejected_; }
  /// Milliseconds spent in step() since the start (a replay measures again).
  double milliseconds() const { return ms_; }

  const char* name() const override { return inner_->name(); }
  const PlannerEvent& step() override {
    const auto t0 = std::chrono::steady_clock::now();
    const PlannerEvent& e = inner_->step();
    ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (e.kind == PlannerEvent::Kind::SampleRejected) rejected_.push_back(e.q);
    return e;
  }
  void finish_phase() override {
    // Step by step through a phase that draws samples (any may be one to keep); a phase whose
    // first steps draw none (PRM's connecting: up to 10^6 edge checks) goes to the planner's own
    // bulk path, which leaves the same state and builds no event per step.
    const std::string phase = inner_->phase_label();
    bool samples = false;
    for (int i = 0; (samples || i < kLookSteps) && !inner_->done() && phase == inner_->phase_label(); ++i) {
      const PlannerEvent::Kind k = step().kind;
      samples |= k == PlannerEvent::Kind::SampleAccepted || k == PlannerEvent::Kind::SampleRejected;
    }
    if (inner_->done() || phase != inner_->phase_label()) return;
    const auto t0 = std::chrono::steady_clock::now();
    inner_->finish_phase();
    ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  void reset() override {
    inner_->reset();
    rejected_.clear();
    ms_ = 0.0;
  }
  bool done() const override { return inner_->done(); }
  long steps() const override { return inner_->steps(); }
  const char* phase_label() const override { return inner_->phase_label(); }
  const PlannerEvent& last_event() const override { return inner_->last_event(); }
  double progress() const override { return inner_->progress(); }
  std::string describe(const PlannerEvent& e, const Scene& scene) const override { return inner_->describe(e, scene); }
  const CollisionWorld& world() const override { return inner_->world(); }
  const Roadmap& roadmap() const override { return inner_->roadmap(); }
  long edges_alive() const override { return inner_->edges_alive(); }
  int components() const override { return inner_->components(); }
  std::vector<int> component_labels() const override { return inner_->component_labels(); }
  bool solved() const override { return inner_->solved(); }
  const std::vector<int>& path() const override { return inner_->path(); }
  std::vector<Config> path_configurations() const override { return inner_->path_configurations(); }
  double path_length() const override { return inner_->path_length(); }
  long edge_checks() const override { return inner_->edge_checks(); }
  long evaluations() const override { return inner_->evaluations(); }
  long long configurations_tested() const override { return inner_->configurations_tested(); }
  int samples_drawn() const override { return inner_->samples_drawn(); }
  const std::vector<unsigned char>* checked_edge_flags() const override { return inner_->checked_edge_flags(); }
  long edges_unchecked() const override { return inner_->edges_unchecked(); }

  /// The planner it watches: what only its type draws (PRM's candidate pairs) reaches it here,
  /// through PlannerSession::shown_as().
  const Planner& inner() const { return *inner_; }

 private:
  // finish_phase(): steps without a sample before a phase counts as one that draws none.
  static constexpr int kLookSteps = 64;
  std::unique_ptr<Planner> inner_;
  std::vector<Config> rejected_;
  double ms_ = 0.0;
};

/// Planners of `make`, each wrapped in a RecordingPlanner.
inline PlannerFactory recorded(PlannerFactory make) {
  return [make = std::move(make)](const CollisionWorld& world, const Config& start, const Config& goal) {
    return std::unique_ptr<Planner>(new RecordingPlanner(make(world, start, goal)));
  };
}

}  // namespace csl::app
