// The planner interface (core/planning/planner.hpp) as the app, the CLI and experiments use it: PRM
// driven only through Planner&, its state JSON (one description for the lab and the CLI), and
// an experiment that takes its planner from a factory.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/planning/planner_json.hpp"
#include "core/planning/prm.hpp"
#include "core/scene/scene.hpp"
#include "core/teaching/experiment.hpp"

namespace {
csl::CollisionWorld wall_with_gap() {
  return csl::CollisionWorld(csl::PointRobot{},
                             {csl::Wall{{0.5, 0.0}, {0.5, 0.4}}, csl::Wall{{0.5, 0.6}, {0.5, 1.0}}}, {0, 0}, {1, 1});
}
csl::PrmParams prm_params(int n, std::uint64_t seed) {
  csl::PrmParams p;
  p.samples = n;
  p.neighbors = csl::NeighborRule::parse("k:8");
  p.seed = seed;
  return p;
}
// The straight line between them crosses the wall: no path without samples.
const csl::Config kStart = csl::config({0.1, 0.2}), kGoal = csl::config({0.9, 0.2});
}  // namespace

TEST_CASE("a planner made by its factory steps, replays and finishes phases through the interface alone") {
  const csl::CollisionWorld world = wall_with_gap();
  const csl::PlannerFactory make = csl::prm_factory(prm_params(120, 5));
  const std::unique_ptr<csl::Planner> stepped = make(world, kStart, kGoal);
  const std::unique_ptr<csl::Planner> jumped = make(world, kStart, kGoal);
  CHECK(std::string(stepped->name()) == "prm");
  CHECK(stepped->steps() == 0);
  CHECK(stepped->progress() == 0.0);
  // Step by step, each event numbered; the same state as run_to() there, at a few stops.
  std::vector<std::string> phases;
  double last_progress = 0.0;
  while (!stepped->done()) {
    const csl::PlannerEvent& e = stepped->step();
    CHECK(e.step == stepped->steps());
    CHECK(!stepped->describe(e, csl::Scene{}).empty());
    CHECK(stepped->progress() >= last_progress);  // a progress bar never goes back
    last_progress = stepped->progress();
    if (phases.empty() || phases.back() != stepped->phase_label()) phases.push_back(stepped->phase_label());
    if (stepped->steps() % 97 == 0) {
      jumped->run_to(stepped->steps());
      CHECK(csl::roadmap_hash(jumped->roadmap()) == csl::roadmap_hash(stepped->roadmap()));
      CHECK(jumped->edge_checks() == stepped->edge_checks());
      jumped->run_to(1);  // back: a replay from the start
      CHECK(jumped->steps() == 1);
      CHECK(jumped->roadmap().vertices.size() == 1);
    }
  }
  CHECK(stepped->progress() == 1.0);
  CHECK(phases == std::vector<std::string>{"endpoints", "sampling", "connecting", "query", "done"});
  REQUIRE(stepped->solved());  // 120 samples through a gap of 0.2 with this seed
  // finish_phase() phase by phase reaches the same state, and the last event stepping left.
  const std::unique_ptr<csl::Planner> phased = make(world, kStart, kGoal);
  while (!phased->done()) phased->finish_phase();
  CHECK(phased->steps() == stepped->steps());
  CHECK(csl::roadmap_hash(phased->roadmap()) == csl::roadmap_hash(stepped->roadmap()));
  CHECK(phased->last_event().kind == stepped->last_event().kind);
  CHECK(phased->path_length() == stepped->path_length());
  CHECK(phased->replay_work() == static_cast<long>(phased->samples_drawn()) + phased->edge_checks());
}

TEST_CASE("components counted from the live edges are the ones PRM keeps as it connects") {
  // Planner::component_labels() (any planner's, from its roadmap) against Prm's own union-find,
  // at every step of a run whose path re-check removes edges (grid:3 lets edges through the
  // wall; the exact re-check takes them out).
  const csl::CollisionWorld world = wall_with_gap();
  csl::PrmParams p = prm_params(60, 9);
  p.checker = csl::EdgeCheckerSpec::parse("grid:3");
  csl::Prm prm(world, kStart, kGoal, p);
  const csl::Planner& planner = prm;
  int checked = 0;
  bool removed = false;
  while (!prm.done()) {
    const bool removal = prm.step().kind == csl::PlannerEvent::Kind::PathEdgeRemoved;
    removed = removed || removal;
    const std::vector<int> mine = prm.component_labels();
    REQUIRE(mine == planner.Planner::component_labels());
    // Dense and ordered by smallest vertex: vertex 0 is in component 0, and each new label is
    // the next number.
    int next = 0;
    for (int label : mine) {
      REQUIRE(label <= next);
      if (label == next) ++next;
    }
    CHECK(next == prm.components());
    ++checked;
  }
  CHECK(checked == prm.steps());
  CHECK(removed);
}

TEST_CASE("the state JSON says what the planner holds, from its own parts") {
  const csl::CollisionWorld world = wall_with_gap();
  csl::Prm prm(world, kStart, kGoal, prm_params(80, 3));
  const csl::Planner& planner = prm;
  nlohmann::json s = csl::planner_state_json(planner, false);
  CHECK(s["steps"] == 0);
  CHECK(s["last_event"].is_null());
  CHECK(s["path_length"].is_null());
  CHECK(s["phase"] == "endpoints");
  CHECK(!s.contains("vertices"));
  prm.run();
  s = csl::planner_state_json(planner, true);
  CHECK(s["done"] == true);
  CHECK(s["phase"] == "done");
  CHECK(s["steps"] == prm.steps());
  CHECK(s["nodes"] == prm.roadmap().vertices.size());
  CHECK(s["samples_drawn"] == 80);
  CHECK(s["edge_checks"] == prm.edge_checks());
  CHECK(s["evaluations"] == prm.evaluations());
  CHECK(s["components"] == prm.components());
  CHECK(s["roadmap_hash"] == csl::roadmap_hash_text(prm.roadmap()));
  CHECK(s["last_event"] == (prm.solved() ? "path_found" : "no_path"));
  // The edge list is E's live edges; the path runs from the start to the goal along them.
  long alive = 0;
  for (const csl::RoadmapEdge& e : prm.roadmap().edges) alive += e.alive;
  CHECK(s["edges"] == alive);
  CHECK(s["edge_list"].size() == static_cast<std::size_t>(alive));
  CHECK(s["vertices"].size() == prm.roadmap().vertices.size());
  REQUIRE(prm.solved());
  const nlohmann::json& path = s["path"];
  REQUIRE(path.size() == prm.path().size());
  CHECK(path.front() == nlohmann::json::array({0.1, 0.2}));
  CHECK(path.back() == nlohmann::json::array({0.9, 0.2}));
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double dx = path[i + 1][0].get<double>() - path[i][0].get<double>();
    const double dy = path[i + 1][1].get<double>() - path[i][1].get<double>();
    length += std::sqrt(dx * dx + dy * dy);
  }
  CHECK(s["path_length"].get<double>() == doctest::Approx(length).epsilon(1e-12));
}

TEST_CASE("an experiment runs the planner its factory makes, with each trial's samples and seed") {
  const csl::CollisionWorld world = wall_with_gap();
  csl::ExperimentParams p;
  p.sample_counts = {10, 40};
  p.trials = 6;
  p.seed = 2;
  p.neighbors = csl::NeighborRule::parse("k:8");
  p.volume_samples = 2000;
  csl::Experiment prm_default(world, kStart, kGoal, p);
  prm_default.run();

  // The same PRM through the factory: the same failures; and the factory was asked once per
  // trial, with the row's n.
  std::vector<int> asked;
  p.planner = [&](int samples, std::uint64_t seed) {
    asked.push_back(samples);
    return csl::prm_factory(prm_params(samples, seed));
  };
  csl::Experiment through_factory(world, kStart, kGoal, p);
  through_factory.run();
  CHECK(asked == std::vector<int>{10, 10, 10, 10, 10, 10, 40, 40, 40, 40, 40, 40});
  for (std::size_t i = 0; i < 2; ++i)
    CHECK(through_factory.rows()[i].failures == prm_default.rows()[i].failures);

  // A planner that never finds a path fails every trial: the rows are the factory's planner's.
  p.planner = [](int, std::uint64_t seed) { return csl::prm_factory(prm_params(0, seed)); };
  csl::Experiment never(world, kStart, kGoal, p);
  never.run();
  for (const csl::ExperimentRow& row : never.rows()) CHECK(row.failures == row.trials);
}
