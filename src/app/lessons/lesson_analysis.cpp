// Lesson "PRM analysis": why PRM works, in numbers. The failure bound of section 2.1 for the
// current scene (L and r from a reference path, mu(F) by Monte Carlo, all editable), against
// n on a log scale, with measured failure rates from repeated runs (in the background of the
// frame loop, with progress and cancel); P8's whole-space tiling bound, first as the handout
// has it (the path bound with m = N^d balls), then refined for the balls at the cube's faces,
// against the path bound; and P9's visibility probability for the wall-with-a-gap square,
// worked out by cases and by Monte Carlo.
#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <utility>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/shell/bundled_scenes.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/lesson.hpp"
#include "core/base/text.hpp"
#include "app/shell/panel.hpp"
#include "app/shell/param_widgets.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/views/draw.hpp"
#include "app/views/plot.hpp"
#include "app/views/scene_editor.hpp"
#include "app/views/split.hpp"
#include "core/teaching/experiment.hpp"
#include "core/teaching/work.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;

constexpr double kFrameBudgetMs = 8.0;  // experiment work per frame: the UI stays responsive

// A count in full (wrapped text may break after the point of "1.689e+05"), up to 1e15.
std::string count_text(double m) {
  char text[40];
  std::snprintf(text, sizeof text, m < 1e15 ? "%.0f" : "%.3g", m);
  return text;
}

// The tabs, and their names in the API ("tab" in params and state).
enum Tab { kBoundTab = 0, kVisibilityTab = 1, kTilingTab = 2 };
const char* tab_name(int tab) { return tab == kBoundTab ? "bound" : tab == kTilingTab ? "tiling" : "visibility"; }

class AnalysisLesson : public Lesson, private NoSteps {
 public:
  AnalysisLesson() : scene_(bundled_scene("wall-gap")) {
    measure();
    sample_p9();
  }

  void update(LabContext& ctx) override {
    if (!experiment_ || experiment_->done()) return;
    // A slice of trials per frame, then back to drawing.
    const auto start = std::chrono::steady_clock::now();
    while (!experiment_->done() &&
           std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() < kFrameBudgetMs)
      experiment_->step();
    if (experiment_->done()) ctx.log.add(0, "experiment finished: " + std::to_string(trials_) + " runs per n");
  }

  void panel(LabContext& ctx) override {
    int tab = tab_;
    {
      instructor::FixedParam fixed("tab");
      if (ImGui::RadioButton("Bound (2.1)", &tab, kBoundTab)) tab_ = kBoundTab;
      ui::flow(ui::toggle_width("Cube (P8)"));
      if (ImGui::RadioButton("Cube (P8)", &tab, kTilingTab)) tab_ = kTilingTab;
      ui::flow(ui::toggle_width("Visibility (P9)"));
      if (ImGui::RadioButton("Visibility (P9)", &tab, kVisibilityTab)) tab_ = kVisibilityTab;
    }
    if (tab_ == kBoundTab) bound_panel(ctx);
    else if (tab_ == kTilingTab) tiling_panel();
    else visibility_panel();
  }

  void views(LabContext& ctx, ImVec2 size) override {
    if (tab_ != kVisibilityTab) {  // the bound and P8: the scene their r comes from, and the plot
      // Beside the plot (a square as tall as the area, at most 42% of the width), or over it on
      // a portrait screen.
      Split s = split(size, 0.45f);
      if (!s.stacked) {
        const float side = std::min(size.x * 0.42f, size.y);
        s.first = ImVec2(side, size.y);
        s.second = ImVec2(size.x - side - ImGui::GetStyle().ItemSpacing.x, size.y);
      }
      scene_view_.begin("##analysis-scene", s.first, scene_.workspace_min, scene_.workspace_max);
      ctx.views["workspace"] = &scene_view_;
      scene_view_.draw_grid();
      scene_view_.push_clip();
      for (const Obstacle& o : scene_.obstacles) scene_view_.draw_obstacle(o);
      if (!reference_path_.empty()) {
        for (std::size_t i = 0; i + 1 < reference_path_.size(); ++i)
          scene_view_.draw_segment(Vec2(reference_path_[i][0], reference_path_[i][1]),
                                   Vec2(reference_path_[i + 1][0], reference_path_[i + 1][1]), theme::kPath, 3.0f);
      }
      scene_view_.draw_marker(Vec2(scene_.start[0], scene_.start[1]), theme::kStart, "S");
      scene_view_.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G");
      scene_view_.pop_clip();
      if (editor_.edit(scene_view_, scene_, ctx, {})) measure();
      editor_.help_window();
      between(s);
      bound_plot(s.second);
      ctx.plots["bound"] = &plot_;
    } else {
      const float side = std::min(size.x, size.y);
      p9_view_.begin("##p9", ImVec2(side, size.y), Vec2(0, 0), Vec2(1, 1));
      ctx.views["p9"] = &p9_view_;
      p9_view_.draw_grid();
      p9_view();
    }
  }

  Scene* scene() override { return &scene_; }
  std::vector<LessonView> views_kept() override {
    return {{"workspace", &scene_view_, scene_.workspace_min, scene_.workspace_max}, {"p9", &p9_view_, Vec2(0, 0), Vec2(1, 1)}};
  }
  SceneEditor* editor() override { return tab_ != kVisibilityTab ? &editor_ : nullptr; }
  bool accept_scene(const Scene& s, std::string& why) override {
    if (std::holds_alternative<ArmRobot>(s.robot)) {
      why = "the analysis lesson uses point and polygon robots";
      return false;
    }
    editor_.replace(scene_, s);
    measure();
    return true;
  }
  bool undo() override { return editor_.undo(scene_) && (measure(), true); }
  bool redo() override { return editor_.redo(scene_) && (measure(), true); }

  json state(const json&) const override {
    json rows = json::array();
    if (experiment_)
      for (const ExperimentRow& r : experiment_->rows())
        rows.push_back({{"samples", r.samples},
                        {"trials", r.trials},
                        {"failures", r.failures},
                        {"failure_rate", r.failure_rate.estimate},
                        {"ci_low", r.failure_rate.low},
                        {"ci_high", r.failure_rate.high},
                        {"bound", bound(r.samples).bound}});
    const std::optional<TilingBound> cube = tiling();
    const FailureBound path = bound(0);
    const auto or_null = [](bool known, double v) { return known ? json(v) : json(nullptr); };
    const auto n_for = [&](double rate, auto solve) { return rate > 0 ? json(solve()) : json(nullptr); };
    json handout = nullptr, refined = nullptr;
    if (cube) {
      // P8 as the handout has it: the path bound with the cube's m balls.
      handout = {{"per_axis", cube->per_axis}, {"m", cube->balls}, {"sigma", cube->sigma}, {"rate", cube->rate},
                 {"target", target_}, {"n_for_target", cube->interior_samples_for(target_)},
                 {"bound_at_1000", cube->interior_bound_at(1000)}};
      refined = {{"m", cube->balls}, {"boundary_balls", cube->boundary_balls}, {"edge_per_axis", cube->edge_per_axis},
                 {"hit_rate", cube->hit_rate}, {"target", target_}, {"n_for_target", cube->samples_for(target_)},
                 {"bound_at_1000", cube->bound_at(1000)}};
    }
    const json path_json = {{"m", or_null(path.rate > 0, path.balls)}, {"sigma", or_null(path.rate > 0, path.sigma)},
                            {"rate", or_null(path.rate > 0, path.rate)}, {"target", target_},
                            {"n_for_target", n_for(path.rate, [&] { return path.samples_for(target_); })}};
    const P9Breakdown cases = p9_breakdown(p9_x_, p9_y_, p9_gap_);
    const auto ray = [](const P9Ray& r) {
      return json{{"start", r.start}, {"slope", r.slope}, {"exit", p9_exit_name(r.exit)},
                  {"exit_x", r.exit_x}, {"exit_y", r.exit_y}, {"area_under", r.area_under}};
    };
    return {{"tab", tab_name(tab_)},
            {"target", target_},
            {"handout", handout},
            {"refined", refined},
            {"path", path_json},
            {"path_exists", path_exists_},
            {"length", length_},
            {"clearance", clearance_},
            {"dimension", dim_},
            {"free_volume", free_volume_},
            {"measured", {{"length", measured_length_}, {"clearance", measured_clearance_}, {"free_volume", measured_volume_}}},
            {"bound_at_1000", bound(1000).bound},
            {"tiling_bound_at_1000", cube ? json(cube->bound_at(1000)) : json(nullptr)},
            {"sample_counts", sample_counts_},
            {"trials", trials_},
            {"experiment",
             {{"running", experiment_ && !experiment_->done()},
              {"progress", experiment_ ? experiment_->progress() : 0.0},
              {"rows", rows}}},
            {"visibility",
             {{"x", p9_x_},
              {"y", p9_y_},
              {"gap", p9_gap_},
              {"exact", visibility_probability(p9_x_, p9_y_, p9_gap_)},
              {"monte_carlo", mc_.estimate},
              {"trials", mc_.trials},
              {"ci_low", mc_.low},
              {"ci_high", mc_.high},
              {"within_ci", exact_in_interval()},
              {"mc_seed", p9_seed_},
              {"case", cases.case_name},
              {"upper", ray(cases.upper)},
              {"lower", ray(cases.lower)},
              {"left_area", cases.left_area},
              {"right_area", cases.right_area},
              {"probability", cases.probability}}}};
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    // Checked in full before anything changes.
    double length = length_, clearance = clearance_, volume = free_volume_;
    std::vector<int> counts = sample_counts_;
    int trials = trials_, tab = tab_;
    double target = target_;
    double x = p9_x_, y = p9_y_, gap = p9_gap_;
    long long mc = mc_trials_;
    std::uint64_t mc_seed = p9_seed_;
    bool run = false, cancel = false;
    const auto positive = [](const json& v, const char* what) {
      if (!v.is_number() || !(v.get<double>() > 0) || !std::isfinite(v.get<double>()))
        throw ApiError(std::string(what) + ": a finite number > 0");
      return v.get<double>();
    };
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& k = it.key();
      const json& v = *it;
      if (k == "length") length = positive(v, "length");
      else if (k == "clearance") clearance = positive(v, "clearance");
      else if (k == "free_volume") volume = positive(v, "free_volume");
      else if (k == "sample_counts") {
        if (!v.is_array() || v.empty() || v.size() > kLabMaxSampleCounts)
          throw ApiError("sample_counts: 1 to " + std::to_string(kLabMaxSampleCounts) + " integers");
        counts.clear();
        for (const json& n : v) {
          // The lab's budget alone (within the CLI's range): one error, the bound that holds here.
          counts.push_back(static_cast<int>(api_param(kLabExperimentSamples, n)));
        }
      } else if (k == "trials") {
        trials = static_cast<int>(api_param(kLabExperimentTrials, v));
      } else if (k == "tab") {
        if (v != "bound" && v != "visibility" && v != "tiling")
          throw ApiError("tab: \"bound\", \"tiling\" or \"visibility\"");
        tab = v == "bound" ? kBoundTab : v == "tiling" ? kTilingTab : kVisibilityTab;
      } else if (k == "target") {
        if (!v.is_number() || !(v.get<double>() > 0.0 && v.get<double>() < 1.0))
          throw ApiError("target: a failure probability p with 0 < p < 1");
        target = v.get<double>();
      } else if (k == "point") {
        if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) throw ApiError("point: [x, y]");
        x = v[0].get<double>();
        y = v[1].get<double>();
      } else if (k == "gap") {
        if (!v.is_number()) throw ApiError("gap: a number in [0, 1]");
        gap = v.get<double>();
      } else if (k == "mc_seed") {
        mc_seed = static_cast<std::uint64_t>(api_param(kMcSeed, v));
      } else if (k == "mc_trials") {
        mc = static_cast<long long>(api_param(kLabVisibilityTrials, v));  // the lab's budget alone
      } else if (k == "run") run = v.is_boolean() && v.get<bool>();
      else if (k == "cancel") cancel = v.is_boolean() && v.get<bool>();
      else throw ApiError("unknown parameter \"" + k + "\"");
    }
    if (!(x >= 0 && x < 0.5 && y >= 0 && y <= 1)) throw ApiError("point: x in [0, 1/2), y in [0, 1]");
    if (!(gap >= 0 && gap <= 1)) throw ApiError("gap: a number in [0, 1]");
    if (run)
      if (const std::string problem = experiment_problem(counts, trials); !problem.empty()) throw ApiError(problem);
    length_ = length;
    clearance_ = clearance;
    free_volume_ = volume;
    sample_counts_ = counts;
    std::string text;
    for (int n : counts) text += (text.empty() ? "" : ",") + std::to_string(n);
    std::snprintf(counts_text_, sizeof counts_text_, "%s", text.c_str());
    trials_ = trials;
    tab_ = tab;
    target_ = target;
    const bool p9_changed = x != p9_x_ || y != p9_y_ || gap != p9_gap_ || mc != mc_trials_ || mc_seed != p9_seed_;
    p9_x_ = x;
    p9_y_ = y;
    p9_gap_ = gap;
    mc_trials_ = mc;
    p9_seed_ = mc_seed;
    if (p9_changed) sample_p9();
    if (cancel) experiment_.reset();
    if (run) start_experiment();
  }

  std::vector<ParamField> param_fields() const override {
    return {{"sample_counts", "sample counts n", &kLabExperimentSamples},
            {"trials", "trials", &kLabExperimentTrials},
            {"tab", "tab", nullptr, {"bound", "tiling", "visibility"}},
            {"mc_trials", "Monte Carlo samples", &kLabVisibilityTrials},
            {"mc_seed", "Monte Carlo seed", &kMcSeed},
            // P9's square, whose wall is at x = 1/2, and the p that tabs 2.1 and P8 solve n for.
            {"gap", "gap d", nullptr, {}, "the height of the opening in the middle of the wall (a number in [0, 1])"},
            {"point", "point (x1, y1)", nullptr, {}, "the configuration that looks through the gap, comma-separated: x1 in [0, 1/2), y1 in [0, 1]"},
            {"target", "target p", nullptr, {}, "the failure probability that n is solved for on tabs Bound (2.1) and Cube (P8), 0 < p < 1"}};
  }

  // What the open tab shows. P9's square is not the scene: its wall and gap are the tab's own.
  std::string describe() const override {
    if (tab_ == kVisibilityTab) return visibility_text();
    std::string out = Lesson::describe();
    if (tab_ == kTilingTab) out += " " + tiling_text();
    if (!experiment_) return out + " No experiment has run yet.";
    out += " The experiment's failure rates:";
    for (const ExperimentRow& r : experiment_->rows())
      out += " n = " + std::to_string(r.samples) + ": " + std::to_string(r.failures) + " failures in " +
             std::to_string(r.trials) + " runs;";
    return out;
  }

  std::string visibility_text() const {
    const auto num = [](double v) { return significant(v, 4); };
    std::string out = "P9: the unit square with a wall at x = 0.5, open from y = " + num(0.5 - 0.5 * p9_gap_) +
                      " to " + num(0.5 + 0.5 * p9_gap_) + " (gap d = " + num(p9_gap_) + "); the point (x1, y1) = (" +
                      num(p9_x_) + ", " + num(p9_y_) + "). In sight: all of the left half, and of the right half the "
                      "cone between the rays through the opening's ends.";
    if (instructor::hidden("p9_probability")) return out + " The cases, the areas and p are hidden by your instructor.";
    const P9Breakdown b = p9_breakdown(p9_x_, p9_y_, p9_gap_);
    return out + " The upper ray leaves through the " + p9_exit_name(b.upper.exit) + ", the lower through the " +
           p9_exit_name(b.lower.exit) + ". p = 1/2 + A_up - A_lo = 0.5 + " + num(b.upper.area_under) + " - " +
           num(b.lower.area_under) + " = " + num(b.probability) + " exact; by Monte Carlo, " + std::to_string(mc_.trials) +
           " samples: " + num(mc_.estimate) + ", 95% interval [" + num(mc_.low) + ", " + num(mc_.high) + "], the exact p " +
           (exact_in_interval() ? "inside it." : "outside it.");
  }

  std::string tiling_text() const {
    const std::optional<TilingBound> t = tiling();
    if (!t) return "P8: no clearance r > 0 (or too many balls): set r in tab Bound.";
    std::string out = "P8, the whole cube [0,1]^" + std::to_string(dim_) + " tiled with balls of radius r/2, r = " +
                      significant(clearance_, 4) + ": N = " + count_text(t->per_axis) + " per axis, m = " +
                      count_text(t->balls) + " balls, sigma = " + significant(t->sigma, 4) + "; P(fail) <= m e^(-" +
                      significant(t->rate, 4) + " n).";
    if (instructor::hidden("p8_n")) return out + " Its n is hidden by your instructor.";
    return out + " n for p = " + target_text() + ": " + count_text(std::ceil(t->interior_samples_for(target_))) +
           " as in the handout, " + count_text(std::ceil(t->samples_for(target_))) + " refined.";
  }

  json params() const override {
    return {{"sample_counts", sample_counts_}, {"trials", trials_}, {"tab", tab_name(tab_)},
            {"point", {p9_x_, p9_y_}}, {"gap", p9_gap_}, {"mc_trials", mc_trials_}, {"mc_seed", p9_seed_},
            {"target", target_}};
  }

  Stepper* stepper() override { return this; }

  // ---- Stepper: the API's "run" finishes the experiment; there is nothing to step, and the
  // experiment has its own buttons in the panel.
  /// "run" from the API: finish the experiment now (starting one if none).
  void run_all() override {
    if (!experiment_) {
      if (const std::string problem = experiment_problem(sample_counts_, trials_); !problem.empty()) throw ApiError(problem);
      start_experiment();
    }
    experiment_->run();
  }

 private:
  FailureBound bound(int n) const {
    if (!(length_ > 0 && clearance_ > 0 && free_volume_ > 0)) return FailureBound{};
    return path_tiling_bound(length_, clearance_, dim_, free_volume_, n);
  }

  // P8 for the current r and d (none without a clearance, or past a double's balls).
  std::optional<TilingBound> tiling() const {
    if (!(clearance_ > 0)) return std::nullopt;
    try {
      return whole_space_tiling_bound(clearance_, dim_, 0);
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  }

  bool exact_in_interval() const {
    const double exact = visibility_probability(p9_x_, p9_y_, p9_gap_);
    return exact >= mc_.low && exact <= mc_.high;
  }

  // Why an experiment of `trials` runs for each n in `counts` is more than the lab does here, or
  // "": each run is one step between frames, so one run must fit about ten frames' work; all of
  // them the lab's budget for a long job (the experiment shows its progress and can be
  // cancelled, so that is minutes at most).
  std::string experiment_problem(const std::vector<int>& counts, int trials) const {
    if (too_dense_)
      return "this scene is too dense for an experiment here (its reference run alone would hold the page): "
             "use cspacelab experiment";
    // Its first step, the reference run and Monte Carlo volume, as measure() sized them.
    const ExperimentWork w = expected_experiment_work(*world_, experiment_params(reference_samples_, volume_samples_, counts, trials));
    const double largest = w.largest_run, total = w.total;
    if (largest > 10 * kLabFrameWork)
      return "a run of " + std::to_string(std::max(reference_samples_, *std::max_element(counts.begin(), counts.end()))) +
             " samples means " + work_text(largest) + " in this scene; the lab runs at most " +
             work_text(10 * kLabFrameWork) + " at once: take smaller n (or use cspacelab experiment)";
    if (total > 10 * kLabMaxWork)
      return "the experiment means " + work_text(total) + " in all; the lab takes at most " +
             work_text(10 * kLabMaxWork) + ": take fewer runs or smaller n (or use cspacelab experiment)";
    return "";
  }

  // Measures the scene: a reference run for a path (L, r), Monte Carlo for mu(F). Within a few
  // frames' work (it runs on every edit): fewer samples in a dense scene, none in one so dense
  // that even those would hold the page (then L, r and mu(F) are entered by hand).
  void measure() {
    world_ = std::make_unique<CollisionWorld>(scene_);
    experiment_.reset();
    reference_path_.clear();
    dim_ = world_->space().dim();
    ExperimentParams p = experiment_params(3000, 50000, {1}, 1);
    too_dense_ = false;
    reference_samples_ = p.reference_samples;
    volume_samples_ = p.volume_samples;
    if (!world_->is_free(scene_.start) || !world_->is_free(scene_.goal)) {
      path_exists_ = false;
      return;
    }
    const auto work = [&](int reference, long volume) {
      return expected_experiment_work(*world_, experiment_params(reference, volume, {}, 0)).reference;
    };
    const double budget = 5 * kLabFrameWork;
    if (const double full = work(p.reference_samples, p.volume_samples); full > budget) {
      const double f = budget / full;
      p.reference_samples = std::max(300, static_cast<int>(p.reference_samples * f));
      p.volume_samples = std::max(2000L, static_cast<long>(static_cast<double>(p.volume_samples) * f));
      if (work(p.reference_samples, p.volume_samples) > budget) {
        path_exists_ = false;
        too_dense_ = true;
        return;
      }
    }
    reference_samples_ = p.reference_samples;
    volume_samples_ = p.volume_samples;
    Experiment probe(*world_, scene_.start, scene_.goal, p);
    probe.step();  // the reference run only
    const ExperimentReference& ref = probe.reference();
    path_exists_ = ref.path_exists;
    measured_length_ = ref.path_length;
    measured_clearance_ = ref.clearance;
    measured_volume_ = ref.free_volume;
    length_ = measured_length_;
    clearance_ = measured_clearance_;
    free_volume_ = measured_volume_;
    reference_path_ = ref.path;
  }

  void start_experiment() {
    // The reference run and volume as measure() sized them for this scene.
    experiment_ = std::make_unique<Experiment>(*world_, scene_.start, scene_.goal,
                                               experiment_params(reference_samples_, volume_samples_, sample_counts_, trials_));
  }

  // The lesson's experiments: PRM's defaults (k = 10, bisection), seed 1.
  static ExperimentParams experiment_params(int reference, long volume, std::vector<int> counts, int trials) {
    ExperimentParams p;
    p.sample_counts = std::move(counts);
    p.trials = trials;
    p.seed = 1;
    p.reference_samples = reference;
    p.volume_samples = volume;
    return p;
  }

  void bound_panel(LabContext& ctx) {
    if (panel::fold("The bound of section 2.1")) bound_section();
    if (panel::fold("How L, r and μ(F) were measured", false)) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("L and r on the widest path (the largest clearance) of a reference roadmap of 3000 samples, "
                         "r = its least clearance in the workspace (proven, a lower bound) / the robot's Lipschitz "
                         "constant; μ(F) by Monte Carlo");
      ImGui::PopStyleColor();
    }
    if (panel::fold("Experiment: run PRM many times")) experiment_section(ctx);
    if (panel::fold("Obstacles") && editor_.toolbar(scene_, ctx)) measure();
  }

  void bound_section() {
    ImGui::TextWrapped("A free path of length L with clearance r is covered by m = ceil(L/(r/2)) balls of "
                       "radius r/2; PRM fails only if one of them gets no sample:");
    ImGui::PushStyleColor(ImGuiCol_Text, theme::vec4(theme::kTextKey));
    ImGui::TextWrapped("P(fail) ≤ m exp(−σ r^d n),  σ = μ(B₁) / (2^d μ(F))");
    ImGui::PopStyleColor();
    if (too_dense_)
      ImGui::TextColored(theme::vec4(theme::kTextBad),
                         "this scene is too dense to measure here: enter L, r and μ(F) by hand (or use cspacelab experiment)");
    else if (!path_exists_)
      ImGui::TextColored(theme::vec4(theme::kTextBad), "no path found in this scene: enter L, r by hand");
    ImGui::PushItemWidth(-110);
    float l = static_cast<float>(length_), r = static_cast<float>(clearance_), v = static_cast<float>(free_volume_);
    if (ImGui::DragFloat("L (length)", &l, 0.01f, 0.001f, 100.0f, "%.4f")) length_ = static_cast<double>(l);
    if (ImGui::DragFloat("r (clearance)", &r, 0.0005f, 0.0001f, 10.0f, "%.4f")) clearance_ = static_cast<double>(r);
    if (ImGui::DragFloat("μ(F)", &v, 0.01f, 0.0001f, 1000.0f, "%.4f")) free_volume_ = static_cast<double>(v);
    ImGui::PopItemWidth();
    ImGui::Text("d = %d   m = %.0f   σ = %.4g", dim_, bound(0).balls, bound(0).sigma);
    if (ui::small_button("use the measured values")) {
      length_ = measured_length_;
      clearance_ = measured_clearance_;
      free_volume_ = measured_volume_;
    }
    if (bound(0).rate > 0)
      ImGui::Text("the bound reaches p = %s at n = %s", target_text().c_str(),
                  count_text(std::ceil(bound(0).samples_for(target_))).c_str());
    if (const std::optional<TilingBound> t = tiling(); t && instructor::hidden("p8_n")) {
      instructor::hidden_line("P8, the whole cube tiled instead: its n");
    } else if (t) {
      // P8 beside it (the orange curve), the handout's version first; the tab has the details.
      ImGui::TextWrapped("P8, the whole cube [0,1]^%d tiled instead: m = %s balls, p = %s at n = %s (%s with the "
                         "balls at its faces counted as hit less often): see the tab Cube (P8)",
                         dim_, count_text(t->balls).c_str(), target_text().c_str(),
                         count_text(std::ceil(t->interior_samples_for(target_))).c_str(),
                         count_text(std::ceil(t->samples_for(target_))).c_str());
    }
  }

  void experiment_section(LabContext& ctx) {
    ImGui::PushItemWidth(-110);
    {
      instructor::FixedParam fixed("sample_counts");
      ImGui::InputText("n values", counts_text_, sizeof counts_text_);
    }
    {
      instructor::FixedParam fixed("trials");
      param_slider(kLabExperimentTrials, "runs per n", trials_, 1, 200);  // the API takes more
    }
    ImGui::PopItemWidth();
    const bool running = experiment_ && !experiment_->done();
    if (!running && ImGui::Button("Run experiment")) {
      std::vector<int> counts;
      std::stringstream in(counts_text_);
      std::string item;
      bool ok = true;
      while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const long n = std::strtol(item.c_str(), &end, 10);
        if (end == item.c_str() || !in_range(kLabExperimentSamples, static_cast<double>(n))) ok = false;
        else counts.push_back(static_cast<int>(n));
      }
      if (!ok || counts.empty() || counts.size() > static_cast<std::size_t>(kLabMaxSampleCounts)) {
        ctx.notify("n values: up to " + std::to_string(kLabMaxSampleCounts) + " values, each " +
                   range_text(kLabExperimentSamples) + ", separated by commas");
      } else if (const std::string problem = experiment_problem(counts, trials_); !problem.empty()) {
        ctx.notify(problem, 10);
      } else {
        sample_counts_ = counts;
        start_experiment();
        ctx.log.clear();
        ctx.log.add(0, "experiment started: " + std::to_string(trials_) + " runs for each of " +
                           std::to_string(counts.size()) + " values of n");
      }
    }
    if (running) {
      ImGui::ProgressBar(static_cast<float>(experiment_->progress()), ImVec2(-80, 0));
      ImGui::SameLine();
      if (ImGui::Button("Cancel")) {
        experiment_.reset();
        ctx.log.add(0, "experiment cancelled");
      }
    }
    if (experiment_) {
      if (ImGui::BeginTable("rates", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH)) {
        ImGui::TableSetupColumn("n");
        ImGui::TableSetupColumn("fail");
        ImGui::TableSetupColumn("rate");
        ImGui::TableSetupColumn("95%");
        ImGui::TableSetupColumn("bound");
        ImGui::TableHeadersRow();
        for (const ExperimentRow& row : experiment_->rows()) {
          if (row.trials == 0) continue;
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
          ImGui::Text("%d", row.samples);
          ImGui::TableNextColumn();
          ImGui::Text("%d/%d", row.failures, row.trials);
          ImGui::TableNextColumn();
          ImGui::Text("%.2f", row.failure_rate.estimate);
          ImGui::TableNextColumn();
          ImGui::Text("%.2f-%.2f", row.failure_rate.low, row.failure_rate.high);
          ImGui::TableNextColumn();
          ImGui::Text("%.3g", bound(row.samples).bound);
        }
        ImGui::EndTable();
      }
    }
  }

  void bound_plot(ImVec2 size) {
    // n on a log scale: the experiment's small n and the bound's large n on one picture.
    double n_lo = 10, n_hi = 1000;
    for (int n : sample_counts_)
      if (n > 0) n_lo = std::min(n_lo, 0.5 * n), n_hi = std::max(n_hi, 2.0 * n);
    if (bound(0).rate > 0) n_hi = std::max(n_hi, std::min(1e6, 2.0 * bound(0).samples_for(1e-3)));
    if (const std::optional<TilingBound> t = tiling()) n_hi = std::max(n_hi, std::min(1e6, 1.5 * t->samples_for(target_)));
    n_hi = std::pow(10.0, std::ceil(std::log10(n_hi)));
    n_lo = std::pow(10.0, std::floor(std::log10(std::max(n_lo, 1.0))));
    Plot& plot = plot_;
    plot.begin("##bound-plot", size, {n_lo, n_hi, true, "samples n (log scale)"}, {1e-4, 1e3, true, "P(failure)"});
    plot.shade_above(1.0, theme::with_alpha(theme::kInk, 18), "above 1: the bound says nothing");
    std::vector<double> xs, path_bound, handout, refined;
    const std::optional<TilingBound> cube = tiling();
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i <= 240; ++i) {
      const double n = n_lo * std::pow(n_hi / n_lo, i / 240.0);
      xs.push_back(n);
      path_bound.push_back(bound(static_cast<int>(std::lround(n))).bound);
      handout.push_back(cube ? cube->interior_bound_at(n) : kNone);
      refined.push_back(cube ? cube->bound_at(n) : kNone);
    }
    const std::string target_legend = "target p = " + target_text();
    plot.line({n_lo, n_hi}, {target_, target_}, theme::kLabel, 1.0f, target_legend.c_str());
    plot.line(xs, path_bound, theme::kBlue, 2.5f, "path tiling bound (2.1)");
    plot.line(xs, handout, theme::kOrange, 2.0f, "P8, handout's");
    plot.line(xs, refined, theme::kPurple, 2.0f, "P8, refined");
    if (experiment_) {
      std::vector<double> n, rate, lo, hi;
      for (const ExperimentRow& row : experiment_->rows()) {
        if (row.trials == 0 || row.samples <= 0) continue;
        n.push_back(row.samples);
        rate.push_back(row.failure_rate.estimate);
        lo.push_back(row.failure_rate.low);
        hi.push_back(row.failure_rate.high);
      }
      plot.points(n, rate, lo, hi, theme::kVermillion, "measured, 95% interval (0: hollow)");
    }
    plot.end();
  }

  // A colour for the numbers a panel is about.
  static ImVec4 key_colour() { return theme::vec4(theme::kTextKey); }
  static void dim_text_wrapped(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
  }
  std::string target_text() const {
    char text[32];
    std::snprintf(text, sizeof text, "%g", target_);
    return text;
  }

  // A line of formulas and numbers, broken only before " = " and after ", " or ": " where it is
  // wider than the panel (the next line indented): ImGui's wrapping would break after any '.',
  // inside a number ("0." / "9500"). A piece wider than the panel on its own is wrapped.
  static void formula(const std::string& text, const ImVec4* colour = nullptr) {
    std::vector<std::string> pieces;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
      const bool before = text.compare(i, 3, " = ") == 0 && i > start;
      const bool after = (text.compare(i, 2, ", ") == 0 || text.compare(i, 2, ": ") == 0);
      if (before) {
        pieces.push_back(text.substr(start, i - start));
        start = i;
      } else if (after) {
        pieces.push_back(text.substr(start, i + 2 - start));
        start = i + 2;
        ++i;
      }
    }
    pieces.push_back(text.substr(start));
    const float width = ImGui::GetContentRegionAvail().x;
    if (colour) ImGui::PushStyleColor(ImGuiCol_Text, *colour);
    std::string line;
    for (const std::string& piece : pieces) {
      if (!line.empty() && ImGui::CalcTextSize((line + piece).c_str()).x > width) {
        ImGui::TextWrapped("%s", line.c_str());
        line = "    " + piece.substr(piece.find_first_not_of(' ') == std::string::npos ? 0 : piece.find_first_not_of(' '));
      } else {
        line += piece;
      }
    }
    if (!line.empty()) ImGui::TextWrapped("%s", line.c_str());
    if (colour) ImGui::PopStyleColor();
  }

  // P8, the handout's way first (its m, sigma, the bound with the numbers in, the n it needs for
  // the student's p), then the refined bound and the path bound beside it.
  void tiling_panel() {
    const std::optional<TilingBound> t = tiling();
    const bool open = panel::fold("P8: tile the whole cube");
    if (open) {
      ImGui::TextWrapped("Cover all of F = [0,1]^%d with balls of radius r/2 instead of one path (r and d: the "
                         "scene's, tab Bound).", dim_);
      if (t) {
        ImGui::PushItemWidth(-ui::toggle_width("target p") + ImGui::GetFrameHeight());
        instructor::FixedParam fixed("target");
        double p = target_;
        // Typed digit by digit ("0", "0.0", "0.01"): only a p in (0, 1) is taken.
        if (ImGui::InputDouble("target p", &p, 0.0, 0.0, "%g") && p > 0.0 && p < 1.0) target_ = p;
        ImGui::PopItemWidth();
      }
    }
    if (!t) {
      ImGui::TextColored(theme::vec4(theme::kTextBad), "no clearance r > 0 (or too many balls): set r in tab Bound");
      return;
    }
    const double lead = std::max(2.0, std::sqrt(static_cast<double>(dim_)));
    const double n_handout = t->interior_samples_for(target_), n_refined = t->samples_for(target_);
    const std::string m = count_text(t->balls), per_axis = count_text(t->per_axis);
    const ImVec4 key = key_colour();
    const FailureBound path = bound(0);
    const bool hide_n = instructor::hidden("p8_n");  // P8's answer: the student solves for it
    if (open) {
      // The headline, in view also in a small embed: the handout's n first.
      const std::string path_n = path.rate > 0 ? count_text(std::ceil(path.samples_for(target_))) : "?";
      if (hide_n)
        instructor::hidden_line("P8's n (as in the handout, refined)");
      else
        formula(ui::format("n for p = %s: %s as in the handout, %s refined, %s for one path (2.1)", target_text().c_str(),
                           count_text(std::ceil(n_handout)).c_str(), count_text(std::ceil(n_refined)).c_str(),
                           path_n.c_str()),
                &key);

      ImGui::TextColored(key, "The handout's bound");
      dim_text_wrapped("A grid of N balls per axis, 1/N apart: neighbours at most r/2 apart needs N ≥ 2/r, and "
                       "covering every point (half a cell's diagonal, √d/(2N), at most r/2) needs N ≥ √d/r.");
      formula(ui::format("N = ⌈max(2, √d)/r⌉ = ⌈%.4g/%.4g⌉ = %s", lead, clearance_, per_axis.c_str()));
      formula(ui::format("m = N^d = %s^%d = %s", per_axis.c_str(), dim_, m.c_str()));
      formula(ui::format("σ = μ(B₁)/2^d = %.4g/%s = %.4g", unit_ball_volume(dim_), count_text(std::ldexp(1.0, dim_)).c_str(),
                     t->sigma));
      formula(ui::format("P(fail) ≤ m e^(−σ r^d n) = %s e^(−%.4g n)", m.c_str(), t->rate));
      if (!hide_n)
        formula(ui::format("n = ln(m/p)/(σ r^d) = ln(%s/%s)/%.4g = %s", m.c_str(), target_text().c_str(), t->rate,
                           count_text(std::ceil(n_handout)).c_str()),
                &key);
    }

    if (panel::fold("Refined: the balls at the faces", false)) {
      ImGui::TextWrapped("%s of the %s balls stick out of the cube, and a sample lands in those less often than σ r^d "
                         "says: there the handout's formula is not quite a bound. Counting a ball that sticks out "
                         "along j axes at rate σ r^d/2^j:",
                         count_text(t->boundary_balls).c_str(), m.c_str());
      if (!hide_n) formula(ui::format("n = %s for p = %s", count_text(std::ceil(n_refined)).c_str(), target_text().c_str()), &key);
    }

    if (panel::fold("Against the path bound (2.1)", false)) {
      if (path.rate > 0)
        formula(ui::format("path: m = ⌈L/(r/2)⌉ = %s, n = %s", count_text(path.balls).c_str(),
                       count_text(std::ceil(path.samples_for(target_))).c_str()));
      else
        ImGui::TextWrapped("path: enter L, r and μ(F) in tab Bound");
      if (!hide_n)
        formula(ui::format("cube: m = %s, n = %s (refined %s)", m.c_str(), count_text(std::ceil(n_handout)).c_str(),
                           count_text(std::ceil(n_refined)).c_str()));
      dim_text_wrapped("Much worse: the cube's m grows like (1/r)^d, the path's like L/r, and n with ln m. The cube "
                       "pays for every corner of the space, not one corridor, the more so as d grows.");
    }
  }

  // One ray of the P9 breakdown: its case (the edge it leaves the right half through, from its
  // height a + s/2 at x = 1) and the area below it by that case's formula, numbers put in.
  static void ray_lines(const char* name, const char* area, const P9Ray& r) {
    const double end = r.start + 0.5 * r.slope;
    const char* exit = r.exit == P9Ray::Exit::Top      ? " > 1: top"
                       : r.exit == P9Ray::Exit::Bottom ? " < 0: bottom"
                                                       : ": right edge";
    formula(ui::format("%s: a = %.3f, s = %.4g, a + s/2 = %.4g%s", name, r.start, r.slope, end, exit));
    if (r.exit == P9Ray::Exit::Top)
      formula(ui::format("  %s = ½ − (1 − a)²/(2s) = ½ − %.3f²/(2·%.4g) = %.5f", area, 1.0 - r.start, r.slope, r.area_under));
    else if (r.exit == P9Ray::Exit::Bottom)
      formula(ui::format("  %s = a²/(2|s|) = %.3f²/(2·%.4g) = %.5f", area, r.start, -r.slope, r.area_under));
    else
      formula(ui::format("  %s = (a + e)/4 = (%.3f + %.4f)/4 = %.5f", area, r.start, r.exit_y, r.area_under));
  }

  void visibility_panel() {
    if (!panel::fold("P9: seeing through the gap")) return exact_and_monte_carlo();
    ImGui::TextWrapped("A wall at x = 1/2, open for a height d in the middle. From a point (x1, y1) you click, "
                       "x1 < 1/2, what share of the square is in sight?");
    ImGui::PushItemWidth(-90);
    float gap = static_cast<float>(p9_gap_);
    {
      instructor::FixedParam fixed("gap");
      if (ImGui::SliderFloat("gap d", &gap, 0.0f, 1.0f, "%.3f")) {
        p9_gap_ = static_cast<double>(gap);
        sample_p9();
      }
    }
    {
      instructor::FixedParam fixed("mc_trials");
      if (param_slider(kLabVisibilityTrials, "samples", mc_trials_, 100, 100000)) sample_p9();
    }
    ImGui::PopItemWidth();
    ImGui::Text("(x1, y1) = (%.3f, %.3f), d = %.3f", p9_x_, p9_y_, p9_gap_);
    const ImVec4 key = key_colour();
    if (instructor::hidden("p9_probability"))
      instructor::hidden_line("p, exact and by Monte Carlo");
    else
      formula(ui::format("p = %.5f exact, %.5f by Monte Carlo", p9_breakdown(p9_x_, p9_y_, p9_gap_).probability, mc_.estimate), &key);
    exact_and_monte_carlo();
  }

  void exact_and_monte_carlo() {
    const P9Breakdown b = p9_breakdown(p9_x_, p9_y_, p9_gap_);
    const ImVec4 key = key_colour();
    if (panel::fold("Exact, by cases")) {
    dim_text_wrapped("All of the left half is in sight, and of the right half the cone between the rays through "
                     "the opening's ends. A ray through height a there has slope s = (a − y1)/(½ − x1) and reaches "
                     "a + s/2 at x = 1; A is the area below it.");
    if (instructor::hidden("p9_probability")) {
      // The method stays; its numbers are P9's answer.
      formula("p = ½ + A_up − A_lo", &key);
      instructor::hidden_line("the cases, the areas and p");
    } else {
      ImGui::TextWrapped("Case: upper ray → %s, lower ray → %s", p9_exit_name(b.upper.exit), p9_exit_name(b.lower.exit));
      ray_lines("upper", "A_up", b.upper);
      ray_lines("lower", "A_lo", b.lower);
      formula(ui::format("p = ½ + A_up − A_lo = 0.5 + %.5f − %.5f = %.5f", b.upper.area_under, b.lower.area_under,
                         b.probability),
              &key);
    }
    }

    if (!panel::fold("Monte Carlo")) return;
    if (instructor::hidden("p9_probability")) {
      instructor::hidden_line(ui::format("%lld samples: the estimate and its interval", mc_.trials).c_str());
    } else {
      formula(ui::format("%lld samples: estimate %.5f", mc_.trials, mc_.estimate));
      formula(ui::format("95%% interval [%.5f, %.5f]", mc_.low, mc_.high));
      if (exact_in_interval())
        ImGui::TextColored(theme::vec4(theme::kTextGood), "the exact p is inside it");
      else
        ImGui::TextColored(theme::vec4(theme::kTextBad), "the exact p is outside it");
      dim_text_wrapped("(1 draw in 20 misses on average: chance, not an error)");
    }
    instructor::FixedParam fixed("mc_seed");
    if (ui::small_button("new samples")) {
      ++p9_seed_;
      sample_p9();
    }
  }

  // A sample set of its own for every point, gap and count (a function of them and the seed,
  // so the same view shows the same dots): one set reused everywhere would carry its one
  // chance excess, say 50.8% of its points on the left, to every point a student tries.
  void sample_p9() {
    std::uint64_t seed = p9_seed_;
    for (double v : {p9_x_, p9_y_, p9_gap_, static_cast<double>(mc_trials_)}) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &v, sizeof bits);
      seed = Rng(seed ^ bits).next_u64();
    }
    Rng rng(seed);
    long long seen = 0;
    mc_points_.clear();
    for (long long i = 0; i < mc_trials_; ++i) {
      const double x = rng.uniform01(), y = rng.uniform01();
      const bool visible = visible_in_p9(p9_x_, p9_y_, p9_gap_, x, y);
      seen += visible;
      if (mc_points_.size() < 3000) mc_points_.push_back({x, y, visible ? 1.0 : 0.0});
    }
    mc_ = wilson_interval(seen, mc_trials_);
  }

  void p9_view() {
    WorkspaceView& v = p9_view_;
    ImDrawList* dl = v.draw_list();
    v.push_clip();
    // The visible region: the left half, and the cone through the opening, clipped.
    const double lo = 0.5 - 0.5 * p9_gap_, hi = 0.5 + 0.5 * p9_gap_, run = 0.5 - p9_x_;
    const ImU32 shade = theme::with_alpha(theme::kSkyBlue, 70);
    dl->AddRectFilled(v.to_screen(Vec2(0, 1)), v.to_screen(Vec2(0.5, 0)), shade);
    // The cone clipped to the square lies between two rays clamped to [0, 1]: not convex when
    // both rays leave through the same edge (the clamped upper ray then bends the other way),
    // but x-monotone. So, strips between the x where either ray meets y = 0 or y = 1, each a
    // trapezoid, exactly; without anti-aliasing, which would draw the seams between strips.
    const double slope_lo = (lo - p9_y_) / run, slope_hi = (hi - p9_y_) / run;
    std::vector<double> xs = {0.5, 1.0};
    for (const auto& [y0, slope] : {std::pair{lo, slope_lo}, std::pair{hi, slope_hi}})
      for (double edge : {0.0, 1.0})
        if (slope != 0.0) {
          const double x = 0.5 + (edge - y0) / slope;
          if (x > 0.5 && x < 1.0) xs.push_back(x);
        }
    std::sort(xs.begin(), xs.end());
    const auto ray = [](double y0, double slope, double x) { return std::clamp(y0 + slope * (x - 0.5), 0.0, 1.0); };
    const ImDrawListFlags flags = dl->Flags;
    dl->Flags &= ~ImDrawListFlags_AntiAliasedFill;
    for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
      const double a = xs[i], b = xs[i + 1];
      dl->AddQuadFilled(v.to_screen(Vec2(a, ray(lo, slope_lo, a))), v.to_screen(Vec2(b, ray(lo, slope_lo, b))),
                        v.to_screen(Vec2(b, ray(hi, slope_hi, b))), v.to_screen(Vec2(a, ray(hi, slope_hi, a))), shade);
    }
    dl->Flags = flags;
    for (const auto& p : mc_points_) {
      const ImVec2 c = v.to_screen(Vec2(p[0], p[1]));
      dl->AddRectFilled(ImVec2(c.x - 1, c.y - 1), ImVec2(c.x + 1, c.y + 1),
                        p[2] > 0 ? theme::with_alpha(theme::kGreen, 160) : theme::with_alpha(theme::kVermillion, 160));
    }
    // The wall, the rays through the opening's ends, the point.
    v.draw_segment(Vec2(0.5, 0), Vec2(0.5, lo), theme::kInk, 4.0f);
    v.draw_segment(Vec2(0.5, hi), Vec2(0.5, 1), theme::kInk, 4.0f);
    for (double end : {lo, hi}) {
      const double far_y = end + (end - p9_y_) / run * 0.5;
      v.draw_segment(Vec2(p9_x_, p9_y_), Vec2(1.0, far_y), theme::with_alpha(theme::kBlue, 150), 1.5f);
    }
    v.draw_marker(Vec2(p9_x_, p9_y_), theme::kBlue, "P");
    v.pop_clip();
    // Where each ray leaves the right half, the edge that decides its case (over the frame).
    const P9Breakdown cases = p9_breakdown(p9_x_, p9_y_, p9_gap_);
    for (const P9Ray* r : {&cases.upper, &cases.lower})
      dl->AddCircleFilled(v.to_screen(Vec2(r->exit_x, r->exit_y)), 4.5f, theme::kBlue, 12);
    // Click or drag in the left half to move the point.
    if (v.hovered() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      const Vec2 m = v.mouse_world();
      const double x = std::clamp(m.x(), 0.0, 0.4999), y = std::clamp(m.y(), 0.0, 1.0);
      if (x != p9_x_ || y != p9_y_) {
        p9_x_ = x;
        p9_y_ = y;
        sample_p9();
      }
    }
  }

  Scene scene_;
  SceneEditor editor_;
  WorkspaceView scene_view_, p9_view_;
  Plot plot_;  // the bounds against n (a member: the JS API maps points through it)
  std::unique_ptr<CollisionWorld> world_;
  std::vector<Config> reference_path_;
  bool path_exists_ = false;
  bool too_dense_ = false;  // measure() would take more than a few frames' work: not measured
  int reference_samples_ = 3000;  // measure()'s reference run and Monte Carlo volume, fewer in a
  long volume_samples_ = 50000;   // dense scene; an experiment's first step uses the same
  int dim_ = 2;
  double length_ = 1, clearance_ = 0.05, free_volume_ = 1;
  double measured_length_ = 0, measured_clearance_ = 0, measured_volume_ = 0;
  std::vector<int> sample_counts_ = {20, 50, 100, 200, 500, 1000};
  char counts_text_[128] = "20,50,100,200,500,1000";
  int trials_ = static_cast<int>(kLabExperimentTrials.def);
  std::unique_ptr<Experiment> experiment_;
  int tab_ = 0;
  double target_ = 0.01;  // the failure probability P8's and the path's n are solved for
  double p9_x_ = 0.25, p9_y_ = 0.3, p9_gap_ = 0.1;
  long long mc_trials_ = static_cast<long long>(kLabVisibilityTrials.def);
  // The default view's draw lands inside its 95% interval (z = 1.5; seed 9's missed it at
  // z = 3.4, which looked like an error on first sight): the e2e test checks it.
  std::uint64_t p9_seed_ = 1;
  Proportion mc_;
  std::vector<std::array<double, 3>> mc_points_;
};

}  // namespace

CSL_REGISTER_LESSON(AnalysisLesson, "analysis", "PRM analysis", "Planning");

}  // namespace csl::app
