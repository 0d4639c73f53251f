// Lesson "2-link arm and the torus": the arm in its workspace and its configuration space
// T^2 = S^1 x S^1 side by side, linked both ways (pose the arm from the C-space; drag its links
// in the workspace), with the C-obstacles drawn from the exact analytic map; PRM grown on the
// torus with the wrapped metric (edges across a seam leave one side of the square and come back
// on the other); the torus in 3-D with the C-obstacles on its surface; and a guided exercise on
// loops that can and cannot be shrunk.
#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>

#include "app/lessons/planner_session.hpp"
#include "core/checking/scene_text.hpp"
#include "core/planning/planner_text.hpp"
#include "app/lessons/prm_controls.hpp"
#include "app/shell/bundled_scenes.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/lesson.hpp"
#include "app/shell/panel.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "app/views/drag_replay.hpp"
#include "app/views/draw.hpp"
#include "app/views/field_draw.hpp"
#include "app/views/scene_editor.hpp"
#include "app/views/split.hpp"
#include "app/views/surface_view.hpp"
#include "core/base/angles.hpp"
#include "core/planning/planner_json.hpp"
#include "core/planning/prm_text.hpp"
#include "core/teaching/cspace_map.hpp"
#include "core/teaching/cspace_quads.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;

constexpr std::size_t kTrail = 400;

enum class Exercise { None, Around, Shrink };

class TorusLesson : public Lesson {
 public:
  TorusLesson() : scene_(bundled_scene("arm-2link")), session_(scene_, params_) {
    q_ = pose_beside_markers();
    rebuild_map();
  }

  void on_show() override { session_.forget_log(); }

  void update(LabContext& ctx) override {
    session_.update(ctx, "ready: press Step or Play to grow a roadmap on the torus");
    // The arm walks along the found path, or along the exercise's loop, again and again.
    const double dt = static_cast<double>(ImGui::GetIO().DeltaTime);
    if (animate_ && (prm().solved() || exercise_ != Exercise::None)) {
      phase_ = std::fmod(phase_ + 0.12 * dt, 1.0);
      q_ = exercise_ != Exercise::None ? loop_at(phase_) : path_at(phase_);
      push_trail();
    }
  }

  void panel(LabContext& ctx) override {
    ImGui::TextWrapped("Two joint angles fix the arm: its C-space is the torus T² = S¹ × S¹, a square whose "
                       "opposite edges are glued. Drag in the square to pose the arm, or drag its links or the "
                       "obstacles.");
    ImGui::Text("q = (%.3f, %.3f)  %s", q_[0], q_[1], world().is_free(q_) ? "free" : "in collision");
    ImGui::Checkbox("animate the path / loop", &animate_);
    ui::flow(ui::button_width("clear trail"));
    if (ui::small_button("clear trail")) trail_.clear();
    // The right-hand view on one row: a heading of its own cost the panel a line.
    ImGui::AlignTextToFramePadding();
    ImGui::TextDisabled("right:");
    ImGui::SameLine();
    {
      instructor::FixedParam fixed("view");
      ImGui::RadioButton("square", &right_view_, 0);
      ui::flow(ui::toggle_width("torus (3-D)"));
      ImGui::RadioButton("torus (3-D)", &right_view_, 1);
      ui::flow(ui::toggle_width("both"));
      ImGui::RadioButton("both", &right_view_, 2);
    }

    if (panel::fold("PRM on the torus")) {
      if (prm_controls(params_, world(), ctx, kLabTorusSamples)) rebuild(0);
      const int parts = prm().components();
      ui::text_flow(ui::format("|V| = %zu  |E| = %ld (%d across a seam), %d component%s", prm().roadmap().vertices.size(),
                               prm().edges_alive(), seam_edges(), parts, parts == 1 ? "" : "s"));
      if (prm().solved() && instructor::hidden("path_length"))
        ImGui::TextColored(theme::vec4(theme::kTextGood), "path found, its length %s", instructor::kHidden);
      else if (prm().solved())
        ImGui::TextColored(theme::vec4(theme::kTextGood), "path found, length %.3f rad", prm().path_length());
      else if (prm().done()) ImGui::TextColored(theme::vec4(theme::kTextBad), "no path found");
      if (replay_pending()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("(the roadmap of the scene before this drag: replayed at the release)");
        ImGui::PopTextWrapPos();
      }
    }

    if (panel::fold("Exercise: loops on the torus")) {
      bool started = false;
      if (ImGui::Button("a loop around the torus")) started = (start_exercise(Exercise::Around), true);
      web::record_control("torus-loop-around");
      ui::flow(ui::button_width("a loop that shrinks"));
      if (ImGui::Button("a loop that shrinks")) started = (start_exercise(Exercise::Shrink), true);
      web::record_control("torus-loop-shrink");
      if (exercise_ == Exercise::Around)
        ImGui::TextWrapped("θ₁ makes a full turn: the point leaves the square on the right and comes back on the "
                           "left, because the edges are the same place. On the torus this loop goes around the hole: "
                           "no continuous change of it shrinks it to a point. The arm turns all the way round.");
      if (exercise_ == Exercise::Shrink)
        ImGui::TextWrapped("A small circle in the square is a loop that can be pulled in to a point, in the square "
                           "and on the torus alike: the arm only wiggles.");
      if (exercise_ != Exercise::None) {
        ImGui::TextWrapped("%s", loop_blocked() ? "Here the loop crosses C-obstacles: the arm could not make this "
                                                  "motion. The loop shows the torus's shape, not a path."
                                                : "Here the whole loop is free.");
        if (ui::small_button("stop the exercise")) exercise_ = Exercise::None;
        web::record_control("torus-loop-stop");
        // The text the button brought is what the student looks for next: scrolled into view.
        if (started) scroll_to_exercise_ = 2;
        if (scroll_to_exercise_ > 0 && --scroll_to_exercise_ == 0) ImGui::SetScrollHereY(1.0f);
      }
    }
    // Folded at first: posing the arm and its torus come first (and a first visit's panel, with
    // the welcome above it, fits 1280 x 800); the keys D, P, W, V edit with it folded too.
    if (panel::fold("Obstacles", false)) {
      if (editor_.toolbar(scene_, ctx)) rebuild(session_.wanted_steps());
    }
  }

  void views(LabContext& ctx, ImVec2 size) override {
    const Split s = split(size);
    workspace(ctx, s.first);
    between(s);
    ImGui::BeginGroup();
    // The 3-D torus, recorded for status().layout (it is not a WorkspaceView).
    const auto torus_in = [&](ImVec2 at_size) {
      const ImVec2 at = ImGui::GetCursorScreenPos();
      torus(at_size);
      ctx.areas["torus"] = {at, ImVec2(at.x + at_size.x, at.y + at_size.y)};
    };
    if (right_view_ == 0) cspace(ctx, s.second);
    if (right_view_ == 1) torus_in(s.second);
    if (right_view_ == 2) {
      const Split both = split(s.second);
      cspace(ctx, both.first);
      between(both);
      torus_in(both.second);
    }
    ImGui::EndGroup();
    editor_.help_window();
  }

  Scene* scene() override { return &scene_; }
  std::vector<LessonView> views_kept() override {
    return {{"workspace", &view_, scene_.workspace_min, scene_.workspace_max},
            {"cspace", &cspace_view_, Vec2(-kPi, -kPi), Vec2(kPi, kPi)},
            {"torus", nullptr, Vec2::Zero(), Vec2::Zero(), &torus_view_}};
  }
  SceneEditor* editor() override { return &editor_; }
  bool accept_scene(const Scene& s, std::string& why) override {
    if (!is_two_link_arm(s.robot)) {
      why = std::string("this lesson is about the 2-link arm (robot type 'arm2'); the scene has a '") +
            robot_type_name(s.robot) + "' robot with " + std::to_string(robot_dof(s.robot)) + " coordinates";
      return false;
    }
    // The parameters were priced in the old scene: a denser one may cost past the lab's budget.
    if (!(why = scene_budget_problem(params_, s)).empty()) return false;
    editor_.replace(scene_, s);
    trail_.clear();
    rebuild(0);
    q_ = pose_beside_markers();  // (in the new scene's world, which rebuild() made)
    return true;
  }
  bool undo() override { return editor_.undo(scene_) && (rebuild(session_.wanted_steps()), true); }
  bool redo() override { return editor_.redo(scene_) && (rebuild(session_.wanted_steps()), true); }

  json state(const json& args) const override {
    json out{{"q", config_to_json(q_)},
             {"q_free", world().is_free(q_)},
             {"start", config_to_json(scene_.start)},
             {"goal", config_to_json(scene_.goal)},
             {"free_fraction", free_fraction_},
             {"link1_blocked", json::array()},
             {"trail", trail_.size()},
             {"view", right_view_ == 0 ? "square" : right_view_ == 1 ? "torus" : "both"},
             {"exercise", exercise_ == Exercise::None ? "none" : exercise_ == Exercise::Around ? "around" : "shrink"},
             {"animate", animate_},
             {"workspace_caption", workspace_caption() ? json(workspace_caption()) : json(nullptr)},
             {"prm", planner_state_json(prm(), false)}};
    out["prm"]["params"] = prm_params_json(params_);
    out["prm"]["seam_crossing_edges"] = seam_edges();
    out["prm"]["replay_pending"] = replay_pending();
    out["prm"]["planner_builds"] = session_.builds();
    out["prm"]["running"] = running_json(session_);
    for (const AngleInterval& i : map_->link1_blocked()) out["link1_blocked"].push_back({i.lo, i.hi});
    if (args.contains("blocked_at")) {
      // The map's answer at given configurations: [[theta1, theta2], ...] -> [bool, ...].
      json at = json::array();
      for (const json& p : args["blocked_at"])
        if (p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number())
          at.push_back(map_->blocked(p[0].get<double>(), p[1].get<double>()));
      out["blocked_at"] = at;
    }
    return out;
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    json rest = j;
    const json prm_part = take_prm_params(rest);
    std::optional<Config> q;
    int view = right_view_;
    std::optional<Exercise> ex;
    for (auto it = rest.begin(); it != rest.end(); ++it) {
      const std::string& k = it.key();
      if (k == "q") {
        if (!it->is_array() || it->size() != 2 || !(*it)[0].is_number() || !(*it)[1].is_number())
          throw ApiError("q: [theta1, theta2]");
        q = config({(*it)[0].get<double>(), (*it)[1].get<double>()});
        if (!std::isfinite((*q)[0]) || !std::isfinite((*q)[1])) throw ApiError("q: finite angles");
      } else if (k == "view") {
        if (*it != "square" && *it != "torus" && *it != "both") throw ApiError("view: square, torus or both");
        view = *it == "square" ? 0 : *it == "torus" ? 1 : 2;
      } else if (k == "exercise") {
        if (*it != "none" && *it != "around" && *it != "shrink") throw ApiError("exercise: none, around or shrink");
        ex = *it == "none" ? Exercise::None : *it == "around" ? Exercise::Around : Exercise::Shrink;
      } else {
        throw ApiError("unknown parameter \"" + k + "\"");
      }
    }
    const PrmParams p = prm_params_from_json(prm_part, params_, world(), kLabTorusSamples);
    right_view_ = view;
    if (q) {
      q_ = world().space().wrap(*q);
      push_trail();
    }
    if (ex) start_exercise(*ex);
    if (!prm_part.empty()) {
      params_ = p;
      rebuild(0);
    }
  }

  json params() const override {
    json p = prm_params_json(params_);
    p["q"] = config_to_json(q_);
    p["view"] = right_view_ == 0 ? "square" : right_view_ == 1 ? "torus" : "both";
    return p;
  }
  std::vector<ParamField> param_fields() const override {
    std::vector<ParamField> f = prm_param_fields(kLabTorusSamples);
    f.push_back({"q", "arm configuration", nullptr, {}, "theta1, theta2 in radians (theta2 relative to link 1)"});
    f.push_back({"view", "right-hand view", nullptr, {"square", "torus", "both"}});
    return f;
  }

  std::string describe() const override {
    return describe_scene(scene_, world()) + " The arm is at " + config_text(q_) + " radians, " +
           (world().is_free(q_) ? "free" : "in collision") + ". The roadmap on the torus: " +
           describe_planner(prm(), !instructor::hidden("path_length"));
  }

 public:
  Stepper* stepper() override { return &session_; }

 private:
  const Prm& prm() const { return session_.shown_as<Prm>(); }
  const CollisionWorld& world() const { return session_.world(); }

  // After any change of the scene or the parameters: the planner (replayed to `steps`) and the
  // exact C-obstacle map.
  void rebuild(long steps) {
    keep_within_budget(params_, robot_space(scene_.robot, scene_.workspace_min, scene_.workspace_max));
    session_.rebuild(scene_, params_, steps);
    rebuild_map();
    session_.forget_log();
  }

  void rebuild_map() {
    map_ = std::make_unique<ArmCSpaceMap>(std::get<ArmRobot>(scene_.robot), scene_.obstacles);
    std::vector<std::uint8_t> pixels;
    free_fraction_ = map_->rasterize(128, pixels);
    torus_mesh_.reset();  // built when the 3-D view next draws (a drag in the square view needs none)
  }

  // The scene changed (the editor): the planner replays now or at the release (see
  // PlannerSession::edited), and the world and the C-obstacles follow the drag live.
  void scene_edited() {
    session_.edited(scene_, editor_.dragging());
    rebuild_map();
  }
  bool replay_pending() const { return session_.replay_pending(); }

  // Where the arm stands when a scene is loaded: free, and well apart from S and G in the square,
  // so that its dot hides neither marker (a student who follows "drag in the square" from the
  // dot poses the arm instead of moving the start). The start itself if nothing nearby is free.
  Config pose_beside_markers() const {
    const Space& space = world().space();
    for (double r : {0.9, 0.6, 1.2})
      for (int k = 0; k < 8; ++k) {
        const double a = kTwoPi * (k + 0.5) / 8.0;  // diagonals first: clear of both axes' labels
        const Config q = space.wrap(config({scene_.start[0] + r * std::cos(a), scene_.start[1] + r * std::sin(a)}));
        if (world().is_free(q) && space.distance(q, scene_.goal) > 0.5) return q;
      }
    return scene_.start;
  }

  int seam_edges() const {
    int n = 0;
    const auto& v = prm().roadmap().vertices;
    for (const RoadmapEdge& e : prm().roadmap().edges) {
      if (!e.alive) continue;
      const Config& a = v[static_cast<std::size_t>(e.a)];
      const Config& b = v[static_cast<std::size_t>(e.b)];
      const Config d = world().space().difference(a, b);
      // The short way round leaves the chart when it differs from the plain difference.
      n += std::fabs(b[0] - a[0] - d[0]) > 1e-9 || std::fabs(b[1] - a[1] - d[1]) > 1e-9;
    }
    return n;
  }

  void push_trail() {
    if (!trail_.empty() && (trail_.back() - q_).norm() < 1e-9) return;
    trail_.push_back(q_);
    while (trail_.size() > kTrail) trail_.pop_front();
  }

  Config path_at(double s) const {
    const auto& v = prm().roadmap().vertices;
    const auto& path = prm().path();
    if (path.size() < 2) return q_;
    const double total = prm().path_length();
    double left = s * total;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const Config& a = v[static_cast<std::size_t>(path[i])];
      const Config& b = v[static_cast<std::size_t>(path[i + 1])];
      const double len = world().space().distance(a, b);
      if (left <= len || i + 2 == path.size()) return world().space().interpolate(a, b, len > 0 ? std::min(1.0, left / len) : 0.0);
      left -= len;
    }
    return q_;
  }

  Config loop_at(double s) const {
    if (exercise_ == Exercise::Around) return world().space().wrap(config({loop_origin_[0] + kTwoPi * s, loop_origin_[1]}));
    return world().space().wrap(config({loop_origin_[0] + 0.35 * std::cos(kTwoPi * s), loop_origin_[1] + 0.35 * std::sin(kTwoPi * s)}));
  }

  bool loop_blocked() const {
    for (int i = 0; i < 360; ++i)
      if (!world().is_free(loop_at(i / 360.0))) return true;
    return false;
  }

  void start_exercise(Exercise e) {
    exercise_ = e;
    loop_origin_ = q_;
    phase_ = 0.0;
    // The arm walks the loop by itself, unless the student asked for reduced motion (then the
    // "animate" box starts it, and the loop is drawn whole anyway).
    animate_ = !web::page().reduced_motion;
    trail_.clear();
    if (!animate_) {  // the whole loop at once, as its trail, and the arm at its start
      for (int i = 0; i <= 200; ++i) {
        q_ = loop_at(i / 200.0);
        push_trail();
      }
      q_ = loop_at(0.0);
    }
  }

  // --- the workspace: the arm, obstacles, the tip's trail; drag a link to turn its joint.
  void workspace(LabContext& ctx, ImVec2 size) {
    const bool grab_link = view_.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && link_under_mouse() > 0;
    view_.begin("##torus-workspace", size, scene_.workspace_min, scene_.workspace_max);
    ctx.views["workspace"] = &view_;
    view_.draw_grid();
    view_.push_clip();
    for (const Obstacle& o : scene_.obstacles) view_.draw_obstacle(o);
    const Robot& robot = scene_.robot;
    if (ghost_) draw_robot(view_, robot, *ghost_, theme::with_alpha(theme::kPurple, 120), 2.0f);
    for (std::size_t i = 1; i < trail_.size(); ++i) {
      const ArmPose a = arm_pose(std::get<ArmRobot>(robot), trail_[i - 1]), b = arm_pose(std::get<ArmRobot>(robot), trail_[i]);
      view_.draw_segment(a.tip, b.tip, theme::with_alpha(theme::kCurrent, 180), 2.0f);
    }
    draw_robot(view_, robot, scene_.start, theme::with_alpha(theme::kStart, 110), 2.0f);
    draw_robot(view_, robot, scene_.goal, theme::with_alpha(theme::kGoal, 110), 2.0f);
    draw_robot(view_, robot, q_, world().is_free(q_) ? theme::kRobot : theme::kHit, 4.0f);
    view_.pop_clip();
    if (const char* caption = workspace_caption()) {
      // The loop is about the shape of the torus, not a motion the arm could make: say so where
      // the arm is seen sweeping through obstacles, not only in the panel.
      view_.draw_label(Vec2(scene_.workspace_min.x(), scene_.workspace_max.y()), caption, theme::kWarning, ImVec2(16, -22));
    }
    (void)grab_link;
    // Links first (a press on a link turns its joint), the editor otherwise.
    if (dragging_link_ == 0 && view_.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
      dragging_link_ = link_under_mouse();
    if (dragging_link_ > 0) {
      if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        const ArmRobot& arm = std::get<ArmRobot>(robot);
        const ArmPose pose = arm_pose(arm, q_);
        const Vec2 m = view_.mouse_world();
        if (dragging_link_ == 1) {
          q_[0] = std::atan2(m.y() - arm.base.y(), m.x() - arm.base.x());
        } else {
          const double absolute = std::atan2(m.y() - pose.elbow.y(), m.x() - pose.elbow.x());
          q_[1] = wrap_angle(absolute - q_[0]);
        }
        exercise_ = Exercise::None;
        animate_ = false;
        push_trail();
      } else {
        dragging_link_ = 0;
      }
      return;
    }
    SceneEditor::Options options;
    options.endpoints_are_points = false;
    // Start and goal are angles, points of the square: the keyboard moves them there (when the
    // square is on screen to show where they go).
    if (right_view_ != 1) options.angle_view = &cspace_view_;
    if (editor_.edit(view_, scene_, ctx, options)) scene_edited();
    if (replay_pending() && !editor_.dragging()) scene_edited();  // released
  }

  const char* workspace_caption() const {
    if (exercise_ == Exercise::None) return nullptr;  // (also when still: reduced motion draws the loop whole)
    return loop_blocked() ? "a loop in C-space, not a path (red-orange: the arm hits)"
                          : "a loop in C-space, not a planned path";
  }

  // 1 or 2 if the mouse is on link 1 or 2 of the posed arm, else 0.
  int link_under_mouse() const {
    const ArmPose pose = arm_pose(std::get<ArmRobot>(scene_.robot), q_);
    const Vec2 m = view_.mouse_world();
    const double near = view_.reach(7.0f);
    if (point_segment_distance(m, pose.elbow, pose.tip) <= near) return 2;
    if (point_segment_distance(m, pose.base, pose.elbow) <= near) return 1;
    return 0;
  }

  // --- the C-space square: exact C-obstacles, roadmap, path, trail; hover and drag to pose.
  void cspace(LabContext& ctx, ImVec2 size) {
    cspace_view_.begin("##torus-cspace", size, Vec2(-kPi, -kPi), Vec2(kPi, kPi));
    ctx.views["cspace"] = &cspace_view_;
    cspace_view_.set_angular(true, true);
    cspace_view_.draw_grid("θ₁", "θ₂");
    cspace_view_.push_clip();
    const bool stale = replay_pending() || session_.replaying();
    if (!stale) draw_arm_cobstacles(cspace_view_, *map_, theme::kCObstacle);  // else over the faded roadmap
    const Space& space = world().space();
    refresh_labels();
    roadmap_layer_.draw(cspace_view_, space, prm().roadmap(), labels_, throttle_(session_.version(), session_.busy()));
    if (prm().solved()) draw_path(cspace_view_, space, prm().roadmap(), prm().path());
    if (stale) {  // the old roadmap faded under the C-obstacles as they are now
      draw_replay_pending(cspace_view_, session_.replaying() ? replaying_text(session_) : std::string());
      draw_arm_cobstacles(cspace_view_, *map_, theme::kCObstacle);
    }
    for (std::size_t i = 1; i < trail_.size(); ++i)
      draw_chart_segment(cspace_view_, space, trail_[i - 1], space.difference(trail_[i - 1], trail_[i]),
                         theme::with_alpha(theme::kCurrent, 200), 2.0f);
    cspace_view_.draw_marker(Vec2(scene_.start[0], scene_.start[1]), theme::kStart, "S", !world().is_free(scene_.start));
    cspace_view_.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G", !world().is_free(scene_.goal));
    const ImVec2 at = cspace_view_.to_screen(Vec2(q_[0], q_[1]));
    cspace_view_.draw_list()->AddCircleFilled(at, 6.0f, world().is_free(q_) ? theme::kRobot : theme::kHit, 16);
    cspace_view_.draw_list()->AddCircle(at, 6.0f, theme::kCanvasBg, 16, 2.0f);
    cspace_view_.pop_clip();
    editor_.draw_endpoint_focus(cspace_view_, scene_);  // S or G with the keyboard's focus

    // Hover: a ghost of the arm; press and drag: pose it (or move start / goal when on them).
    ghost_.reset();
    if (!cspace_view_.hovered() && drag_marker_ == 0 && !posing_) return;
    const Vec2 m = cspace_view_.mouse_world();
    const Config at_mouse = space.wrap(config({m.x(), m.y()}));
    if (cspace_view_.hovered()) ghost_ = at_mouse;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && cspace_view_.hovered()) {
      // What is drawn on top takes the press: the arm's dot, then G, then S.
      const double grab = cspace_view_.reach(11.0f);
      if (length(Vec2(q_[0], q_[1]) - m) <= cspace_view_.reach(8.0f)) posing_ = true;
      else if (length(Vec2(scene_.goal[0], scene_.goal[1]) - m) <= grab) drag_marker_ = 2;
      else if (length(Vec2(scene_.start[0], scene_.start[1]) - m) <= grab) drag_marker_ = 1;
      else posing_ = true;
      marker_before_ = scene_;
      marker_grab_ = m;
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      if (drag_marker_ != 0 && !same_scene(marker_before_, scene_)) editor_.record(marker_before_);
      drag_marker_ = 0;
      posing_ = false;
      return;
    }
    if (drag_marker_ != 0) {
      // By the mouse's offset from the press, as the workspace editor moves things: a press a
      // few pixels off the marker does not make it jump (and restart the run).
      const Config& was = drag_marker_ == 1 ? marker_before_.start : marker_before_.goal;
      const Vec2 offset = m - marker_grab_;
      const Config moved = offset == Vec2::Zero() ? was : space.wrap(config({was[0] + offset.x(), was[1] + offset.y()}));
      Config& marker = drag_marker_ == 1 ? scene_.start : scene_.goal;
      if (moved != marker) {
        marker = moved;
        rebuild(0);
      }
    } else if (posing_) {
      q_ = at_mouse;
      exercise_ = Exercise::None;
      animate_ = false;
      push_trail();
    }
  }

  void refresh_labels() {
    if (labels_at_ == session_.version()) return;
    labels_ = session_.shown().component_labels();
    labels_at_ = session_.version();
  }

  // --- the torus in 3-D: C-obstacles on its surface, the roadmap and path on it, the arm's point.
  void torus(ImVec2 size) {
    torus_view_.begin("##torus-3d", size, 1.5);
    if (!torus_mesh_) {
      // Quads whose edges are the C-obstacles' (a grid's cells drew them as blocks).
      std::vector<SurfacePatch> patches;
      for (const CSpaceQuad& q : cspace_quads(*map_, 96, 40))
        patches.push_back({q.u0, q.u1, q.va0, q.va1, q.vb0, q.vb1,
                           q.blocked ? theme::rgba(110, 110, 120) : theme::rgba(225, 228, 235)});
      torus_mesh_.emplace([](double u, double v) { return torus_point(u, v); }, patches);
    }
    torus_view_.draw_mesh(*torus_mesh_);
    const auto on_torus = [](const Config& q) { return torus_point((q[0] + kPi) / kTwoPi, (q[1] + kPi) / kTwoPi); };
    const Space& space = world().space();
    const auto curve = [&](const Config& a, const Config& b, ImU32 c, float t) {
      std::vector<SurfacePoint> pts;
      const Config d = space.difference(a, b);
      for (int i = 0; i <= 8; ++i) pts.push_back(on_torus(space.along(a, d, i / 8.0)));
      torus_view_.draw_curve(pts, c, t);
    };
    const Roadmap& r = prm().roadmap();
    // While a replay waits for the end of a drag (or catches up), the old roadmap and path would
    // lie on the new C-obstacles with nothing to say so (the square view fades them): not drawn.
    const bool show_roadmap = !replay_pending() && !session_.replaying();
    if (r.edges.size() <= 6000 && show_roadmap)
      for (const RoadmapEdge& e : r.edges)
        if (e.alive)
          curve(r.vertices[static_cast<std::size_t>(e.a)], r.vertices[static_cast<std::size_t>(e.b)],
                theme::with_alpha(theme::kBlue, r.edges.size() > 1500 ? 45 : 100), 1.0f);
    for (std::size_t i = 0; show_roadmap && i + 1 < prm().path().size(); ++i)
      curve(r.vertices[static_cast<std::size_t>(prm().path()[i])], r.vertices[static_cast<std::size_t>(prm().path()[i + 1])],
            theme::kPath, 3.5f);
    for (std::size_t i = 1; i < trail_.size(); ++i) curve(trail_[i - 1], trail_[i], theme::kCurrent, 2.5f);
    const SurfacePoint p = on_torus(q_);
    const ImVec2 s = torus_view_.project(p.p);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddCircleFilled(s, torus_view_.facing(p.n) ? 6.0f : 3.0f, world().is_free(q_) ? theme::kRobot : theme::kHit, 16);
    const ImVec2 corner = ImGui::GetItemRectMin();
    dl->AddText(ImVec2(corner.x + 6, corner.y + 4), theme::kLabel, "θ₁: around the hole, θ₂: around the tube");
    if (!show_roadmap)
      dl->AddText(ImVec2(corner.x + 6, corner.y + 4 + ImGui::GetTextLineHeightWithSpacing()), theme::kWarning,
                  session_.replaying() ? replaying_text(session_).c_str() : "the roadmap is replayed when you release");
  }

  Scene scene_;
  SceneEditor editor_;
  WorkspaceView view_, cspace_view_;
  SurfaceView torus_view_;
  PrmParams params_;
  PlannerSession session_;  // after scene_ and params_, from which it starts
  std::unique_ptr<ArmCSpaceMap> map_;
  std::optional<SurfaceMesh> torus_mesh_;  // the 3-D torus with map_'s C-obstacles, once drawn
  double free_fraction_ = 0;
  RoadmapLayer roadmap_layer_;
  RedrawThrottle throttle_;
  std::vector<int> labels_;
  long long labels_at_ = -1;
  Config q_;
  std::optional<Config> ghost_;
  std::deque<Config> trail_;
  int right_view_ = 0;
  int dragging_link_ = 0;
  int drag_marker_ = 0;
  bool posing_ = false;
  Scene marker_before_;
  Vec2 marker_grab_{0, 0};  // where a marker drag was pressed (C-space)
  bool animate_ = false;
  double phase_ = 0.0;
  Exercise exercise_ = Exercise::None;
  int scroll_to_exercise_ = 0;  // frames until the panel scrolls to the exercise's text (its height settles first)
  Config loop_origin_;
};

}  // namespace

CSL_REGISTER_LESSON(TorusLesson, "torus", "2-link arm and the torus", "Configuration spaces");

}  // namespace csl::app
