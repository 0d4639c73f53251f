// Lesson "Step PRM": the probabilistic roadmap method on a point robot, one step at a time.
// The workspace is the C-space here (Q = R^2): obstacles, samples, edges and path in one view.
// The sampler is a choice (uniform, Gaussian, bridge test, Halton): the planner is recorded
// (recording_planner.hpp) so that the draws Gaussian and bridge throw away can be shown.
#include <cstdio>
#include <memory>

#include "app/lessons/planner_session.hpp"
#include "app/lessons/prm_controls.hpp"
#include "app/lessons/recording_planner.hpp"
#include "app/lessons/sampler_controls.hpp"
#include "app/shell/bundled_scenes.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/lesson.hpp"
#include "app/shell/theme.hpp"
#include "app/views/drag_replay.hpp"
#include "app/views/draw.hpp"
#include "app/views/scene_editor.hpp"
#include "core/planning/planner_json.hpp"
#include "core/checking/scene_text.hpp"
#include "core/planning/planner_text.hpp"
#include "core/planning/prm_text.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;

class StepPrmLesson : public Lesson {
 public:
  StepPrmLesson() : scene_(bundled_scene("prm-demo")), session_(scene_, recorded(prm_factory(params_))) {}

  void on_show() override { session_.forget_log(); }

  void update(LabContext& ctx) override {
    session_.update(ctx, "ready: press Step or Play");
  }

  void panel(LabContext& ctx) override {
    ImGui::TextWrapped("PRM as the course states it: add q_init and q_final; draw n samples and keep the "
                       "free ones; connect close pairs whose straight line is free; search the graph.");
    ImGui::Spacing();
    if (prm_controls(params_, session_.world(), ctx, kLabPrmSamples, true)) rebuild(0);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", sampler_summary(params_.sampler));
    ImGui::PopTextWrapPos();
    ImGui::Separator();
    stats();
    ImGui::Separator();
    ImGui::TextDisabled("Obstacles (drawn in the view)");
    if (editor_.toolbar(scene_, ctx)) rebuild(session_.wanted_steps());
  }

  void views(LabContext& ctx, ImVec2 size) override {
    view_.begin("##prm-workspace", size, scene_.workspace_min, scene_.workspace_max);
    ctx.views["workspace"] = &view_;
    ctx.views["cspace"] = &view_;  // a point robot: the workspace is its C-space
    view_.draw_grid("x", "y");
    view_.push_clip();
    for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) view_.draw_obstacle(scene_.obstacles[i]);
    refresh_labels();
    const Space& space = session_.world().space();
    roadmap_layer_.draw(view_, space, prm().roadmap(), labels_, throttle_(session_.version(), session_.busy()));
    // Gaussian and bridge draws thrown away (many of them in free space): crosses, apart from the
    // kept samples' squares. The planner's own sampler: during a replay, the old one's.
    if (sampler_rejects_free_draws(prm().params().sampler)) draw_rejected_samples(view_, recording().rejected());
    if (prm().solved()) draw_path(view_, space, prm().roadmap(), prm().path());
    if (replay_pending() || session_.replaying()) {
      // The old roadmap faded under the obstacles where they are now.
      draw_replay_pending(view_, session_.replaying() ? replaying_text(session_) : std::string());
      for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) view_.draw_obstacle(scene_.obstacles[i]);
    } else {
      draw_current_step();
    }
    view_.draw_marker(Vec2(scene_.start[0], scene_.start[1]), theme::kStart, "S", !session_.world().is_free(scene_.start));
    view_.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G", !session_.world().is_free(scene_.goal));
    view_.pop_clip();
    // An edit replaces the session's world: nothing may hold on to the old one past here.
    if (editor_.edit(view_, scene_, ctx, {})) session_.edited(scene_, editor_.dragging());
    if (replay_pending() && !editor_.dragging()) session_.edited(scene_, false);  // released
    if (!session_.world().is_free(scene_.start) || !session_.world().is_free(scene_.goal))
      view_.draw_label(scene_.workspace_min, "start or goal inside an obstacle: no path can exist",
                       theme::kWarning, ImVec2(4, 8));
    // Above the view's top left corner, clear of the y axis's label.
    view_.draw_label(Vec2(scene_.workspace_min.x(), scene_.workspace_max.y()),
                     "point robot: workspace = C-space, Q = R²", theme::kLabel, ImVec2(16, -22));
    editor_.help_window();
  }

  Scene* scene() override { return &scene_; }
  std::vector<LessonView> views_kept() override {  // (its "cspace" is this one view)
    return {{"workspace", &view_, scene_.workspace_min, scene_.workspace_max}};
  }
  SceneEditor* editor() override { return &editor_; }
  bool accept_scene(const Scene& s, std::string& why) override {
    if (!std::holds_alternative<PointRobot>(s.robot)) {
      why = "this lesson plans for a point robot; the scene has a '" + std::string(robot_type_name(s.robot)) + "' robot";
      return false;
    }
    // The parameters were priced in the old scene: a denser one may cost past the lab's budget.
    if (!(why = scene_budget_problem(params_, s)).empty()) return false;
    editor_.replace(scene_, s);
    rebuild(0);
    return true;
  }
  bool undo() override { return editor_.undo(scene_) && (rebuild(session_.wanted_steps()), true); }
  bool redo() override { return editor_.redo(scene_) && (rebuild(session_.wanted_steps()), true); }

  json state(const json& args) const override {
    json out = planner_state_json(prm(), args.value("roadmap", false));
    out["params"] = params();
    out["rejected"] = recording().rejected().size();
    out["replay_pending"] = replay_pending();
    out["planner_builds"] = session_.builds();
    out["running"] = running_json(session_);
    return out;
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    // The sampler is this lesson's (the torus's PRM has none); the rest is PRM's, priced with
    // the new sampler (a bridge draw tests up to three configurations).
    PrmParams next = params_;
    json rest = j;
    if (j.contains("sampler")) {
      next.sampler = sampler_from_json("sampler", j.at("sampler"));
      rest.erase("sampler");
    }
    params_ = prm_params_from_json(rest, next, session_.world());
    rebuild(0);
  }

  json params() const override {
    json out = prm_params_json(params_);
    out["sampler"] = params_.sampler.name();
    return out;
  }
  std::vector<ParamField> param_fields() const override {
    std::vector<ParamField> out = prm_param_fields(kLabPrmSamples);
    out.push_back(sampler_field("sampler", "sampler"));
    return out;
  }

  std::string describe() const override {
    // The planner's scene: during a drag that would replay slowly it is the one from before.
    const SamplerSpec& sampler = prm().params().sampler;
    const std::string draws =
        sampler.kind == SamplerSpec::Kind::Uniform
            ? ""
            : " Samples come from the sampler " + sampler.name() + ": " + sampler_summary(sampler) +
                  (sampler_rejects_free_draws(sampler)
                       ? " " + std::to_string(recording().rejected().size()) + " draws were thrown away so far."
                       : "");
    return describe_scene(session_.planned_scene(), prm().world()) + " " +
           describe_planner(prm(), !instructor::hidden("path_length")) + draws +
           (replay_pending() ? " The roadmap is the scene's before the drag; it is replayed at the release." : "");
  }

 public:
  Stepper* stepper() override { return &session_; }

 private:
  const Prm& prm() const { return session_.shown_as<Prm>(); }
  const RecordingPlanner& recording() const { return *session_.recording(); }
  // A new planner for the current scene and parameters, replayed to `steps` (an edit keeps the
  // student at the same step, with the same seed).
  void rebuild(long steps) {
    // A smaller workspace makes the same r cover more pairs.
    keep_within_budget(params_, robot_space(scene_.robot, scene_.workspace_min, scene_.workspace_max));
    session_.rebuild(scene_, recorded(prm_factory(params_)), steps);
    labels_at_ = -1;
    check_at_ = -1;
    session_.forget_log();
  }
  bool replay_pending() const { return session_.replay_pending(); }

  void refresh_labels() {
    if (labels_at_ == session_.version()) return;
    labels_ = session_.shown().component_labels();
    labels_at_ = session_.version();
  }


  void draw_current_step() {
    const Prm& planner = prm();
    if (planner.steps() == 0) return;
    const PrmEvent& e = planner.last_event();
    const auto& v = planner.roadmap().vertices;
    ImDrawList* dl = view_.draw_list();
    const auto at = [&](int i) { return view_.to_screen(Vec2(v[static_cast<std::size_t>(i)][0], v[static_cast<std::size_t>(i)][1])); };
    switch (e.kind) {
      case PrmEvent::Kind::SampleAccepted:
      case PrmEvent::Kind::SampleRejected: {
        const ImVec2 s = view_.to_screen(Vec2(e.q[0], e.q[1]));
        const bool ok = e.kind == PrmEvent::Kind::SampleAccepted;
        dl->AddCircle(s, 9.0f, ok ? theme::kFree : theme::kHit, 24, 2.5f);
        if (!ok) {
          dl->AddLine(ImVec2(s.x - 5, s.y - 5), ImVec2(s.x + 5, s.y + 5), theme::kHit, 2.0f);
          dl->AddLine(ImVec2(s.x - 5, s.y + 5), ImVec2(s.x + 5, s.y - 5), theme::kHit, 2.0f);
        }
        char text[24];
        std::snprintf(text, sizeof text, "#%d", e.sample);
        view_.draw_label(Vec2(e.q[0], e.q[1]), text, theme::kCurrent, ImVec2(10, -20));
        break;
      }
      case PrmEvent::Kind::Neighbors:
        for (const Neighbor& nb : planner.candidates()) dl->AddLine(at(e.vertex), at(nb.index), theme::kCurrent, 1.5f);
        dl->AddCircle(at(e.vertex), 8.0f, theme::kCurrent, 24, 2.5f);
        break;
      case PrmEvent::Kind::EdgeAdded:
      case PrmEvent::Kind::EdgeRejected:
      case PrmEvent::Kind::PathEdgeRemoved: {
        const bool ok = e.kind == PrmEvent::Kind::EdgeAdded;
        dl->AddLine(at(e.vertex), at(e.other), ok ? theme::kFree : theme::kHit, 3.0f);
        // What the edge checker tested along it (recomputed: the check is deterministic).
        if (check_at_ != session_.version()) {
          const auto spec = e.kind == PrmEvent::Kind::PathEdgeRemoved ? EdgeCheckerSpec::parse("bisection")
                                                                      : planner.params().checker;
          check_ = check_edge(planner.world(), spec, v[static_cast<std::size_t>(e.vertex)], v[static_cast<std::size_t>(e.other)], true);
          check_at_ = session_.version();
        }
        for (const EdgeEvent& ev : check_.trace)
          if (ev.kind == EdgeEvent::Kind::Evaluate)
            dl->AddCircleFilled(view_.to_screen(Vec2(ev.q[0], ev.q[1])), 3.5f, ev.free ? theme::kFree : theme::kHit, 12);
        break;
      }
      default:
        break;
    }
  }

  void stats() {
    const Prm& planner = prm();
    const Roadmap& r = planner.roadmap();
    ImGui::Text("step %ld   phase: %s", planner.steps(), phase_name(planner.phase()));
    ImGui::Text("|V| = %zu   |E| = %ld   components: %d", r.vertices.size(), planner.edges_alive(), planner.components());
    ImGui::Text("samples drawn %d of %d", planner.samples_drawn(), params_.samples);
    ImGui::Text("edge checks %ld   evaluations %ld", planner.edge_checks(), planner.evaluations());
    if (planner.solved() && instructor::hidden("path_length"))
      ImGui::TextColored(theme::vec4(theme::kTextGood), "path found: %zu edges, its length %s", planner.path().size() - 1,
                         instructor::kHidden);
    else if (planner.solved())
      ImGui::TextColored(theme::vec4(theme::kTextGood), "path found: length %.4f, %zu edges", planner.path_length(),
                         planner.path().size() - 1);
    else if (planner.done())
      ImGui::TextColored(theme::vec4(theme::kTextBad), "no path found");
    if (replay_pending()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("(the roadmap of the scene before this drag: replayed at the release)");
      ImGui::PopTextWrapPos();
    }
  }

  Scene scene_;
  SceneEditor editor_;
  WorkspaceView view_;
  PrmParams params_;
  PlannerSession session_;  // after scene_ and params_, from which it starts
  std::vector<int> labels_;
  long long labels_at_ = -1;
  EdgeCheckResult check_;
  long long check_at_ = -1;
  RoadmapLayer roadmap_layer_;
  RedrawThrottle throttle_;
};

}  // namespace

CSL_REGISTER_LESSON(StepPrmLesson, "step-prm", "Step PRM", "Planning");

}  // namespace csl::app
