// Lesson "Compare planners": two planners of the planner choice (core/planning/planner_choice)
// on the same scene and seed, side by side (one over the other on a portrait screen), stepped
// in sync, with a table of what each cost; a narrow-passage scene whose gap is a slider; and an
// experiment that runs each planner on many seeds at several sample budgets and plots the
// share of runs that found a path.
//
// The planners are listed from planner_kinds(): a planner added to that table appears here by
// itself. Each side is a PlannerSession (replay, long work in slices), whose planner is wrapped
// in a RecordingPlanner for the rejected samples and the time. The lesson is its own Stepper:
// each request goes to both sessions, so Step, Back, Play, Run and the API's step, step_back,
// run_to and state work as in Step PRM; a step back is each planner's replay to one step
// fewer (a planner that ended sooner stays at its end).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "app/lessons/planner_session.hpp"
#include "app/lessons/prm_controls.hpp"
#include "app/lessons/recording_planner.hpp"
#include "app/lessons/sampler_controls.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/lesson.hpp"
#include "app/shell/panel.hpp"
#include "app/shell/param_widgets.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/views/drag_replay.hpp"
#include "app/views/draw.hpp"
#include "app/views/plot.hpp"
#include "app/views/split.hpp"
#include "core/base/text.hpp"
#include "core/checking/scene_text.hpp"
#include "core/planning/planner_choice.hpp"
#include "core/planning/planner_json.hpp"
#include "core/planning/planner_text.hpp"
#include "core/scene/narrow_passage.hpp"
#include "core/teaching/experiment.hpp"
#include "core/teaching/work.hpp"
#include "imgui.h"

namespace csl::app {
namespace {

using json = nlohmann::json;

// Each side's own parameters under its own key (a link sets them one by one).
constexpr ParamSpec kSamplesA = kLabPrmSamples.named("samples_a");
constexpr ParamSpec kSamplesB = kLabPrmSamples.named("samples_b");
constexpr ParamSpec kGoalBiasA = kGoalBias.named("goal_bias_a");
constexpr ParamSpec kGoalBiasB = kGoalBias.named("goal_bias_b");
constexpr ParamSpec kStepA = kTreeStep.named("step_a");
constexpr ParamSpec kStepB = kTreeStep.named("step_b");
// The experiment: runs per budget (a trial is a whole run of a planner, up to the lab's sample
// budget: 100 runs x 6 budgets x 2 planners stays within minutes in the slowest browser).
constexpr ParamSpec kCompareTrials = kLabExperimentTrials.in_lab(1, 100, 10);
constexpr std::size_t kMaxBudgets = 6;
// The most samples an experiment draws for one planner (runs x the budgets' sum): PRM's
// 400000 in 2000-sample runs take about a minute in a browser; the API runs an experiment in one
// call unless asked {background: true}, so a bound keeps a link from holding the page for long.
constexpr long kMaxExperimentSamples = 400000;

std::string experiment_problem(const std::vector<int>& budgets, int trials) {
  long total = 0;
  for (int n : budgets) total += static_cast<long>(n) * trials;
  if (total <= kMaxExperimentSamples) return "";
  return "the experiment would draw " + std::to_string(total) + " samples for each planner (runs x budgets); at most " +
         std::to_string(kMaxExperimentSamples) + " in the lab";
}
// The experiment's reference run (Experiment measures L and r for the analysis lesson's bound;
// this lesson plots success rates only): as small as it takes.
constexpr int kReferenceSamples = 50;
constexpr long kVolumeSamples = 100;

const char* const kSideNames[2] = {"A", "B"};
const char* const kSideKeys[2] = {"a", "b"};

std::vector<std::string> planner_choices() {
  std::vector<std::string> out;
  for (const PlannerKindInfo& k : planner_kinds()) out.emplace_back(k.name);
  return out;
}

class CompareLesson : public Lesson, private Stepper {
 public:
  CompareLesson() : scene_(narrow_passage_scene(passage_)) {
    sides_[0].choice.kind = PlannerChoice::Kind::Prm;
    sides_[1].choice.kind = PlannerChoice::Kind::RrtConnect;
    for (Side& s : sides_) {
      s.choice.samples = 300;
      s.choice.seed = seed_;
      s.session = std::make_unique<PlannerSession>(scene_, recorded(make_planner_factory(s.choice)));
    }
  }

  void on_show() override { forget_log(); }

  void update(LabContext& ctx) override {
    // Play: one step of each a tick, as Step PRM's session does.
    const int due = ctx.playback.due(static_cast<double>(ImGui::GetIO().DeltaTime));
    for (int i = 0; i < due && !finished() && !busy(); ++i) step_forward();
    if (finished()) ctx.playback.playing = false;
    if (experiment_done_now_) {
      experiment_done_now_ = false;
      ctx.log.add(0, "experiment finished: " + std::to_string(trials_) + " runs per budget and planner");
    }
    log_steps(ctx.log);
  }

  void panel(LabContext& ctx) override {
    ImGui::TextWrapped("Two planners on the same scene with the same seed. Step them together, run them to the end, "
                       "and compare what each drew and checked; the experiment runs each many times.");
    ImGui::Spacing();
    int mode = mode_;
    {
      instructor::FixedParam fixed("mode");
      if (ImGui::RadioButton("Step", &mode, kStepMode)) mode_ = kStepMode;
      ui::flow(ui::toggle_width("Experiment"));
      if (ImGui::RadioButton("Experiment", &mode, kExperimentMode)) mode_ = kExperimentMode;
    }
    {
      instructor::FixedParam fixed("passage", true);
      double w = passage_;
      if (param_slider(kPassageWidth, "passage w", w, kPassageWidth.min, kPassageWidth.max, "%.3f") && w != passage_) {
        passage_ = w;
        scene_ = narrow_passage_scene(passage_);
        rebuild_all(0);
      }
    }
    {
      instructor::FixedParam fixed("seed");
      std::uint64_t seed = seed_;
      if (param_input(kSeed, "seed", seed) && seed != seed_) {
        seed_ = seed;
        rebuild_all(0);
      }
    }
    for (int i = 0; i < 2; ++i) {
      ImGui::PushID(i);
      const std::string title = std::string("Planner ") + kSideNames[i];
      if (panel::fold(title.c_str())) side_controls(i, ctx);
      ImGui::PopID();
    }
    ImGui::Separator();
    if (mode_ == kExperimentMode) experiment_panel(ctx);
    // The table's and the plot's collision checks are one measure for every planner
    // (Planner::configurations_tested(), the CLI's configurations_tested): say what is in it, so
    // that a bridge sampler's 3 tests per draw are not a riddle.
    {
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("Collision checks: every configuration given to the collision checker, counted alike for "
                         "each planner: samples (a bridge or Gaussian draw tests 1 to 3), the edge checks' points, "
                         "the ends' clearances and the path's re-check.");
      ImGui::PopStyleColor();
    }
  }

  void views(LabContext& ctx, ImVec2 size) override {
    if (mode_ == kExperimentMode) {
      experiment_plot(size);
      ctx.plots["success"] = &plot_;
      return;
    }
    // The table under the two views: a header and a row per planner.
    const float table_h = 3.0f * ImGui::GetFrameHeightWithSpacing() + 2.0f * ImGui::GetStyle().ItemSpacing.y;
    const ImVec2 area(size.x, std::max(80.0f, size.y - table_h - ImGui::GetStyle().ItemSpacing.y));
    const Split s = split(area);
    draw_side(0, ctx, s.first);
    between(s);
    draw_side(1, ctx, s.second);
    table(size.x, table_h);
  }

  Scene* scene() override { return &scene_; }
  bool accept_scene(const Scene& s, std::string& why) override {
    if (!std::holds_alternative<PointRobot>(s.robot)) {
      why = "this lesson compares planners for a point robot; the scene has a '" +
            std::string(robot_type_name(s.robot)) + "' robot";
      return false;
    }
    for (const Side& side : sides_)
      if (!(why = budget_problem(side.choice, s)).empty()) return false;
    scene_ = s;
    rebuild_all(0);
    return true;
  }

  json state(const json& args) const override {
    json planners = json::array();
    for (int i = 0; i < 2; ++i) {
      const Planner& p = shown(i);
      json one = planner_state_json(p, args.value("roadmap", false));
      one["side"] = kSideKeys[i];
      one["name"] = p.name();
      one["planner"] = planner_kind_info(sides_[i].choice.kind).name;
      if (!planner_kind_info(sides_[i].choice.kind).tree) one["sampler"] = sides_[i].choice.sampler.name();
      one["samples"] = p.samples_drawn();
      one["rejected"] = recording(i).rejected().size();
      one["start"] = config_to_json(sides_[i].session->planned_scene().start);
      one["goal"] = config_to_json(sides_[i].session->planned_scene().goal);
      one["running"] = running_json(*sides_[i].session);
      planners.push_back(std::move(one));
    }
    json out{{"steps", steps()},
             {"done", finished()},
             {"planners", planners},
             {"mode", mode_name(mode_)},
             {"params", params()},
             {"experiment", experiment_json()}};
    return out;
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    // Checked in full before anything changes.
    std::array<PlannerChoice, 2> choice = {sides_[0].choice, sides_[1].choice};
    double passage = passage_;
    std::uint64_t seed = seed_;
    int mode = mode_, trials = trials_, axis = axis_;
    std::vector<int> budgets = budgets_;
    bool run = false, cancel = false;
    std::array<bool, 2> sampler_given = {false, false};
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& k = it.key();
      const json& v = *it;
      const int side = k.size() > 2 && k[k.size() - 2] == '_' && (k.back() == 'a' || k.back() == 'b') ? (k.back() == 'b')
                                                                                                      : -1;
      const std::string base = side >= 0 ? k.substr(0, k.size() - 2) : k;
      if (side >= 0 && base == "planner") {
        if (!v.is_string()) throw ApiError(k + ": one of " + planner_names(", "));
        try {
          choice[static_cast<std::size_t>(side)].kind = parse_planner_kind(v.get<std::string>());
        } catch (const std::invalid_argument& e) {
          throw ApiError(k + ": " + e.what());
        }
      } else if (side >= 0 && base == "sampler") {
        choice[static_cast<std::size_t>(side)].sampler = sampler_from_json(k, v);
        sampler_given[static_cast<std::size_t>(side)] = true;
      } else if (side >= 0 && base == "samples") {
        choice[static_cast<std::size_t>(side)].samples = static_cast<int>(api_param(side ? kSamplesB : kSamplesA, v));
      } else if (side >= 0 && base == "goal_bias") {
        choice[static_cast<std::size_t>(side)].goal_bias = api_param(side ? kGoalBiasB : kGoalBiasA, v);
      } else if (side >= 0 && base == "step") {
        choice[static_cast<std::size_t>(side)].step = api_param(side ? kStepB : kStepA, v);
      } else if (k == "seed") {
        seed = static_cast<std::uint64_t>(api_param(kSeed, v));
      } else if (k == "passage") {
        passage = api_param(kPassageWidth, v);
      } else if (k == "mode") {
        if (v != "step" && v != "experiment") throw ApiError("mode: \"step\" or \"experiment\"");
        mode = v == "step" ? kStepMode : kExperimentMode;
      } else if (k == "axis") {
        if (v != "samples" && v != "checks") throw ApiError("axis: \"samples\" or \"checks\"");
        axis = v == "samples" ? kSamplesAxis : kChecksAxis;
      } else if (k == "trials") {
        trials = static_cast<int>(api_param(kCompareTrials, v));
      } else if (k == "budgets") {
        if (!v.is_array() || v.empty() || v.size() > kMaxBudgets)
          throw ApiError("budgets: 1 to " + std::to_string(kMaxBudgets) + " sample counts, each " +
                         range_text(kLabExperimentSamples));
        budgets.clear();
        for (const json& n : v) budgets.push_back(static_cast<int>(api_param(kLabExperimentSamples, n)));
      } else if (k == "run") {
        run = v.is_boolean() && v.get<bool>();
      } else if (k == "cancel") {
        cancel = v.is_boolean() && v.get<bool>();
      } else {
        throw ApiError("unknown parameter \"" + printable(k, 40) + "\"");
      }
    }
    if (run)
      if (const std::string problem = experiment_problem(budgets, trials); !problem.empty()) throw ApiError(problem);
    // The passage rebuilds the scene only while the scene is the passage's: a scene of the
    // student's (edited, imported, or restored before its parameters: a link, a snapshot) stays,
    // and the passage is then the slider's value alone. The slider itself replaces any scene.
    const bool passage_scene = same_content(scene_, narrow_passage_scene(passage_));
    const Scene scene = passage != passage_ && passage_scene ? narrow_passage_scene(passage) : scene_;
    for (std::size_t i = 0; i < 2; ++i) {
      PlannerChoice& c = choice[i];
      // A tree planner samples uniformly: a side switched to one leaves its PRM sampler behind
      // (one named in the same call is still refused, by validate()).
      if (planner_kind_info(c.kind).tree && !sampler_given[i]) c.sampler = SamplerSpec{};
      c.seed = seed;
      try {
        validate(c);
      } catch (const std::invalid_argument& e) {
        throw ApiError(e.what());
      }
      if (const std::string problem = budget_problem(c, scene); !problem.empty()) throw ApiError(problem);
    }
    const bool changed = passage != passage_ || seed != seed_ || !same_choice(choice[0], sides_[0].choice) ||
                         !same_choice(choice[1], sides_[1].choice);
    sides_[0].choice = choice[0];
    sides_[1].choice = choice[1];
    passage_ = passage;
    scene_ = scene;
    seed_ = seed;
    mode_ = mode;
    axis_ = axis;
    trials_ = trials;
    budgets_ = budgets;
    if (changed) rebuild_all(0);
    if (cancel) drop_experiment();
    if (run) start_experiment();
  }

  json params() const override {
    json out{{"passage", passage_}, {"seed", seed_},        {"mode", mode_name(mode_)},
             {"axis", axis_name(axis_)}, {"trials", trials_}, {"budgets", budgets_}};
    for (int i = 0; i < 2; ++i) {
      const PlannerChoice& c = sides_[i].choice;
      const std::string key = kSideKeys[i];
      out["planner_" + key] = planner_kind_info(c.kind).name;
      out["samples_" + key] = c.samples;
      out["goal_bias_" + key] = c.goal_bias;
      out["step_" + key] = c.step;
      out["sampler_" + key] = c.sampler.name();
    }
    return out;
  }
  std::vector<std::string> scene_params() const override { return {"passage"}; }

  std::vector<ParamField> param_fields() const override {
    return {{"planner_a", "planner A", nullptr, planner_choices()},
            {"samples_a", "samples A", &kSamplesA},
            {"goal_bias_a", "goal bias A", &kGoalBiasA},
            {"step_a", "step A", &kStepA},
            sampler_field("sampler_a", "sampler A"),
            {"planner_b", "planner B", nullptr, planner_choices()},
            {"samples_b", "samples B", &kSamplesB},
            {"goal_bias_b", "goal bias B", &kGoalBiasB},
            {"step_b", "step B", &kStepB},
            sampler_field("sampler_b", "sampler B"),
            {"seed", "seed", &kSeed},
            {"passage", "passage width", &kPassageWidth},
            {"mode", "mode", nullptr, {"step", "experiment"}},
            {"axis", "plot against", nullptr, {"samples", "checks"}},
            {"trials", "runs per budget", &kCompareTrials},
            {"budgets", "sample budgets", &kLabExperimentSamples}};
  }

  std::string describe() const override {
    std::string out = describe_scene(scene_, sides_[0].session->world());
    for (int i = 0; i < 2; ++i)
      out += std::string(" Planner ") + kSideNames[i] + ", " + planner_kind_info(sides_[i].choice.kind).name + ": " +
             describe_planner(shown(i), !instructor::hidden("path_length"));
    if (const Experiment* e = sides_[0].experiment.get()) {
      out += e->done() && sides_[1].experiment->done() ? " The experiment's success rates:" : " The experiment so far:";
      for (int i = 0; i < 2; ++i) {
        out += std::string(" ") + planner_kind_info(sides_[i].choice.kind).name;
        for (const ExperimentRow& r : sides_[i].experiment->rows())
          if (r.trials > 0)
            out += ", " + std::to_string(r.samples) + " samples: " + std::to_string(r.trials - r.failures) + " of " +
                   std::to_string(r.trials);
        out += ";";
      }
    }
    return out;
  }

  Stepper* stepper() override { return this; }

 private:
  enum Mode { kStepMode = 0, kExperimentMode = 1 };
  static const char* mode_name(int m) { return m == kExperimentMode ? "experiment" : "step"; }
  // The experiment plot's x axis: the sample budget, or the collision checks the runs made (their
  // mean per run at each budget: Planner::configurations_tested()).
  enum Axis { kSamplesAxis = 0, kChecksAxis = 1 };
  static const char* axis_name(int a) { return a == kChecksAxis ? "checks" : "samples"; }

  struct Side {
    PlannerChoice choice;
    std::unique_ptr<PlannerSession> session;
    WorkspaceView view;
    RoadmapLayer layer;
    RedrawThrottle throttle;
    std::vector<int> labels;
    long long labels_at = -1;
    long long logged_version = -1;
    std::unique_ptr<Experiment> experiment;
  };

  static bool same_choice(const PlannerChoice& a, const PlannerChoice& b) {
    return a.kind == b.kind && a.samples == b.samples && a.goal_bias == b.goal_bias && a.step == b.step &&
           a.seed == b.seed && a.sampler.kind == b.sampler.kind && a.sampler.sigma == b.sampler.sigma &&
           a.sampler.uniform_share == b.sampler.uniform_share;
  }

  // What PRM's budgets say of `c` in `scene` (the tree planners check one edge a sample: their
  // samples' budget is the bound), or "".
  static std::string budget_problem(const PlannerChoice& c, const Scene& scene) {
    if (planner_kind_info(c.kind).tree) {
      // A short D makes each extension cheap but RRT-Connect's connects long: priced per sample.
      const CollisionWorld world(scene);
      const double work = expected_tree_work(world, c).total();
      if (work <= kLabMaxWork) return "";
      char text[300];
      std::snprintf(text, sizeof text,
                    "%s with %d samples and step %g means about %s of work, more than the lab's %s: take fewer "
                    "samples or a longer step",
                    planner_kind_info(c.kind).name, c.samples, tree_step(world.space(), c.step),
                    work_text(work).c_str(), work_text(kLabMaxWork).c_str());
      return text;
    }
    PrmParams p;
    p.samples = c.samples;
    p.neighbors = c.kind == PlannerChoice::Kind::PrmStar ? NeighborRule::parse("prm*") : c.neighbors;
    p.checker = c.checker;
    p.seed = c.seed;
    p.sampler = c.sampler;  // a bridge draw tests up to three configurations
    return scene_budget_problem(p, scene);
  }

  const Planner& shown(int i) const { return sides_[static_cast<std::size_t>(i)].session->shown(); }
  const RecordingPlanner& recording(int i) const { return dynamic_cast<const RecordingPlanner&>(shown(i)); }
  PlannerSession& session(int i) { return *sides_[static_cast<std::size_t>(i)].session; }
  const PlannerSession& session(int i) const { return *sides_[static_cast<std::size_t>(i)].session; }

  void rebuild_all(long steps) {
    for (Side& s : sides_) {
      s.choice.seed = seed_;
      s.session->rebuild(scene_, recorded(make_planner_factory(s.choice)), steps);
      s.labels_at = -1;
    }
    forget_log();
    // The experiment belonged to the old scene or planners.
    drop_experiment();
  }

  // ---- Stepper: every request to both sessions.
  long steps() const override { return std::max(session(0).steps(), session(1).steps()); }
  bool finished() const override { return session(0).finished() && session(1).finished(); }
  void step_forward() override {
    for (int i = 0; i < 2; ++i) {
      // (A planner at its end stays there; cancel its work all the same, as a step does.)
      if (session(i).finished()) session(i).cancel_work();
      else session(i).step_forward();
    }
  }
  void step_back() override {
    const long at = wanted_steps();
    if (at > 0) run_to(at - 1);
  }
  void finish_phase() override {
    for (int i = 0; i < 2; ++i) session(i).finish_phase();
  }
  void run_all() override {
    for (int i = 0; i < 2; ++i) session(i).run_all();
  }
  void reset() override {
    for (int i = 0; i < 2; ++i) session(i).reset();
  }
  void run_to(long steps) override {
    for (int i = 0; i < 2; ++i) session(i).run_to(steps);
  }
  bool busy() const override { return experiment_running() || session(0).busy() || session(1).busy(); }
  void work(double ms) override {
    if (experiment_running()) return work_experiment(ms);
    const bool both = session(0).busy() && session(1).busy();
    for (int i = 0; i < 2; ++i)
      if (session(i).busy()) session(i).work(both ? 0.5 * ms : ms);
  }
  void cancel_work() override {
    if (experiment_running()) drop_experiment();
    for (int i = 0; i < 2; ++i) session(i).cancel_work();
  }
  double progress() const override {
    if (experiment_running())
      return 0.5 * (sides_[0].experiment->progress() + sides_[1].experiment->progress());
    double sum = 0;
    int n = 0;
    for (int i = 0; i < 2; ++i)
      if (session(i).busy()) sum += session(i).progress(), ++n;
    return n ? sum / n : 1.0;
  }
  std::string busy_text() const override {
    if (experiment_running()) return "experiment: " + std::to_string(trials_) + " runs per budget and planner";
    std::string out;
    for (int i = 0; i < 2; ++i)
      if (session(i).busy()) out += (out.empty() ? "" : "; ") + std::string(kSideNames[i]) + ": " + session(i).busy_text();
    return out;
  }
  long wanted_steps() const override { return std::max(session(0).wanted_steps(), session(1).wanted_steps()); }

  // ---- the experiment: one Experiment per planner on the scene's world, run a trial at a time
  bool experiment_running() const {
    return sides_[0].experiment && !(sides_[0].experiment->done() && sides_[1].experiment->done());
  }
  void start_experiment() {
    drop_experiment();
    experiment_world_ = std::make_shared<const CollisionWorld>(scene_);
    for (Side& s : sides_) {
      ExperimentParams p;
      p.sample_counts = budgets_;
      p.trials = trials_;
      p.seed = seed_;
      p.reference_samples = kReferenceSamples;
      p.volume_samples = kVolumeSamples;
      const PlannerChoice choice = s.choice;
      p.planner = [choice](int samples, std::uint64_t seed) {
        PlannerChoice c = choice;
        c.samples = samples;
        c.seed = seed;
        return make_planner_factory(c);
      };
      s.experiment = std::make_unique<Experiment>(*experiment_world_, scene_.start, scene_.goal, p);
    }
  }
  void drop_experiment() {
    for (Side& s : sides_) s.experiment.reset();
  }
  void work_experiment(double ms) {
    // A trial of each planner in turn, until the time is up (an infinite ms: to the end).
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
      return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    while (experiment_running() && (!std::isfinite(ms) || elapsed() < ms))
      for (Side& s : sides_) s.experiment->step();
    if (!experiment_running()) experiment_done_now_ = true;
  }
  json experiment_json() const {
    if (!sides_[0].experiment) return nullptr;
    json planners = json::array();
    for (const Side& s : sides_) {
      json rates = json::array();
      for (const ExperimentRow& r : s.experiment->rows())
        rates.push_back({{"samples", r.samples},
                         {"trials", r.trials},
                         {"successes", r.trials - r.failures},
                         {"configurations_tested", r.trials > 0 ? json(static_cast<double>(r.configurations_tested) / r.trials)
                                                                : json(nullptr)},
                         {"success_rate", r.trials > 0 ? json(1.0 - r.failure_rate.estimate) : json(nullptr)}});
      planners.push_back({{"planner", planner_kind_info(s.choice.kind).name}, {"rates", rates}});
    }
    return {{"done", !experiment_running()},
            {"progress", 0.5 * (sides_[0].experiment->progress() + sides_[1].experiment->progress())},
            {"trials", trials_},
            {"planners", planners}};
  }

  // ---- the log: each step of each planner, in words
  void forget_log() {
    for (Side& s : sides_) s.logged_version = -1;
  }
  void log_steps(EventLog& log) {
    bool same = true, jump = false;
    for (int i = 0; i < 2; ++i) {
      const Side& s = sides_[static_cast<std::size_t>(i)];
      const long long v = s.session->version();
      if (v == s.logged_version) continue;
      same = false;
      // Another planner, a step back or a jump of more than one step: start again.
      if (s.logged_version < 0 || (v >> 32) != (s.logged_version >> 32) || v != s.logged_version + 1) jump = true;
    }
    if (same) return;
    if (jump) {
      log.clear();
      log.add(0, steps() == 0 ? "ready: press Step or Play" : "at step " + std::to_string(steps()));
    } else {
      for (int i = 0; i < 2; ++i) {
        const Side& s = sides_[static_cast<std::size_t>(i)];
        if (s.session->version() == s.logged_version) continue;
        const Planner& p = s.session->shown();
        std::string line = std::string(kSideNames[i]) + ": " + p.describe(p.last_event(), s.session->planned_scene());
        if (instructor::hidden("path_length")) line = without_lengths(line);
        log.add(p.steps(), line);
      }
    }
    for (Side& s : sides_) s.logged_version = s.session->version();
  }

  // ---- drawing
  void side_controls(int i, LabContext& ctx) {
    Side& s = sides_[static_cast<std::size_t>(i)];
    const std::string key = kSideKeys[i];
    PlannerChoice c = s.choice;
    {
      const std::string param = "planner_" + key;
      instructor::FixedParam fixed(param.c_str());
      const char* current = planner_kind_info(c.kind).name;
      if (ImGui::BeginCombo("planner", current)) {
        for (const PlannerKindInfo& k : planner_kinds()) {
          if (ImGui::Selectable(k.name, k.kind == c.kind)) {
            c.kind = k.kind;
            if (k.tree) c.sampler = SamplerSpec{};  // the trees sample uniformly
          }
          if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", k.summary);
        }
        ImGui::EndCombo();
      }
    }
    {
      const std::string param = "samples_" + key;
      instructor::FixedParam fixed(param.c_str());
      param_slider(i ? kSamplesB : kSamplesA, "samples", c.samples, 0, 2000, ImGuiSliderFlags_AlwaysClamp);
    }
    if (!planner_kind_info(c.kind).tree) {
      const std::string param = "sampler_" + key;
      sampler_controls(c.sampler, param.c_str());
    }
    if (planner_kind_info(c.kind).tree) {
      if (c.kind == PlannerChoice::Kind::Rrt) {  // (RRT-Connect heads for the other tree, not the goal)
        const std::string param = "goal_bias_" + key;
        instructor::FixedParam fixed(param.c_str());
        param_slider(i ? kGoalBiasB : kGoalBiasA, "goal bias", c.goal_bias, 0.0, 1.0, "%.2f");
      }
      const std::string param = "step_" + key;
      instructor::FixedParam fixed(param.c_str());
      param_slider(i ? kStepB : kStepA, "step D", c.step, 0.0, 0.5, c.step == 0 ? "0 (auto)" : "%.3f");
    }
    if (same_choice(c, s.choice)) return;
    if (const std::string problem = budget_problem(c, scene_); !problem.empty()) {
      ctx.notify(problem);
      return;
    }
    s.choice = c;
    s.session->rebuild(scene_, recorded(make_planner_factory(s.choice)), 0);
    s.labels_at = -1;
    forget_log();
    drop_experiment();
  }

  void draw_side(int i, LabContext& ctx, ImVec2 size) {
    Side& s = sides_[static_cast<std::size_t>(i)];
    WorkspaceView& view = s.view;
    const char* ids[2] = {"##compare-a", "##compare-b"};
    view.begin(ids[i], size, scene_.workspace_min, scene_.workspace_max);
    // Planner A's is the lesson's "workspace" (what the API and the keys name first), B's "workspaceb".
    ctx.views[i == 0 ? "workspace" : "workspaceb"] = &view;
    view.draw_grid("x", "y");
    view.push_clip();
    for (const Obstacle& o : scene_.obstacles) view.draw_obstacle(o);
    const Planner& p = s.session->shown();
    const Space& space = s.session->world().space();
    if (s.labels_at != s.session->version()) {
      s.labels = p.component_labels();
      s.labels_at = s.session->version();
    }
    // (Lazy PRM's edges never checked come out dashed.)
    s.layer.draw(view, space, p.roadmap(), s.labels, s.throttle(s.session->version(), s.session->busy()),
                 p.checked_edge_flags());
    // Rejected samples: small crosses (the accepted ones are the roadmap's vertices).
    draw_rejected_samples(view, recording(i).rejected());
    if (p.solved()) draw_path(view, space, p.roadmap(), p.path());
    if (s.session->replaying()) draw_replay_pending(view, replaying_text(*s.session));
    else draw_current(p, view);
    view.draw_marker(Vec2(scene_.start[0], scene_.start[1]), theme::kStart, "S", !s.session->world().is_free(scene_.start));
    view.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G", !s.session->world().is_free(scene_.goal));
    view.pop_clip();
    const std::string title = side_label(i);
    view.draw_label(Vec2(scene_.workspace_min.x(), scene_.workspace_max.y()), title.c_str(), theme::kLabel,
                    ImVec2(16, -22));
  }

  // "A: prm", or "B: prm, bridge:0.05,uniform:0.3": the view's title, the table's row and the
  // plot's legend name the sampler too, since two PRMs differ only there.
  std::string side_label(int i) const {
    const PlannerChoice& c = sides_[static_cast<std::size_t>(i)].choice;
    std::string label = std::string(kSideNames[i]) + ": " + planner_kind_info(c.kind).name;
    if (c.sampler.kind != SamplerSpec::Kind::Uniform) label += ", " + c.sampler.name();
    return label;
  }

  // The last step's sample, ringed (free) or crossed (in collision), as Step PRM shows it.
  static void draw_current(const Planner& p, const WorkspaceView& view) {
    if (p.steps() == 0) return;
    const PlannerEvent& e = p.last_event();
    if (e.kind != PlannerEvent::Kind::SampleAccepted && e.kind != PlannerEvent::Kind::SampleRejected) return;
    const ImVec2 c = view.to_screen(Vec2(e.q[0], e.q[1]));
    const bool ok = e.kind == PlannerEvent::Kind::SampleAccepted;
    view.draw_list()->AddCircle(c, 9.0f, ok ? theme::kFree : theme::kHit, 24, 2.5f);
  }

  void table(float width, float height) {
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_ScrollX |
                                  ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("##compare-table", 9, flags, ImVec2(width, height))) return;
    for (const char* h : {"planner", "steps", "samples", "collision checks", "edge checks", "edges", "path", "length",
                          "time"})
      ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    for (int i = 0; i < 2; ++i) {
      const Planner& p = shown(i);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(side_label(i).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%ld", p.steps());
      ImGui::TableNextColumn();
      ImGui::Text("%d (%zu rejected)", p.samples_drawn(), recording(i).rejected().size());
      ImGui::TableNextColumn();
      ImGui::Text("%lld", p.configurations_tested());
      ImGui::TableNextColumn();
      ImGui::Text("%ld", p.edge_checks());
      ImGui::TableNextColumn();
      ImGui::Text("%ld", p.edges_alive());
      ImGui::TableNextColumn();
      if (p.solved()) ImGui::TextColored(theme::vec4(theme::kTextGood), "found");
      else if (p.done()) ImGui::TextColored(theme::vec4(theme::kTextBad), "none");
      else ImGui::TextDisabled("not yet");
      ImGui::TableNextColumn();
      if (!p.solved()) ImGui::TextDisabled("-");
      else if (instructor::hidden("path_length")) ImGui::TextUnformatted(instructor::kHidden);
      else ImGui::Text("%.4f", p.path_length());
      ImGui::TableNextColumn();
      // The platform's clock, for the eye only (a replay measures again).
      ImGui::Text("%.1f ms", recording(i).milliseconds());
    }
    ImGui::EndTable();
  }

  void experiment_panel(LabContext& ctx) {
    ImGui::TextWrapped("Each planner runs with %d seeds at each sample budget; the plot shows the share of runs "
                       "that found a path.",
                       trials_);
    {
      instructor::FixedParam fixed("trials");
      param_slider(kCompareTrials, "runs per budget", trials_, static_cast<int>(kCompareTrials.min),
                   static_cast<int>(kCompareTrials.max), ImGuiSliderFlags_AlwaysClamp);
    }
    {
      instructor::FixedParam fixed("axis");
      int axis = axis_;
      ImGui::TextUnformatted("plot against");
      ui::flow(ui::toggle_width("samples"));
      if (ImGui::RadioButton("samples", &axis, kSamplesAxis)) axis_ = kSamplesAxis;
      ui::flow(ui::toggle_width("collision checks"));
      if (ImGui::RadioButton("collision checks", &axis, kChecksAxis)) axis_ = kChecksAxis;
    }
    std::string text;
    for (int n : budgets_) text += (text.empty() ? "" : ", ") + std::to_string(n);
    ImGui::TextWrapped("budgets (samples): %s", text.c_str());
    if (!experiment_running() && ImGui::Button("Run experiment")) {
      if (const std::string problem = experiment_problem(budgets_, trials_); !problem.empty()) return ctx.notify(problem);
      start_experiment();
      ctx.log.clear();
      ctx.log.add(0, "experiment started: " + std::to_string(trials_) + " runs per budget and planner");
    }
  }

  // A row's x: its budget, or the mean collision checks of its runs so far (0 before any).
  double row_x(const ExperimentRow& r) const {
    if (axis_ == kSamplesAxis) return r.samples;
    return r.trials > 0 ? static_cast<double>(r.configurations_tested) / r.trials : 0.0;
  }
  void experiment_plot(ImVec2 size) {
    double lo = 1e9, hi = 1;
    if (axis_ == kSamplesAxis || !sides_[0].experiment) {
      for (int n : budgets_) lo = std::min(lo, static_cast<double>(std::max(n, 1))), hi = std::max(hi, static_cast<double>(n));
    } else {
      for (const Side& s : sides_)
        for (const ExperimentRow& r : s.experiment->rows())
          if (r.trials > 0 && row_x(r) >= 1.0) lo = std::min(lo, row_x(r)), hi = std::max(hi, row_x(r));
      if (lo > hi) lo = hi = 1.0;
    }
    lo = std::pow(10.0, std::floor(std::log10(lo)));
    hi = std::pow(10.0, std::ceil(std::log10(std::max(hi, 1.5 * lo))));
    const char* x_label = axis_ == kSamplesAxis ? "samples (log scale)"
                                                : "collision checks per run: configurations tested (log scale)";
    plot_.begin("##compare-plot", size, {lo, hi, true, x_label}, {0.0, 1.0, false, "success rate"});
    const ImU32 colours[2] = {theme::kBlue, theme::kVermillion};
    if (sides_[0].experiment) {
      for (int i = 0; i < 2; ++i) {
        std::vector<double> xs, ys, los, his;
        for (const ExperimentRow& r : sides_[static_cast<std::size_t>(i)].experiment->rows()) {
          if (r.trials == 0 || r.samples <= 0 || !(row_x(r) >= 1.0)) continue;
          xs.push_back(row_x(r));
          ys.push_back(1.0 - r.failure_rate.estimate);
          los.push_back(1.0 - r.failure_rate.high);
          his.push_back(1.0 - r.failure_rate.low);
        }
        const std::string legend = side_label(i);
        plot_.line(xs, ys, colours[i], 2.5f, legend.c_str());
        plot_.points(xs, ys, los, his, colours[i], nullptr);
      }
    }
    plot_.end();
  }

  double passage_ = kPassageWidth.def;
  Scene scene_;
  std::uint64_t seed_ = 1;
  std::shared_ptr<const CollisionWorld> experiment_world_;  // the experiments reference it: before sides_
  std::array<Side, 2> sides_;
  int mode_ = kStepMode;
  int trials_ = static_cast<int>(kCompareTrials.def);
  int axis_ = kSamplesAxis;
  std::vector<int> budgets_ = {25, 50, 100, 200, 400};
  bool experiment_done_now_ = false;
  Plot plot_;  // a member: the JS API maps points through it
};

}  // namespace

CSL_REGISTER_LESSON(CompareLesson, "compare", "Compare planners", "Planning");

}  // namespace csl::app
