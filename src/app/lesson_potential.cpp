// Lesson "Potential fields" (homework P13, the course's section 2.4): the attractive and
// repulsive fields a robot's control points feel, as a heat map with level lines and the rho0
// rings; the forces at each control point (the polygon's vertices, the arm's elbow and tip) and
// what they add up to in C-space through J^T (force and torque, or joint torques); drag the
// robot and watch them change; gradient descent step by step from where the robot is, its
// local minima and the random-walk escapes. Three examples: P13's rectangle among two polygons,
// a point robot and a cup (a local minimum), and the 2-link arm with its field on the torus.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>

#include "app/bundled_scenes.hpp"
#include "app/draw.hpp"
#include "app/field_draw.hpp"
#include "app/js_api.hpp"
#include "app/lesson.hpp"
#include "app/prm_text.hpp"
#include "app/scene_editor.hpp"
#include "app/theme.hpp"
#include "app/ui.hpp"
#include "core/angles.hpp"
#include "core/cspace_map.hpp"
#include "core/descent.hpp"
#include "core/geometry.hpp"
#include "core/potential.hpp"
#include "core/scalar_grid.hpp"
#include "core/work.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;

constexpr int kGridNodes = 97;     // heat maps: 96 x 96 cells, recomputed only when they change...
constexpr int kLeastGridNodes = 17;  // ...fewer in a dense scene (grid_nodes()), at least 16 x 16
constexpr int kLevels = 8;         // level lines per heat map
constexpr double kSliceStep = 0.02;  // rad: how far the angle turns before a playing slice is redrawn
constexpr float kForcePixels = 250.0f;  // arrow pixels per unit of force: the largest pull (0.2) is 50 px
const ImU32 kAttract = theme::kGreen;
const ImU32 kRepel = theme::kVermillion;
const ImU32 kTotal = theme::rgba(30, 30, 30);
const ImU32 kRing = theme::with_alpha(theme::kBlue, 200);
const ImU32 kIso = theme::rgba(60, 40, 20, 110);
const ImU32 kTrajectory = theme::kPurple;

struct Example {
  const char* scene;
  const char* label;
  const char* tooltip;
};
const Example kExamples[] = {
    {"p13", "P13: rectangle", "the homework's rectangle robot and two polygons, their regions of influence apart"},
    {"potential-cup", "cup: a local minimum", "a point robot below a cup-shaped obstacle: the pull up and the push "
                                              "down cancel inside the cup"},
    {"arm-2link", "2-link arm", "the arm's elbow and tip as control points; its field on the torus"},
};

std::string fmt(const char* f, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, a);
  return buf;
}

std::string describe(const DescentEvent& e) {
  const std::string at = format_config(e.q);
  switch (e.kind) {
    case DescentEvent::Kind::Descend:
      return "descend to " + at + ": U = " + fmt("%.4g", e.U) + ", |τ| = " + fmt("%.3g", e.force) +
             (e.halvings > 0 ? " (step halved " + std::to_string(e.halvings) + "x to stay free)" : "");
    case DescentEvent::Kind::RandomWalk: return "random walk to " + at + ": U = " + fmt("%.4g", e.U);
    case DescentEvent::Kind::ReachedGoal: return "reached the goal at " + at;
    case DescentEvent::Kind::LocalMinimum:
      return std::string("local minimum at ") + at + (e.blocked ? " (every shorter step collides)" : "") +
             ": U = " + fmt("%.4g", e.U) + ", |τ| = " + fmt("%.3g", e.force) + "; a random walk follows";
    case DescentEvent::Kind::GaveUp:
      return "stopped at " + at + ": " + (e.blocked ? "blocked" : "no progress") + ", no escapes left";
  }
  return "";
}

class PotentialLesson : public Lesson {
 public:
  PotentialLesson() { load(bundled_scene("p13")); }

  void update(LabContext& ctx) override {
    const int due = ctx.playback.due(static_cast<double>(ImGui::GetIO().DeltaTime));
    for (int i = 0; i < due && descent_ && !descent_->done(); ++i) descent_->step();
    if (!descent_ || descent_->done()) ctx.playback.playing = false;
    const long steps = descent_ ? descent_->steps() : 0;
    if (logged_ != steps) {
      if (steps == 0 || steps < logged_ || steps > logged_ + 1) ctx.log.clear();
      if (steps > 0) ctx.log.add(steps, describe(descent_->last_event()));
      logged_ = steps;
    }
  }

  void panel(LabContext& ctx) override {
    ImGui::TextWrapped("Every control point is pulled toward where it is at the goal and pushed away from each "
                       "obstacle closer than ρ₀. J^T turns each workspace force into a configuration-space "
                       "force; gradient descent follows their sum. Drag the robot; step the descent.");
    ImGui::TextDisabled("Example:");
    for (const Example& e : kExamples) {
      ui::flow(ui::button_width(e.label));  // same row while it fits (the panel may be narrow)
      if (ImGui::SmallButton(e.label)) set_example(e.scene, ctx);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.tooltip);
    }

    ui::section("Field");
    bool changed = false;
    PotentialParams f = field_params_;
    changed |= slider("ρ₀", &f.rho0, 0.02, 0.3, "region of influence of each obstacle");
    changed |= slider("η", &f.eta, 1e-6, 1e-2, "repulsive gain", true);
    changed |= slider("ζ", &f.zeta, 0.1, 10.0, "attractive gain", true);
    changed |= slider("switch d", &f.switch_distance, 0.01, 1.0, "quadratic pull within d of the goal, conic beyond");
    if (robot_kind() == Kind::Polygon) {
      double theta = from_[2];
      if (slider("start θ", &theta, -kPi, kPi, "the robot's orientation where the descent starts (drag the robot to move it)"))
        set_from(config({from_[0], from_[1], theta}));
    }
    if (changed && f.problem().empty()) {
      field_params_ = f;
      rebuild();
    }

    ui::section("Gradient descent");
    changed = false;
    DescentParams d = descent_params_;
    changed |= slider("step", &d.step, 0.001, 0.1, "alpha: the length of one descent step", true);
    int escapes = d.escapes;
    if (ImGui::SliderInt("escapes", &escapes, 0, 20, "%d", ImGuiSliderFlags_AlwaysClamp)) {
      d.escapes = escapes;
      changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("random walks allowed out of local minima (0: plain descent)");
    int seed = static_cast<int>(std::min<std::uint64_t>(d.seed, 2147483647u));
    if (ImGui::InputInt("seed", &seed) && seed >= 0) {
      d.seed = static_cast<std::uint64_t>(seed);
      changed = true;
    }
    if (changed && d.problem().empty()) {
      descent_params_ = d;
      restart_descent();
    }
    if (ImGui::Button("Descend from the start")) set_from(scene_.start);
    status_text();

    ui::section("At the robot");
    forces_table();
    ui::section("Obstacles");
    if (editor_.toolbar(scene_, ctx)) scene_changed();
  }

  void views(LabContext& ctx, ImVec2 size) override {
    if (robot_kind() == Kind::Point) {
      workspace(ctx, size);
    } else {
      const float w = 0.5f * (size.x - ImGui::GetStyle().ItemSpacing.x);
      workspace(ctx, ImVec2(w, size.y));
      ImGui::SameLine();
      cspace(ctx, ImVec2(w, size.y));
    }
    editor_.help_window();
  }

  Scene* scene() override { return &scene_; }
  bool accept_scene(const Scene& s, std::string& why) override {
    (void)why;  // every robot type has control points
    editor_.replace(scene_, s);
    load(s);
    return true;
  }
  bool undo() override { return editor_.undo(scene_) && (scene_changed(), true); }
  bool redo() override { return editor_.redo(scene_) && (scene_changed(), true); }

  json state(const json& args) const override {
    (void)args;
    const Config q = shown();
    json points = json::array();
    const PotentialReport r = field_->evaluate(q);
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const ControlPointReport& p = r.points[i];
      points.push_back({{"name", control_point_name(scene_.robot, static_cast<int>(i))},
                        {"position", {p.position.x(), p.position.y()}},
                        {"rho", std::isfinite(p.nearest.rho) ? json(p.nearest.rho) : json(nullptr)},
                        {"F_att", {p.attractive.F.x(), p.attractive.F.y()}},
                        {"F_rep", finite_vec(p.repulsive.F)},
                        {"U_rep", std::isfinite(p.repulsive.U) ? json(p.repulsive.U) : json(nullptr)}});
    }
    json out{{"robot", robot_type_name(scene_.robot)},
             {"q", config_to_json(q)},
             {"from", config_to_json(from_)},
             {"from_free", world_->is_free(from_)},
             {"goal", config_to_json(scene_.goal)},
             {"control_points", points},
             {"contact", r.contact},
             {"U", std::isfinite(r.U) ? json(r.U) : json(nullptr)},
             {"U_att", r.U_att},
             {"tau", finite_config(r.tau)},
             {"field", {{"zeta", field_params_.zeta}, {"switch", field_params_.switch_distance}, {"eta", field_params_.eta}, {"rho0", field_params_.rho0}}},
             {"steps", descent_ ? descent_->steps() : 0},
             {"heat_map", {{"nodes", grid_nodes_}, {"levels", map_u_.level_count}, {"lo", map_u_.scale.lo}, {"hi", map_u_.scale.hi},
                           {"slice_theta", robot_kind() == Kind::Polygon ? json(cspace_key_) : json(nullptr)}}}};
    if (descent_) {
      json trajectory = json::array();
      for (const Config& c : descent_->trajectory()) trajectory.push_back(config_to_json(c));
      out["descent"] = {{"outcome", outcome_name(descent_->outcome())},
                        {"steps", descent_->steps()},
                        {"descent_steps", descent_->descent_steps()},
                        {"walk_steps", descent_->walk_steps()},
                        {"local_minima", descent_->local_minima()},
                        {"escapes_used", descent_->escapes_used()},
                        {"distance_to_goal", descent_->distance_to_goal()},
                        {"U", descent_->potential()},
                        {"trajectory", trajectory}};
    } else {
      out["descent"] = nullptr;
    }
    return out;
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    PotentialParams f = field_params_;
    DescentParams d = descent_params_;
    std::optional<Config> from;
    const auto number = [](const json& v, const std::string& k) {
      if (!v.is_number() || !std::isfinite(v.get<double>())) throw ApiError(k + ": a finite number");
      return v.get<double>();
    };
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& k = it.key();
      if (k == "rho0") f.rho0 = number(*it, k);
      else if (k == "eta") f.eta = number(*it, k);
      else if (k == "zeta") f.zeta = number(*it, k);
      else if (k == "switch") f.switch_distance = number(*it, k);
      else if (k == "step") d.step = number(*it, k);
      else if (k == "escapes") {
        if (!it->is_number_integer() || it->get<long long>() < 0 || it->get<long long>() > 100) throw ApiError("escapes: an integer from 0 to 100");
        d.escapes = it->get<int>();
      } else if (k == "seed") {
        if (!it->is_number_unsigned()) throw ApiError("seed: an integer >= 0");
        d.seed = it->get<std::uint64_t>();
      } else if (k == "from") {
        if (!it->is_array() || static_cast<int>(it->size()) != robot_dof(scene_.robot)) throw ApiError("from: a configuration of " + std::to_string(robot_dof(scene_.robot)) + " numbers");
        Config q(static_cast<Eigen::Index>(it->size()));
        for (std::size_t i = 0; i < it->size(); ++i) q[static_cast<Eigen::Index>(i)] = number((*it)[i], k);
        from = q;
      } else {
        throw ApiError("unknown parameter \"" + k + "\"");
      }
    }
    if (const std::string p = f.problem(); !p.empty()) throw ApiError(p);
    if (const std::string p = d.problem(); !p.empty()) throw ApiError(p);
    field_params_ = f;
    descent_params_ = d;
    if (from) from_ = world_->space().wrap(*from);
    rebuild();
  }

  json params() const override {
    return {{"rho0", field_params_.rho0}, {"eta", field_params_.eta}, {"zeta", field_params_.zeta},
            {"switch", field_params_.switch_distance}, {"step", descent_params_.step},
            {"escapes", descent_params_.escapes}, {"seed", descent_params_.seed}, {"from", config_to_json(from_)}};
  }

  bool steppable() const override { return true; }
  long steps() const override { return descent_ ? descent_->steps() : 0; }
  bool finished() const override { return !descent_ || descent_->done(); }
  void step_forward() override {
    if (descent_ && !descent_->done()) descent_->step();
  }
  void step_back() override { run_to(steps() - 1); }
  // A "phase" of descent: up to the next local minimum (or the end).
  void finish_phase() override {
    while (descent_ && !descent_->done()) {
      const DescentEvent::Kind k = descent_->step().kind;
      if (k == DescentEvent::Kind::LocalMinimum) break;
    }
  }
  void run_all() override {
    if (descent_) descent_->run();
  }
  void reset() override {
    if (descent_) descent_->reset();
  }
  void run_to(long steps) override {
    if (!descent_) return;
    descent_->reset();
    while (descent_->steps() < steps && !descent_->done()) descent_->step();
  }

 private:
  enum class Kind { Point, Arm, Polygon };
  Kind robot_kind() const {
    if (std::holds_alternative<ArmRobot>(scene_.robot)) return Kind::Arm;
    if (std::holds_alternative<PolygonRobot>(scene_.robot)) return Kind::Polygon;
    return Kind::Point;
  }

  static json finite_vec(const Vec2& v) {
    return std::isfinite(v.x()) && std::isfinite(v.y()) ? json{v.x(), v.y()} : json(nullptr);
  }
  static json finite_config(const Config& c) {
    for (Eigen::Index i = 0; i < c.size(); ++i)
      if (!std::isfinite(c[i])) return nullptr;
    return config_to_json(c);
  }

  bool slider(const char* label, double* v, double lo, double hi, const char* tip, bool log = false) {
    // AlwaysClamp: a value typed with Ctrl+click stays in range too (0 for rho0 would be invalid).
    const ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | (log ? ImGuiSliderFlags_Logarithmic : 0);
    const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, v, &lo, &hi, log ? "%.3g" : "%.3f", flags);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    return changed;
  }

  void set_example(const char* name, LabContext& ctx) {
    std::string why;
    accept_scene(bundled_scene(name), why);
    ctx.log.clear();
  }

  // A new scene: everything rebuilt, the descent from its start.
  void load(const Scene& s) {
    scene_ = s;
    from_ = scene_.start;
    rebuild();
  }

  // After the scene changed in place (an edit, a drag, undo, redo, delete), against built_, the
  // scene the world was built from: another robot starts over; a moved start only moves the
  // descent's start (the world and the fields do not depend on it); anything else rebuilds.
  void scene_changed() {
    json now = scene_to_json(scene_), before = scene_to_json(built_);
    if (now["robot"] != before["robot"]) {
      load(Scene(scene_));
      return;
    }
    const bool start_moved = now["start"] != before["start"];
    now.erase("start");
    before.erase("start");
    if (start_moved) from_ = scene_.start;
    if (now == before) {
      built_ = scene_;
      set_from(from_);
      return;
    }
    rebuild();
  }

  // After the scene or the field changed: world, field, heat maps, and the descent from from_.
  void rebuild() {
    built_ = scene_;
    descent_.reset();
    field_.reset();
    world_ = std::make_unique<CollisionWorld>(scene_);
    field_ = std::make_unique<PotentialField>(*world_, scene_.goal, field_params_);
    // Three heat maps of n x n potentials must fit one frame's work (kLabFrameWork): 97 x 97 in
    // ordinary scenes, coarser in dense ones (1000 polygons of 256 vertices took seconds a map).
    grid_nodes_ = std::clamp(static_cast<int>(std::sqrt(kLabFrameWork / (3.0 * world_->evaluation_cost()))),
                             kLeastGridNodes, kGridNodes);
    map_.reset();
    if (robot_kind() == Kind::Arm) map_ = std::make_unique<ArmCSpaceMap>(std::get<ArmRobot>(scene_.robot), scene_.obstacles);
    workspace_grids();
    cspace_key_ = std::numeric_limits<double>::quiet_NaN();
    restart_descent();
    cspace_grids(false);
  }

  void set_from(const Config& q) {
    from_ = world_->space().wrap(q);
    restart_descent();
    cspace_grids(false);  // the polygon's slice follows its angle (the state reports it)
  }

  // The descent from from_ with the current parameters, at step 0; none if from_ collides.
  void restart_descent() {
    descent_.reset();
    logged_ = -1;
    problem_.clear();
    if (!world_->is_free(from_)) {
      problem_ = "the robot is in collision here: drag it to a free place to descend";
      return;
    }
    try {
      descent_ = std::make_unique<Descent>(*field_, from_, descent_params_);
    } catch (const std::exception& e) {
      problem_ = e.what();
    }
  }

  Config shown() const { return descent_ ? descent_->q() : from_; }

  // The workspace heat map: the repulsive potential a control point at x feels (the same for
  // every control point), and rho(x) to the nearest obstacle for the rho0 rings.
  void workspace_grids() {
    const Scene& s = scene_;
    const PotentialParams fp = field_params_;
    ScalarGrid rho = sample_grid(grid_nodes_, grid_nodes_, s.workspace_min, s.workspace_max, [&](const Vec2& x) {
      double best = std::numeric_limits<double>::infinity();
      for (const Obstacle& o : s.obstacles) best = std::min(best, obstacle_distance(o, x).rho);
      return best;
    });
    ws_rings_ = level_set(rho, fp.rho0);
    ws_map_ = make_heat_map(sample_grid(grid_nodes_, grid_nodes_, s.workspace_min, s.workspace_max, [&](const Vec2& x) {
                              double u = 0.0;
                              for (const Obstacle& o : s.obstacles) u += repulsive_field(obstacle_distance(o, x), fp.eta, fp.rho0).U;
                              return u;
                            }),
                            kLevels);
  }

  // The C-space heat map of the total potential U: the workspace for the point robot, the
  // torus square for the arm, the slice at the robot's current angle for the polygon robot.
  // Recomputed when that angle changes.
  // While the descent plays, the slice follows the angle in steps of kSliceStep (a 97 x 97 grid
  // of potentials each frame would cost more than the rest of the frame); at rest it is exact.
  void cspace_grids(bool playing) {
    const Kind kind = robot_kind();
    const double key = kind == Kind::Polygon ? shown()[2] : 0.0;
    if (key == cspace_key_ || (playing && std::fabs(key - cspace_key_) < kSliceStep)) return;
    cspace_key_ = key;
    const Vec2 lo = kind == Kind::Arm ? Vec2(-kPi, -kPi) : scene_.workspace_min;
    const Vec2 hi = kind == Kind::Arm ? Vec2(kPi, kPi) : scene_.workspace_max;
    map_u_ = make_heat_map(sample_grid(grid_nodes_, grid_nodes_, lo, hi, [&](const Vec2& p) {
                             const Config q = kind == Kind::Polygon ? config({p.x(), p.y(), key}) : config({p.x(), p.y()});
                             return field_->potential(q);
                           }),
                           // The arm's square gets its exact C-obstacles drawn over, opaque (the
                           // workspace's obstacles are translucent over grey, the polygon's slice
                           // has no exact overlay).
                           kLevels, /*covered=*/kind == Kind::Arm);
  }

  void status_text() {
    if (!problem_.empty()) {
      ImGui::TextColored(ImVec4(0.75f, 0.25f, 0.0f, 1.0f), "%s", problem_.c_str());
      return;
    }
    const Descent& d = *descent_;
    ImGui::Text("step %ld  U = %.4g  |τ| = %.3g", d.steps(), d.potential(), d.force());
    ImGui::Text("distance to the goal %.3f", d.distance_to_goal());
    ImGui::Text("local minima %d  escapes used %d of %d", d.local_minima(), d.escapes_used(), d.params().escapes);
    switch (d.outcome()) {
      case DescentOutcome::Running: break;
      case DescentOutcome::Goal: ImGui::TextColored(ImVec4(0.0f, 0.45f, 0.3f, 1.0f), "reached the goal"); break;
      case DescentOutcome::Escaped:
        ImGui::TextColored(ImVec4(0.0f, 0.45f, 0.3f, 1.0f), "reached the goal after %d random walk(s)", d.escapes_used());
        break;
      case DescentOutcome::LocalMinimum:
        ImGui::TextColored(ImVec4(0.75f, 0.25f, 0.0f, 1.0f), "stuck in a local minimum");
        ImGui::TextWrapped("The descent makes no progress here, away from the goal: attraction and repulsion "
                           "nearly cancel, so its steps of fixed length go back and forth around a minimum of U "
                           "(|τ| is small there, not zero), or every step is blocked. Allow escapes: random "
                           "walks out of the basin, then descent again.");
        break;
      case DescentOutcome::MaxSteps: ImGui::TextColored(ImVec4(0.75f, 0.25f, 0.0f, 1.0f), "out of steps"); break;
    }
  }

  void forces_table() {
    const PotentialReport r = field_->evaluate(shown());
    if (ImGui::BeginTable("##forces", 4, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
      ImGui::TableSetupColumn("point");
      ImGui::TableSetupColumn("ρ");
      ImGui::TableSetupColumn("|F_att|");
      ImGui::TableSetupColumn("|F_rep|");
      ImGui::TableHeadersRow();
      for (std::size_t i = 0; i < r.points.size(); ++i) {
        const ControlPointReport& p = r.points[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(control_point_name(scene_.robot, static_cast<int>(i)).c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", p.nearest.rho);
        ImGui::TableNextColumn();
        ImGui::TextColored(ImVec4(0.0f, 0.5f, 0.35f, 1.0f), "%.3f", length(p.attractive.F));
        ImGui::TableNextColumn();
        ImGui::TextColored(ImVec4(0.75f, 0.3f, 0.0f, 1.0f), "%.3g", length(p.repulsive.F));
      }
      ImGui::EndTable();
    }
    if (r.contact) {
      ImGui::TextColored(ImVec4(0.75f, 0.25f, 0.0f, 1.0f), "a control point is on an obstacle: U is infinite");
      return;
    }
    if (robot_kind() == Kind::Polygon)
      ImGui::Text("τ = J^T F: force (%.3f, %.3f), torque %.4f", r.tau[0], r.tau[1], r.tau[2]);
    else if (robot_kind() == Kind::Arm)
      ImGui::Text("τ = J^T F: joint torques (%.3f, %.3f)", r.tau[0], r.tau[1]);
    else
      ImGui::Text("τ = F = (%.3f, %.3f)", r.tau[0], r.tau[1]);
    ImGui::Text("U = %.4g  (attractive %.4g, repulsive %.4g)", r.U, r.U_att, r.U_rep);
  }

  // --- the workspace: field, rings, obstacles, robot with its forces; drag the robot.
  void workspace(LabContext& ctx, ImVec2 size) {
    const Kind kind = robot_kind();
    if (kind == Kind::Point) cspace_grids(ctx.playback.playing);
    view_.begin("##potential-workspace", size, scene_.workspace_min, scene_.workspace_max);
    ctx.views["workspace"] = &view_;
    if (kind == Kind::Point) ctx.views["cspace"] = &view_;  // the point's workspace is its C-space
    view_.draw_grid();
    view_.push_clip();
    if (kind == Kind::Point) {
      draw_heat_map(view_, map_u_);
      draw_level_set(view_, map_u_.levels, kIso, 1.0f);
    } else {
      draw_heat_map(view_, ws_map_);
      draw_level_set(view_, ws_map_.levels, kIso, 1.0f);
    }
    draw_level_set(view_, ws_rings_, kRing, 2.0f);
    for (const Obstacle& o : scene_.obstacles) view_.draw_obstacle(o);
    const Robot& robot = scene_.robot;
    draw_robot(view_, robot, scene_.goal, theme::with_alpha(theme::kGoal, 140), 2.0f);
    if (kind != Kind::Point) draw_robot(view_, robot, from_, theme::with_alpha(theme::kStart, 120), 2.0f);
    if (descent_ && kind != Kind::Arm) {
      const auto& t = descent_->trajectory();
      for (std::size_t i = 1; i < t.size(); ++i)
        view_.draw_segment(Vec2(t[i - 1][0], t[i - 1][1]), Vec2(t[i][0], t[i][1]), kTrajectory, 2.0f);
    }
    const Config q = shown();
    draw_robot(view_, robot, q, world_->is_free(q) ? theme::kRobot : theme::kHit, 3.0f);
    draw_forces(q);
    view_.pop_clip();
    if (kind != Kind::Arm) view_.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G");  // the arm's goal is angles
    title(view_, kind == Kind::Point ? "U(x, y): workspace = C-space" : "U_rep(x): what a control point feels from the obstacles");

    if (robot_drag(q)) return;
    SceneEditor::Options options;
    options.endpoints_are_points = kind != Kind::Arm;
    if (editor_.edit(view_, scene_, ctx, options)) scene_changed();
  }

  // A view's title in its top left corner, cut at its right edge (narrow windows put the views
  // side by side with little room).
  static void title(const WorkspaceView& v, const char* text) {
    ImDrawList* dl = v.draw_list();
    dl->PushClipRect(v.canvas_min(), v.canvas_max(), true);
    dl->AddText(ImVec2(v.canvas_min().x + 6, v.canvas_min().y + 4), theme::kLabel, text);
    dl->PopClipRect();
  }

  // Arrows at every control point: pull (green), push (red), their sum (dark); and for the
  // polygon the summed force at its reference point with the torque as a turning arc.
  void draw_forces(const Config& q) {
    const PotentialReport r = field_->evaluate(q);
    for (const ControlPointReport& p : r.points) {
      draw_force(view_, p.position, p.attractive.F, kAttract, kForcePixels);
      draw_force(view_, p.position, p.repulsive.F, kRepel, kForcePixels);
      draw_force(view_, p.position, p.attractive.F + p.repulsive.F, kTotal, kForcePixels, 110.0f, 1.5f);
      view_.draw_list()->AddCircleFilled(view_.to_screen(p.position), 3.5f, kTotal, 12);
    }
    if (robot_kind() != Kind::Polygon || r.contact) return;
    const Vec2 c(q[0], q[1]);
    draw_force(view_, c, Vec2(r.tau[0], r.tau[1]), theme::kBlue, kForcePixels, 110.0f, 3.5f);
    // The torque: an arc around the reference point, its sweep growing with |torque|.
    const double torque = r.tau[2];
    const float sweep = static_cast<float>(std::min(1.0, std::fabs(torque) / 0.05)) * 2.5f;
    if (sweep > 0.05f) {
      ImDrawList* dl = view_.draw_list();
      const ImVec2 s = view_.to_screen(c);
      const float radius = 16.0f, start = static_cast<float>(-q[2]);
      const float dir = torque > 0 ? -1.0f : 1.0f;  // screen angles turn clockwise
      dl->PathArcTo(s, radius, start, start + dir * sweep, 24);
      dl->PathStroke(theme::kBlue, 0, 2.5f);
      const float end = start + dir * sweep;
      const ImVec2 tip(s.x + radius * std::cos(end), s.y + radius * std::sin(end));
      dl->AddCircleFilled(tip, 4.0f, theme::kBlue, 10);
    }
  }

  // Press on the robot and drag: it moves (the point and the polygon translate; the arm's links
  // turn their joints); the descent restarts from there. Returns true while dragging.
  bool robot_drag(const Config& q) {
    const Vec2 m = view_.mouse_world();
    if (drag_ == 0 && view_.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && editor_.tool() == SceneEditor::Tool::Select) {
      drag_ = grab(q, m);
      grab_offset_ = Vec2(q[0], q.size() > 1 ? q[1] : 0.0) - m;
    }
    if (drag_ == 0) return false;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      drag_ = 0;
      return true;
    }
    Config next = q;
    if (robot_kind() == Kind::Arm) {
      const ArmRobot& arm = std::get<ArmRobot>(scene_.robot);
      const ArmPose pose = arm_pose(arm, q);
      if (drag_ == 1) next[0] = std::atan2(m.y() - arm.base.y(), m.x() - arm.base.x());
      else next[1] = wrap_angle(std::atan2(m.y() - pose.elbow.y(), m.x() - pose.elbow.x()) - q[0]);
    } else {
      next[0] = m.x() + grab_offset_.x();
      next[1] = m.y() + grab_offset_.y();
    }
    if ((next - from_).norm() > 0 || descent_ == nullptr || descent_->steps() > 0) set_from(next);
    return true;
  }

  // What a press at m grabs: 1 the body (the arm's first link), 2 the arm's second link, 0 none.
  int grab(const Config& q, const Vec2& m) const {
    const double near = view_.pixels(8.0f);
    switch (robot_kind()) {
      case Kind::Point: return length(Vec2(q[0], q[1]) - m) <= near ? 1 : 0;
      case Kind::Polygon: {
        Polygon body;
        polygon_pose(std::get<PolygonRobot>(scene_.robot), q, body);
        return point_in_polygon(m, body) || point_polygon_boundary_distance(m, body) <= near ? 1 : 0;
      }
      case Kind::Arm: {
        const ArmPose pose = arm_pose(std::get<ArmRobot>(scene_.robot), q);
        if (point_segment_distance(m, pose.elbow, pose.tip) <= near) return 2;
        return point_segment_distance(m, pose.base, pose.elbow) <= near ? 1 : 0;
      }
    }
    return 0;
  }

  // --- the C-space view: U over the torus square (arm) or the slice at the current angle
  // (polygon), level lines, the descent's trajectory; press and drag to place the robot.
  void cspace(LabContext& ctx, ImVec2 size) {
    cspace_grids(ctx.playback.playing);
    const Kind kind = robot_kind();
    const bool arm = kind == Kind::Arm;
    cspace_view_.begin("##potential-cspace", size, arm ? Vec2(-kPi, -kPi) : scene_.workspace_min,
                       arm ? Vec2(kPi, kPi) : scene_.workspace_max);
    ctx.views["cspace"] = &cspace_view_;
    cspace_view_.draw_grid(arm ? "θ₁" : "x", arm ? "θ₂" : "y");
    cspace_view_.push_clip();
    draw_heat_map(cspace_view_, map_u_);
    draw_level_set(cspace_view_, map_u_.levels, kIso, 1.0f);
    // Over the level lines: the exact edges are the ones seen.
    if (arm) draw_arm_cobstacles(cspace_view_, *map_, theme::rgba(96, 96, 104));
    const Space& space = world_->space();
    if (descent_) {
      const auto& t = descent_->trajectory();
      for (std::size_t i = 1; i < t.size(); ++i) draw_chart_segment(cspace_view_, space, t[i - 1], space.difference(t[i - 1], t[i]), kTrajectory, 2.0f);
    }
    cspace_view_.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G");
    const Config q = shown();
    const ImVec2 at = cspace_view_.to_screen(Vec2(q[0], q[1]));
    cspace_view_.draw_list()->AddCircleFilled(at, 6.0f, world_->is_free(q) ? theme::kRobot : theme::kHit, 16);
    cspace_view_.draw_list()->AddCircle(at, 6.0f, theme::rgba(255, 255, 255), 16, 2.0f);
    cspace_view_.pop_clip();
    const std::string text = arm ? "U(θ₁, θ₂) on the torus; grey: C-obstacles"
                                  : "U(x, y, θ) at θ = " + fmt("%.3f", cspace_key_) + "; grey: a vertex on an obstacle";
    title(cspace_view_, text.c_str());
    if (cspace_view_.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) placing_ = true;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) placing_ = false;
    if (placing_) {
      const Vec2 m = cspace_view_.mouse_world();
      set_from(arm ? config({m.x(), m.y()}) : config({m.x(), m.y(), q[2]}));
    }
  }

  Scene scene_;
  SceneEditor editor_;
  WorkspaceView view_, cspace_view_;
  int grid_nodes_ = kGridNodes;  // heat maps' nodes per side (see rebuild())
  std::unique_ptr<CollisionWorld> world_;
  std::unique_ptr<PotentialField> field_;
  std::unique_ptr<ArmCSpaceMap> map_;
  std::unique_ptr<Descent> descent_;
  PotentialParams field_params_;
  DescentParams descent_params_;
  Config from_;
  Scene built_;  // the scene world_, field_ and the heat maps were built from
  std::string problem_;
  HeatMap ws_map_, map_u_;  // U_rep over the workspace; U over the C-space view
  std::vector<LevelSegment> ws_rings_;
  double cspace_key_ = std::numeric_limits<double>::quiet_NaN();
  long logged_ = -1;
  int drag_ = 0;
  Vec2 grab_offset_{0, 0};
  bool placing_ = false;
};

}  // namespace

CSL_REGISTER_LESSON(PotentialLesson, "potential", "Potential fields", "Planning");

}  // namespace csl::app
