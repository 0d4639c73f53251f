// Lesson "Step PRM": the probabilistic roadmap method on a point robot, one step at a time.
// The workspace is the C-space here (Q = R^2): obstacles, samples, edges and path in one view.
#include <cstdio>
#include <memory>

#include "app/bundled_scenes.hpp"
#include "app/drag_replay.hpp"
#include "app/draw.hpp"
#include "app/js_api.hpp"
#include "app/lesson.hpp"
#include "app/prm_controls.hpp"
#include "app/prm_text.hpp"
#include "app/scene_editor.hpp"
#include "app/theme.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;

class StepPrmLesson : public Lesson {
 public:
  StepPrmLesson() : scene_(bundled_scene("prm-demo")) { rebuild(0); }

  void update(LabContext& ctx) override {
    const int due = ctx.playback.due(static_cast<double>(ImGui::GetIO().DeltaTime));
    for (int i = 0; i < due && !prm_->done(); ++i) step_forward();
    if (prm_->done()) ctx.playback.playing = false;
    log_new_steps(ctx);
  }

  void panel(LabContext& ctx) override {
    ImGui::TextWrapped("PRM as the course states it: add q_init and q_final; draw n samples and keep the "
                       "free ones; connect close pairs whose straight line is free; search the graph.");
    ImGui::Spacing();
    if (prm_controls(params_, world_->space())) rebuild(0);
    ImGui::Separator();
    stats();
    ImGui::Separator();
    ImGui::TextDisabled("Obstacles (drawn in the view)");
    if (editor_.toolbar(scene_, ctx)) rebuild(prm_->steps());
  }

  void views(LabContext& ctx, ImVec2 size) override {
    view_.begin("##prm-workspace", size, scene_.workspace_min, scene_.workspace_max);
    ctx.views["workspace"] = &view_;
    ctx.views["cspace"] = &view_;  // a point robot: the workspace is its C-space
    view_.draw_grid("x", "y");
    view_.push_clip();
    for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) view_.draw_obstacle(scene_.obstacles[i]);
    refresh_labels();
    roadmap_layer_.draw(view_, world_->space(), prm_->roadmap(), labels_, roadmap_version());
    if (prm_->solved()) draw_path(view_, world_->space(), prm_->roadmap(), prm_->path());
    if (replay_pending()) {
      // The old roadmap faded under the obstacles where they are now.
      draw_replay_pending(view_);
      for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) view_.draw_obstacle(scene_.obstacles[i]);
    } else {
      draw_current_step();
    }
    view_.draw_marker(Vec2(scene_.start[0], scene_.start[1]), theme::kStart, "S", !world_->is_free(scene_.start));
    view_.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G", !world_->is_free(scene_.goal));
    view_.pop_clip();
    if (editor_.edit(view_, scene_, ctx, {})) scene_edited();
    if (replay_pending() && !editor_.dragging()) rebuild(prm_->steps());  // released
    if (!world_->is_free(scene_.start) || !world_->is_free(scene_.goal))
      view_.draw_label(scene_.workspace_min, "start or goal inside an obstacle: no path can exist",
                       theme::kWarning, ImVec2(4, 8));
    // Above the view's top left corner, clear of the y axis's label.
    view_.draw_label(Vec2(scene_.workspace_min.x(), scene_.workspace_max.y()),
                     "point robot: workspace = C-space, Q = R²", theme::kLabel, ImVec2(16, -22));
    editor_.help_window();
  }

  Scene* scene() override { return &scene_; }
  bool accept_scene(const Scene& s, std::string& why) override {
    if (!std::holds_alternative<PointRobot>(s.robot)) {
      why = "this lesson plans for a point robot; the scene has a '" + std::string(robot_type_name(s.robot)) + "' robot";
      return false;
    }
    editor_.replace(scene_, s);
    rebuild(0);
    return true;
  }
  bool undo() override { return editor_.undo(scene_) && (rebuild(prm_->steps()), true); }
  bool redo() override { return editor_.redo(scene_) && (rebuild(prm_->steps()), true); }

  json state(const json& args) const override {
    const Roadmap& r = prm_->roadmap();
    json path = json::array();
    for (int v : prm_->path()) path.push_back(config_to_json(r.vertices[static_cast<std::size_t>(v)]));
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(roadmap_hash(r)));
    json out{{"params", prm_params_json(params_)},
             {"phase", phase_name(prm_->phase())},
             {"steps", prm_->steps()},
             {"done", prm_->done()},
             {"nodes", r.vertices.size()},
             {"edges", prm_->edges_alive()},
             {"components", const_cast<Prm&>(*prm_).components()},
             {"edge_checks", prm_->edge_checks()},
             {"evaluations", prm_->evaluations()},
             {"samples_drawn", prm_->samples_drawn()},
             {"solved", prm_->solved()},
             {"replay_pending", replay_pending()},
             {"planner_builds", rebuilds_},
             {"path", path},
             {"path_length", prm_->solved() ? json(prm_->path_length()) : json(nullptr)},
             {"roadmap_hash", hash},
             {"last_event", prm_->steps() > 0 ? json(event_kind_name(prm_->last_event().kind)) : json(nullptr)}};
    if (args.value("roadmap", false)) {
      json vertices = json::array(), edges = json::array();
      for (const Config& q : r.vertices) vertices.push_back(config_to_json(q));
      for (const RoadmapEdge& e : r.edges)
        if (e.alive) edges.push_back(json::array({e.a, e.b}));
      out["vertices"] = vertices;
      out["edge_list"] = edges;
    }
    return out;
  }

  void set_params(const json& j) override {
    params_ = prm_params_from_json(j, params_, world_->space());
    rebuild(0);
  }

  json params() const override { return prm_params_json(params_); }

  bool steppable() const override { return true; }
  long steps() const override { return prm_->steps(); }
  bool finished() const override { return prm_->done(); }
  void step_forward() override {
    if (!prm_->done()) prm_->step();
  }
  void step_back() override {
    if (prm_->steps() > 0) prm_->run_to(prm_->steps() - 1);
  }
  void finish_phase() override { prm_->finish_phase(); }
  void run_all() override { prm_->run(); }
  void reset() override { prm_->reset(); }
  void run_to(long steps) override { prm_->run_to(steps); }

 private:
  // A fresh world and planner for the current scene and parameters, replayed to `steps` (an
  // edit keeps the student at the same step, with the same seed).
  void rebuild(long steps) {
    if (!planned_world_) planned_world_ = std::move(world_);  // prm_ points into it: kept until replaced
    world_ = std::make_unique<CollisionWorld>(scene_);
    keep_within_budget(params_, world_->space());  // a smaller workspace makes the same r cover more pairs
    prm_ = std::make_unique<Prm>(*world_, scene_.start, scene_.goal, params_);
    planned_world_.reset();
    planned_scene_ = scene_;
    prm_->run_to(steps);
    labels_at_ = -1;
    logged_through_ = -1;
    check_at_ = -1;
    ++rebuilds_;
  }

  // The scene changed (the editor): replay, unless a drag goes on and the replay is too long for
  // a frame (see drag_replay.hpp). Then the planner keeps the world and scene it ran in, and
  // world_ follows the drag for what is drawn from it (the markers' warnings).
  // A drag back to where it was pressed gives back the scene the planner ran in, exactly (see
  // SceneEditor::continue_drag): its world again, and nothing to replay.
  void scene_edited() {
    if (same_scene(scene_, planned_scene_)) {
      if (planned_world_) world_ = std::move(planned_world_);
      return;
    }
    if (!editor_.dragging() || replay_is_live(*prm_)) return rebuild(prm_->steps());
    if (!planned_world_) planned_world_ = std::move(world_);
    world_ = std::make_unique<CollisionWorld>(scene_);
  }
  bool replay_pending() const { return planned_world_ != nullptr; }

  // Changes whenever the roadmap may have: a step, a replay or a rebuild.
  long long roadmap_version() const { return static_cast<long long>(prm_->steps()) + (rebuilds_ << 32); }

  void refresh_labels() {
    if (labels_at_ == prm_->steps()) return;
    labels_ = prm_->component_labels();
    labels_at_ = prm_->steps();
  }

  // The event log follows the planner: after a replay it says where we are, then each new step.
  void log_new_steps(LabContext& ctx) {
    if (logged_through_ == prm_->steps()) return;
    if (logged_through_ < 0 || prm_->steps() < logged_through_ || prm_->steps() > logged_through_ + 1) {
      ctx.log.clear();
      ctx.log.add(0, prm_->steps() == 0 ? std::string("ready: press Step or Play")
                                        : "at step " + std::to_string(prm_->steps()) + " (" +
                                              phase_name(prm_->phase()) + ")");
    }
    if (prm_->steps() > 0) ctx.log.add(prm_->steps(), describe(prm_->last_event(), *prm_, planned_scene_));
    logged_through_ = prm_->steps();
  }

  void draw_current_step() {
    if (prm_->steps() == 0) return;
    const PrmEvent& e = prm_->last_event();
    const auto& v = prm_->roadmap().vertices;
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
        for (const Neighbor& nb : prm_->candidates()) dl->AddLine(at(e.vertex), at(nb.index), theme::kCurrent, 1.5f);
        dl->AddCircle(at(e.vertex), 8.0f, theme::kCurrent, 24, 2.5f);
        break;
      case PrmEvent::Kind::EdgeAdded:
      case PrmEvent::Kind::EdgeRejected:
      case PrmEvent::Kind::PathEdgeRemoved: {
        const bool ok = e.kind == PrmEvent::Kind::EdgeAdded;
        dl->AddLine(at(e.vertex), at(e.other), ok ? theme::kFree : theme::kHit, 3.0f);
        // What the edge checker tested along it (recomputed: the check is deterministic).
        if (check_at_ != prm_->steps()) {
          const auto spec = e.kind == PrmEvent::Kind::PathEdgeRemoved ? EdgeCheckerSpec::parse("bisection")
                                                                      : prm_->params().checker;
          check_ = check_edge(prm_->world(), spec, v[static_cast<std::size_t>(e.vertex)], v[static_cast<std::size_t>(e.other)], true);
          check_at_ = prm_->steps();
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
    const Roadmap& r = prm_->roadmap();
    ImGui::Text("step %ld   phase: %s", prm_->steps(), phase_name(prm_->phase()));
    ImGui::Text("|V| = %zu   |E| = %ld   components: %d", r.vertices.size(), prm_->edges_alive(), prm_->components());
    ImGui::Text("samples drawn %d of %d", prm_->samples_drawn(), params_.samples);
    ImGui::Text("edge checks %ld   evaluations %ld", prm_->edge_checks(), prm_->evaluations());
    if (prm_->solved())
      ImGui::TextColored(ImVec4(0.0f, 0.45f, 0.3f, 1.0f), "path found: length %.4f, %zu edges", prm_->path_length(),
                         prm_->path().size() - 1);
    else if (prm_->done())
      ImGui::TextColored(ImVec4(0.7f, 0.25f, 0.0f, 1.0f), "no path found");
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
  // The scene's world; prm_ points into it, except while a replay waits for the end of a drag:
  // then prm_ points into planned_world_ (else null; both declared before prm_, so that they
  // outlive it), and planned_scene_ (otherwise equal to scene_) is the scene it ran in, whose
  // obstacles the event log names.
  std::unique_ptr<CollisionWorld> world_;
  Scene planned_scene_;
  std::unique_ptr<CollisionWorld> planned_world_;
  std::unique_ptr<Prm> prm_;
  std::vector<int> labels_;
  long labels_at_ = -1;
  EdgeCheckResult check_;
  long check_at_ = -1;
  long logged_through_ = -1;
  long long rebuilds_ = 0;
  RoadmapLayer roadmap_layer_;
};

}  // namespace

CSL_REGISTER_LESSON(StepPrmLesson, "step-prm", "Step PRM", "Planning");

}  // namespace csl::app
