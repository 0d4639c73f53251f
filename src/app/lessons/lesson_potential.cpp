// Lesson "Potential fields" (homework P13, the course's section 2.4): the attractive and
// repulsive fields a robot's control points feel, as a heat map with level lines and the rho0
// rings; the forces at each control point (the polygon's vertices, the arm's elbow and tip) and
// what they add up to in C-space through J^T (force and torque, or joint torques); drag the
// robot and watch them change; gradient descent step by step from where the robot is, its
// local minima and the random-walk escapes. Three examples: P13's rectangle among two polygons,
// a point robot and a cup (a local minimum), and the 2-link arm with its field on the torus.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>

#include "app/shell/instructor.hpp"
#include "app/shell/bundled_scenes.hpp"
#include "app/shell/fonts.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/lesson.hpp"
#include "core/checking/scene_text.hpp"
#include "app/shell/panel.hpp"
#include "app/shell/param_widgets.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "app/views/draw.hpp"
#include "app/views/field_draw.hpp"
#include "app/views/scene_editor.hpp"
#include "app/views/split.hpp"
#include "core/base/angles.hpp"
#include "core/fields/descent.hpp"
#include "core/fields/potential.hpp"
#include "core/fields/scalar_grid.hpp"
#include "core/geometry/geometry.hpp"
#include "core/planning/prm_text.hpp"
#include "core/teaching/cspace_map.hpp"
#include "core/teaching/work.hpp"

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
// Over the heat map (light yellow to brown) in every look: dark ink reads on all of it.
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

// The forces table's text is made of numbers formatted into fixed buffers and one printf per
// line: no temporary strings to destroy, which keeps the wasm module small.

// A number as the table shows it: 4 significant digits, plain ASCII (the tests read it back);
// `paren`: a negative one in parentheses, as a factor of a product.
struct Num {
  char s[32];
  explicit Num(double v, bool paren = false) {
    if (v == 0.0) v = 0.0;  // -0 too: a vertex outside rho0 has no push at all
    std::snprintf(s, sizeof s, paren && v < 0.0 ? "(%.4g)" : "%.4g", v);
  }
};

// "(x, y)" or "(x, y, z)". A component that is rounding noise next to the largest
// (grad rho = (1, 1e-17)) shows as 0: the vector a student computes by hand.
struct Vec {
  char s[112];
  Vec(const double* x, int n) {
    double big = 0.0;
    for (int i = 0; i < n; ++i) big = std::max(big, std::fabs(x[i]));
    int at = 0;
    for (int i = 0; i < n; ++i)
      at += std::snprintf(s + at, sizeof s - static_cast<std::size_t>(at), "%s%s", i == 0 ? "(" : ", ",
                          Num(std::isfinite(big) && std::fabs(x[i]) <= 1e-12 * big ? 0.0 : x[i]).s);
    std::snprintf(s + at, sizeof s - static_cast<std::size_t>(at), ")");
  }
  explicit Vec(const Vec2& v) : Vec(v.data(), 2) {}
  explicit Vec(const Config& c) : Vec(c.data(), static_cast<int>(std::min<Eigen::Index>(c.size(), 3))) {}
};

// A cell at the end of a row (out of line: one call per cell, not an inlined string each).
__attribute__((noinline)) void add(std::vector<std::string>& row, const char* text) { row.emplace_back(text); }


// "a₁", "a₁₂": the homework's name of vertex i, counted from 1 as the handout and P13's
// exercise count them (the table said a₀ where the exercise asked about a₁).
std::string vertex_name(int i) {
  std::string out = "a";
  for (char d : std::to_string(i + 1)) {
    const char sub[4] = {'\xE2', '\x82', static_cast<char>('\x80' + (d - '0')), 0};  // U+2080 + d
    out.append(sub);
  }
  return out;
}

// `with_force` off: |tau| is left out (an instructor hid P13's forces: instructor.hpp).
std::string describe(const DescentEvent& e, bool with_force = true) {
  const std::string at = format_config(e.q);
  const std::string force = with_force ? ", |τ| = " + fmt("%.3g", e.force) : std::string();
  switch (e.kind) {
    case DescentEvent::Kind::Descend:
      return "descend to " + at + ": U = " + fmt("%.4g", e.U) + force +
             (e.halvings > 0 ? " (step halved " + std::to_string(e.halvings) + "x to stay free)" : "");
    case DescentEvent::Kind::RandomWalk: return "random walk to " + at + ": U = " + fmt("%.4g", e.U);
    case DescentEvent::Kind::ReachedGoal: return "reached the goal at " + at;
    case DescentEvent::Kind::LocalMinimum:
      return std::string("local minimum at ") + at + (e.blocked ? " (every shorter step collides)" : "") +
             ": U = " + fmt("%.4g", e.U) + force + "; a random walk follows";
    case DescentEvent::Kind::GaveUp:
      return "stopped at " + at + ": " + (e.blocked ? "blocked" : "no progress") + ", no escapes left";
  }
  return "";
}

class PotentialLesson : public Lesson, private Stepper {
 public:
  PotentialLesson() { load(bundled_scene("p13")); }

  void on_show() override { logged_ = -1; }

  void update(LabContext& ctx) override {
    const int due = ctx.playback.due(static_cast<double>(ImGui::GetIO().DeltaTime));
    for (int i = 0; i < due && descent_ && !descent_->done(); ++i) descent_->step();
    if (!descent_ || descent_->done()) ctx.playback.playing = false;
    const long steps = descent_ ? descent_->steps() : 0;
    if (logged_ != steps) {
      if (steps == 0 || steps < logged_ || steps > logged_ + 1) ctx.log.clear();
      if (steps > 0) ctx.log.add(steps, csl::app::describe(descent_->last_event(), !instructor::hidden("p13_forces")));
      logged_ = steps;
    }
  }

  // P13 asks about the forces at the vertices: in the compact layout their table is on the
  // panel (the Controls tab), so the numbers stay there, the table open and scrolled to. (Hidden
  // by the instructor, the table holds no numbers: the View tab, as for other problems.)
  bool numbers_shown(LabContext& ctx) override {
    if (!ctx.compact || instructor::hidden("p13_forces")) return false;
    forces_open_ = reveal_forces_ = true;
    // Named tabs, not "here": the page's accessible copy reads it aloud, away from the canvas.
    ctx.notify("Forces: the table on the Controls tab. The robot and its arrows: the View tab.");
    return true;
  }

  void panel(LabContext& ctx) override {
    ImGui::TextWrapped("Every control point is pulled toward where it is at the goal and pushed away from each "
                       "obstacle closer than ρ₀. J^T turns each workspace force into a configuration-space "
                       "force; gradient descent follows their sum. Drag the robot; step the descent.");
    ImGui::TextDisabled("Example:");
    for (const Example& e : kExamples) {
      ui::flow(ui::button_width(e.label));  // same row while it fits (the panel may be narrow)
      instructor::FixedScene fixed;  // an example brings its scene
      if (ui::small_button(e.label)) set_example(e.scene, ctx);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.tooltip);
    }
    // In the compact layout (a phone) the forces area is here, the whole width, and scrolls with
    // the panel: under the views it left the two plots 108 px of a 390 x 844 screen.
    if (ctx.compact) forces_area(ImVec2(ImGui::GetContentRegionAvail().x, forces_panel_height()));

    if (panel::fold("Field")) field_controls();
    if (panel::fold("Gradient descent")) descent_controls(ctx);
    // Folded at first: the examples bring their scenes, and the panel's default fits 1280 x 800.
    if (panel::fold("Obstacles", false) && editor_.toolbar(scene_, ctx)) scene_changed();
  }

  void field_controls() {
    bool changed = false;
    PotentialParams f = field_params_;
    changed |= slider("ρ₀", &f.rho0, 0.02, 0.3, "region of influence of each obstacle", false, "rho0");
    changed |= slider("η", &f.eta, 1e-6, 1e-2, "repulsive gain", true, "eta");
    changed |= slider("ζ", &f.zeta, 0.1, 10.0, "attractive gain", true, "zeta");
    changed |= slider("switch d", &f.switch_distance, 0.01, 1.0, "quadratic pull within d of the goal, conic beyond", false,
                      "switch");
    if (robot_kind() == Kind::Polygon) {
      instructor::FixedParam fixed("from");
      double theta = from_[2];
      if (slider("start θ", &theta, -kPi, kPi, "the robot's orientation where the descent starts (drag the robot to move it)"))
        set_from(config({from_[0], from_[1], theta}));
    }
    if (changed && f.problem().empty()) {
      field_params_ = f;
      rebuild();
    }
  }

  void descent_controls(LabContext& ctx) {
    bool changed = false;
    DescentParams d = descent_params_;
    changed |= slider("step", &d.step, 0.001, 0.1, "alpha: the length of one descent step", true, "step");
    int escapes = d.escapes;
    {
      instructor::FixedParam fixed("escapes");
      if (ImGui::SliderInt("escapes", &escapes, 0, 20, "%d", ImGuiSliderFlags_AlwaysClamp)) {
        d.escapes = escapes;
        changed = true;
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("random walks allowed out of local minima (0: plain descent)");
    }
    int seed = static_cast<int>(std::min<std::uint64_t>(d.seed, 2147483647u));
    {
      instructor::FixedParam fixed("seed");
      if (ImGui::InputInt("seed", &seed) && seed >= 0) {
        d.seed = static_cast<std::uint64_t>(seed);
        changed = true;
      }
    }
    if (changed && d.problem().empty()) {
      descent_params_ = d;
      restart_descent();
    }
    // Back to the start and play: the button says "descend", so the robot moves at once.
    {
      instructor::FixedParam fixed("from");
      if (ImGui::Button("Descend from the start")) {
        set_from(scene_.start);
        ctx.playback.playing = descent_ != nullptr;
      }
    }
    web::record_control("potential-descend");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("from the scene's start, played step by step (Space pauses)");
    status_text();
  }

  // The views on top, the forces table under them (the panel is too narrow for its vectors). In
  // the compact layout the views have the whole area; the table is on the Controls tab (panel()).
  void views(LabContext& ctx, ImVec2 size) override {
    const float below = ctx.compact ? 0.0f : forces_height(size);
    const ImVec2 top(size.x, ctx.compact ? size.y : std::max(120.0f, size.y - below - ImGui::GetStyle().ItemSpacing.y));
    if (robot_kind() == Kind::Point) {
      workspace(ctx, top);
    } else {
      // (Stacked when the whole area is portrait: the forces under them make `top` look wide.)
      const Split s = split_as(top, size.x < size.y);
      workspace(ctx, s.first);
      between(s);
      cspace(ctx, s.second);
    }
    if (!ctx.compact) forces_area(ImVec2(size.x, below));
    editor_.help_window();
  }

  Scene* scene() override { return &scene_; }
  std::vector<LessonView> views_kept() override {
    std::vector<LessonView> out{{"workspace", &view_, scene_.workspace_min, scene_.workspace_max}};
    // A point's C-space is its workspace, one view; an arm's is the torus square.
    if (robot_kind() == Kind::Arm) out.push_back({"cspace", &cspace_view_, Vec2(-kPi, -kPi), Vec2(kPi, kPi)});
    else if (robot_kind() != Kind::Point) out.push_back({"cspace", &cspace_view_, scene_.workspace_min, scene_.workspace_max});
    return out;
  }
  SceneEditor* editor() override { return &editor_; }
  bool accept_scene(const Scene& s, std::string& why) override {
    // Every robot type has control points; the arm's C-space view is the torus square (2 links).
    if (std::holds_alternative<ArmRobot>(s.robot) && !is_two_link_arm(s.robot)) {
      why = "this lesson shows the 2-link arm on its torus; the scene's arm has " + std::to_string(robot_dof(s.robot)) + " links";
      return false;
    }
    editor_.replace(scene_, s);
    load(s);
    return true;
  }
  bool undo() override { return editor_.undo(scene_) && (scene_changed(), true); }
  bool redo() override { return editor_.redo(scene_) && (scene_changed(), true); }

  json state(const json& args) const override {
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
      json& more = points.back();  // (assignments: lighter in the wasm module than the list above)
      more["grad_rho"] = p.nearest_obstacle < 0 ? json(nullptr) : finite_vec(p.nearest.grad);
      more["nearest_obstacle"] = p.nearest_obstacle;
      more["within_rho0"] = !p.terms.empty();
      more["tau"] = finite_config(p.tau);
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
    forces_state(r, args, out);
    return out;
  }

  // The sums, tau's parts and the forces table as shown (its text, for the tests to read back).
  void forces_state(const PotentialReport& r, const json& args, json& out) const {
    out["U_rep"] = std::isfinite(r.U_rep) ? json(r.U_rep) : json(nullptr);
    out["F_att"] = finite_vec(r.F_att);
    out["F_rep"] = finite_vec(r.F_rep);
    out["tau_att"] = finite_config(r.tau_att);
    out["tau_rep"] = finite_config(r.tau_rep);
    const ForcesText t = forces_text(r);
    json& table = out["forces_table"];
    table["open"] = forces_open_;
    json& header = table["header"] = json::array();
    for (const char* h : t.header) header.push_back(h);
    json& rows = table["rows"] = json::array();
    for (const auto& row : t.rows) rows.push_back(row);
    table["sum"] = t.sum;
    table["tau"] = t.tau;
    table["chosen"] = t.chosen;
    table["equations"] = t.equations;
    // Where the table was drawn last frame (logical pixels in the canvas): only when asked, as it
    // depends on the window, not on the lesson.
    if (!args.is_object() || !args.value("layout", false)) return;
    json& layout = out["forces_layout"];
    json& rects = layout["rows"] = json::array();
    for (const auto& rc : layout_.rows) rects.push_back(std::vector<float>(rc.begin(), rc.end()));
    layout["bottom"] = layout_.bottom;
    layout["table_right"] = layout_.table_right;
    layout["area_right"] = layout_.area_right;
    layout["scrolls"] = layout_.scrolls;
    layout["header_right"] = layout_.header_right;
    layout["header_clip"] = layout_.header_clip;
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    PotentialParams f = field_params_;
    DescentParams d = descent_params_;
    std::optional<Config> from;
    int point = chosen_;
    const auto number = [](const json& v, const std::string& k) {
      if (!v.is_number() || !std::isfinite(v.get<double>())) throw ApiError(k + ": a finite number");
      return v.get<double>();
    };
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& k = it.key();
      // The field's and the descent's numbers: their specs' ranges and texts (core/base/params.hpp).
      if (k == "rho0") f.rho0 = api_param(kFieldRho0, *it);
      else if (k == "eta") f.eta = api_param(kFieldEta, *it);
      else if (k == "zeta") f.zeta = api_param(kFieldZeta, *it);
      else if (k == "switch") f.switch_distance = api_param(kFieldSwitch, *it);
      else if (k == "step") d.step = api_param(kDescentStep, *it);
      else if (k == "escapes") d.escapes = static_cast<int>(api_param(kDescentEscapes, *it));
      else if (k == "seed") {
        if (!it->is_number_unsigned()) throw ApiError("seed: an integer >= 0");
        d.seed = it->get<std::uint64_t>();
      } else if (k == "point") {
        // Any index: one past the robot's control points means "the one pushed hardest" (a link
        // may carry a point of another robot's scene).
        if (!it->is_number_integer() || it->get<long long>() < -1 || it->get<long long>() > 100000)
          throw ApiError("point: a control point's index (-1: the one pushed hardest)");
        point = it->get<int>();
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
    chosen_ = point;
    if (from) from_ = world_->space().wrap(*from);
    rebuild();
  }

  json params() const override {
    return {{"rho0", field_params_.rho0}, {"eta", field_params_.eta}, {"zeta", field_params_.zeta},
            {"switch", field_params_.switch_distance}, {"step", descent_params_.step},
            {"escapes", descent_params_.escapes}, {"seed", descent_params_.seed}, {"from", config_to_json(from_)},
            {"point", chosen_}};
  }

  std::vector<ParamField> param_fields() const override {
    return {{"rho0", "rho0", &kFieldRho0},   {"eta", "eta", &kFieldEta},       {"zeta", "zeta", &kFieldZeta},
            {"switch", "switch d", &kFieldSwitch}, {"step", "step alpha", &kDescentStep}, {"escapes", "escapes", &kDescentEscapes},
            {"seed", "seed", &kSeed},
            {"from", "descent start", nullptr, {}, "the configuration the descent starts from, comma-separated"},
            {"point", "control point shown", nullptr, {}, "the control point whose equations are worked (-1: the one pushed hardest)"}};
  }

  std::string describe() const override {
    const Config q = shown();
    std::string out = Lesson::describe() + " The robot is at " + config_text(q) + ", " +
                      (world_->is_free(q) ? "free" : "in collision") + ". ";
    if (!descent_) return out + "No descent has started.";
    out += "Descent step " + std::to_string(descent_->steps()) + ": ";
    return out + (descent_->done() ? std::string("finished, ") + outcome_name(descent_->outcome()) + "." : "running.");
  }

  Stepper* stepper() override { return this; }

  // ---- Stepper
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

  // `key`: the parameter it sets, drawn disabled while the instructor fixed it.
  bool slider(const char* label, double* v, double lo, double hi, const char* tip, bool log = false, const char* key = "") {
    instructor::FixedParam fixed(key);
    // AlwaysClamp: a value typed with Ctrl+click stays in range too (0 for rho0 would be invalid).
    const ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | (log ? ImGuiSliderFlags_Logarithmic : 0);
    const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, v, &lo, &hi, log ? "%.3g" : "%.3f", flags);
    if (ImGui::IsItemHovered() && !fixed.locked()) ImGui::SetTooltip("%s", tip);
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
    chosen_ = -1;
    forces_width_ = 0.0f;  // another robot, another table: measure it again
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
    for (const char* key : {"start", "name"}) {  // (a new name, "(edited)", changes no field)
      now.erase(key);
      before.erase(key);
    }
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
      ImGui::TextColored(theme::vec4(theme::kTextBad), "%s", problem_.c_str());
      return;
    }
    const Descent& d = *descent_;
    if (instructor::hidden("p13_forces"))  // |tau| is P13's net force's size
      ImGui::Text("step %ld  to the goal %.3f", d.steps(), d.distance_to_goal());
    else
      ImGui::Text("step %ld  |τ| = %.3g  to the goal %.3f", d.steps(), d.force(), d.distance_to_goal());
    robot_summary();
    ImGui::Text("local minima %d  escapes used %d of %d", d.local_minima(), d.escapes_used(), d.params().escapes);
    switch (d.outcome()) {
      case DescentOutcome::Running: break;
      case DescentOutcome::Goal: ImGui::TextColored(theme::vec4(theme::kTextGood), "reached the goal"); break;
      case DescentOutcome::Escaped:
        ImGui::TextColored(theme::vec4(theme::kTextGood), "reached the goal after %d random walk(s)", d.escapes_used());
        break;
      case DescentOutcome::LocalMinimum:
        ImGui::TextColored(theme::vec4(theme::kTextBad), "stuck in a local minimum");
        ImGui::TextWrapped("The descent makes no progress here, away from the goal: attraction and repulsion "
                           "nearly cancel, so its steps of fixed length go back and forth around a minimum of U "
                           "(|τ| is small there, not zero), or every step is blocked. Allow escapes: random "
                           "walks out of the basin, then descent again.");
        break;
      case DescentOutcome::MaxSteps: ImGui::TextColored(theme::vec4(theme::kTextBad), "out of steps"); break;
    }
  }

  // U at the robot, in the descent's status; the table of every control point is under the views
  // (in the compact layout, in the panel).
  void robot_summary() {
    const PotentialReport r = field_->evaluate(shown());
    if (r.contact) {
      ImGui::TextColored(theme::vec4(theme::kTextBad), "a control point is on an obstacle: U is infinite");
      return;
    }
    if (instructor::hidden("p13_forces")) ImGui::Text("U = %.4g", r.U);  // (its repulsive part comes from each rho)
    else ImGui::Text("U = %.4g  (attractive %.4g, repulsive %.4g)", r.U, r.U_att, r.U_rep);
  }

  // The control point whose equations are worked: the one chosen, or (none chosen, or the
  // robot has fewer points now) the one pushed hardest, else the one nearest an obstacle.
  int chosen_point(const PotentialReport& r) const {
    const int n = static_cast<int>(r.points.size());
    if (chosen_ >= 0 && chosen_ < n) return chosen_;
    int best = 0;
    for (int i = 1; i < n; ++i) {
      const ControlPointReport &a = r.points[static_cast<std::size_t>(i)], &b = r.points[static_cast<std::size_t>(best)];
      const double fa = length(a.repulsive.F), fb = length(b.repulsive.F);
      if (fa > fb || (fa == fb && a.nearest.rho < b.nearest.rho)) best = i;
    }
    return best;
  }

  std::string point_label(int i) const {
    return robot_kind() == Kind::Polygon ? vertex_name(i) : control_point_name(scene_.robot, i);
  }

  // What the forces table and the worked equations show, as text: drawn by forces_area() and
  // reported by state() (the tests read the numbers back), from one evaluation of the field.
  struct ForcesText {
    std::array<const char*, 6> header;
    std::vector<std::vector<std::string>> rows;  // one per control point
    std::vector<bool> outside;                   // beyond rho0 of every obstacle: no push
    std::vector<std::string> sum;                // the sums over the control points
    std::vector<std::string> tau;                // tau = tau_rep + tau_att
    int chosen = 0;                              // the point whose equations are worked
    std::vector<std::string> equations;
  };

  ForcesText forces_text(const PotentialReport& r) const {
    ForcesText t;
    const Kind kind = robot_kind();
    // Short headers: a 900 px embed leaves the table under 600 px.
    t.header = {kind == Kind::Polygon ? "a_i" : "point", "ρ", "∇ρ", "F_rep,i", "F_att,i", kind == Kind::Point ? "J^T F = F" : "J_i^T F_i"};
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const ControlPointReport& p = r.points[i];
      const bool outside = p.terms.empty(), none = p.nearest_obstacle < 0;
      t.outside.push_back(outside);
      auto& row = t.rows.emplace_back();
      add(row, point_label(static_cast<int>(i)).c_str());
      add(row, none ? "-" : Num(p.nearest.rho).s);
      add(row, none ? "-" : Vec(p.nearest.grad).s);
      add(row, outside ? "(0, 0) outside ρ₀" : Vec(p.repulsive.F).s);
      add(row, Vec(p.attractive.F).s);
      add(row, Vec(p.tau).s);
    }
    for (const char* cell : {"Σ", "", ""}) add(t.sum, cell);
    add(t.sum, Vec(r.F_rep).s);
    add(t.sum, Vec(r.F_att).s);
    add(t.sum, Vec(r.tau).s);
    t.tau.push_back(ui::format("τ = Σ J_i^T F_i = τ_rep + τ_att = %s + %s = %s%s", Vec(r.tau_rep).s, Vec(r.tau_att).s,
                         Vec(r.tau).s, kind == Kind::Polygon ? "  (F_x, F_y, torque)" : kind == Kind::Arm ? "  (joint torques)" : ""));
    if (r.points.empty()) return t;
    t.chosen = chosen_point(r);
    worked_equations(r, t.chosen, t.equations);
    return t;
  }

  // (5.5) and (5.6) with the numbers put in for control point k, then its J^T F.
  void worked_equations(const PotentialReport& r, int k, std::vector<std::string>& out) const {
    const ControlPointReport& p = r.points[static_cast<std::size_t>(k)];
    const std::string name = point_label(k);
    const char* a = name.c_str();
    const Num rho0(field_params_.rho0), eta(field_params_.eta);
    if (p.nearest_obstacle < 0) {
      out.push_back(ui::format("%s = %s: no obstacles, so no repulsion", a, Vec(p.position).s));
    } else {
      out.push_back(ui::format("%s = %s: nearest obstacle %d, ρ = %s, ∇ρ = %s; ρ₀ = %s, η = %s", a, Vec(p.position).s,
                         p.nearest_obstacle, Num(p.nearest.rho).s, Vec(p.nearest.grad).s, rho0.s, eta.s));
      if (p.terms.empty())
        out.push_back(ui::format("ρ = %s > ρ₀ = %s: outside ρ₀, so (5.5) U_rep = 0 and (5.6) F_rep = (0, 0)",
                           Num(p.nearest.rho).s, rho0.s));
    }
    for (const RepulsiveTerm& term : p.terms) {
      char which[32] = "";
      if (p.terms.size() > 1) std::snprintf(which, sizeof which, "obstacle %d: ", term.obstacle);
      const double rho = term.distance.rho;
      if (rho == 0.0) {
        out.push_back(ui::format("%sρ = 0: on the obstacle, U_rep and F_rep are infinite", which));
        continue;
      }
      const Num n_rho(rho), d(1.0 / rho - 1.0 / field_params_.rho0, true);
      const Vec grad(term.distance.grad);
      out.push_back(ui::format("%s(5.5) U_rep = ½ η (1/ρ − 1/ρ₀)² = ½ · %s · (1/%s − 1/%s)² = ½ · %s · %s² = %s", which,
                         eta.s, n_rho.s, rho0.s, eta.s, d.s, Num(term.field.U).s));
      out.push_back(ui::format("%s(5.6) F_rep = η (1/ρ − 1/ρ₀) (1/ρ²) ∇ρ = %s · (1/%s − 1/%s) · (1/%s²) · %s = %s · %s · %s · %s = %s",
                         which, eta.s, n_rho.s, rho0.s, n_rho.s, grad.s, eta.s, d.s, Num(1.0 / (rho * rho)).s, grad.s,
                         Vec(term.field.F).s));
    }
    if (p.terms.size() > 1) out.push_back(ui::format("F_rep = the sum of those terms = %s", Vec(p.repulsive.F).s));
    const Vec2 F = p.attractive.F + p.repulsive.F;
    const std::string sum = ui::format("F = F_att + F_rep = %s + %s = %s", Vec(p.attractive.F).s, Vec(p.repulsive.F).s, Vec(F).s);
    const PointJacobian& J = p.jacobian;
    switch (robot_kind()) {
      case Kind::Polygon: {
        // J = [[1, 0, -(Rv)_y], [0, 1, (Rv)_x]]: the lever arm is read off the Jacobian.
        const double rx = J(1, 2), ry = -J(0, 2);
        out.push_back(ui::format("R v = %s − (x, y) = %s;  %s", a, Vec(Vec2(rx, ry)).s, sum.c_str()));
        out.push_back(ui::format("%s: J^T F = (F_x, F_y, (R v)_x F_y − (R v)_y F_x) = (%s, %s, %s · %s − %s · %s) = %s", a,
                           Num(F.x()).s, Num(F.y()).s, Num(rx, true).s, Num(F.y(), true).s, Num(ry, true).s,
                           Num(F.x(), true).s, Vec(p.tau).s));
        break;
      }
      case Kind::Arm:
        out.push_back(ui::format("J = [[%s, %s], [%s, %s]];  %s", Num(J(0, 0)).s, Num(J(0, 1)).s, Num(J(1, 0)).s,
                           Num(J(1, 1)).s, sum.c_str()));
        out.push_back(ui::format("%s: J^T F = (J₁₁ F_x + J₂₁ F_y, J₁₂ F_x + J₂₂ F_y) = %s", a, Vec(p.tau).s));
        break;
      case Kind::Point: out.push_back("J = I, so J^T F = " + sum); break;
    }
  }

  // Under the views: the table of every control point (click a row to work its equations),
  // the sums, tau, and (5.5), (5.6) with the numbers put in. Collapsible, open at first.
  void forces_area(ImVec2 size) {
    ImGui::PushFont(fonts().small);  // compact: the views above need the height
    ImGui::SetNextItemOpen(forces_open_);
    // The whole title where it fits; narrower (a phone upright, where it was cut at the right
    // edge), the name alone, and what the area works out on a line under it.
    const char* const what = "ρ, ∇ρ, (5.5), (5.6), τ = Σ J^T F";
    const std::string full = std::string("Forces at the control points: ") + what;
    const float text_x = ImGui::GetFontSize() + 3.0f * ImGui::GetStyle().FramePadding.x;  // the arrow
    title_fits_ = text_x + ImGui::CalcTextSize(full.c_str()).x <= ImGui::GetContentRegionAvail().x;
    const char* const title = title_fits_ ? full.c_str() : "Forces at the control points";
    forces_open_ = ImGui::CollapsingHeader((std::string(title) + "###forces").c_str());
    layout_.header_right = ImGui::GetItemRectMin().x + text_x + ImGui::CalcTextSize(title).x;
    layout_.header_clip = ImGui::GetItemRectMax().x;
    if (reveal_forces_) {
      ImGui::SetScrollHereY(0.0f);  // the panel, to the header (numbers_shown)
      reveal_forces_ = false;
    }
    layout_.rows.clear();
    layout_.scrolls = false;
    if (!forces_open_) {
      ImGui::PopFont();
      return;
    }
    if (!title_fits_) ImGui::TextDisabled("%s", what);
    if (instructor::hidden("p13_forces")) {
      // P13's numbers; the arrows in the view stay (directions, not values).
      instructor::hidden_line("ρ, ∇ρ, the forces and τ at the control points");
      ImGui::PopFont();
      return;
    }
    const PotentialReport r = field_->evaluate(shown());
    const ForcesText t = forces_text(r);
    const float avail = std::max(40.0f, size.y - ImGui::GetFrameHeightWithSpacing());
    ImGui::BeginChild("##forces", ImVec2(size.x, avail), false);
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, 2.0f));
    ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(2.0f, 1.0f));
    // One table where its six columns fit; narrower (a phone), two under each other, the point's
    // name in both: ρ, ∇ρ and F_rep,i, then F_att,i and J_i^T F_i (they were cut off on the right).
    layout_.table_right = 0.0f;
    if (table_width(t, {0, 1, 2, 3, 4, 5}) <= ImGui::GetContentRegionAvail().x) {
      forces_table(t, "##vertex-forces", {0, 1, 2, 3, 4, 5}, true);
    } else {
      forces_table(t, "##vertex-forces", {0, 1, 2, 3}, true);
      forces_table(t, "##vertex-forces-2", {0, 4, 5}, false);
    }
    layout_.area_right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    // Room for the longest case under the table (tau, and (5.5), (5.6) with one of them wrapped:
    // 8 lines), so that choosing another row or moving the robot does not move the table.
    const float reserved = ImGui::GetCursorPosY() + 8.0f * ImGui::GetTextLineHeightWithSpacing() + ImGui::GetStyle().ItemSpacing.y;
    if (r.contact) ImGui::TextColored(theme::vec4(theme::kTextBad), "a control point is on an obstacle: U is infinite");
    for (const std::string& line : t.tau) wrapped(line);
    ImGui::Spacing();
    for (const std::string& line : t.equations) wrapped(line);
    // The views above must not move under the mouse: the area keeps its height during a drag,
    // and otherwise only grows (a number one digit longer wraps a line) until the width changes.
    const float measured = std::max(reserved, ImGui::GetCursorPosY());
    if (size.x != forces_width_) forces_content_h_ = measured;
    else if (drag_ == 0 && !placing_) forces_content_h_ = std::max(forces_content_h_, measured);
    forces_width_ = size.x;
    layout_.bottom = ImGui::GetItemRectMax().y;
    layout_.scrolls = ImGui::GetScrollMaxY() > 0.0f;
    ImGui::PopStyleVar(2);
    ImGui::EndChild();
    ImGui::PopFont();
  }

  // A line wrapped at its spaces only (ImGui's wrapping also breaks after '.' and ',', inside
  // numbers); the continuation indented.
  static void wrapped(const std::string& text) {
    const float width = ImGui::GetContentRegionAvail().x, indent = 16.0f;
    std::size_t begin = 0;
    bool first = true;
    while (begin < text.size()) {
      const float room = first ? width : width - indent;
      std::size_t end = text.size(), last_space = std::string::npos;
      for (std::size_t i = begin; i < text.size(); ++i) {
        if (text[i] != ' ') continue;
        if (ImGui::CalcTextSize(text.data() + begin, text.data() + i).x > room) {
          end = last_space == std::string::npos ? i : last_space;
          break;
        }
        last_space = i;
      }
      if (end == text.size() && ImGui::CalcTextSize(text.data() + begin, text.data() + end).x > room && last_space != std::string::npos)
        end = last_space;  // the last word does not fit either
      if (!first) ImGui::SetCursorPosX(ImGui::GetCursorPosX() + indent);
      ImGui::TextUnformatted(text.data() + begin, text.data() + end);
      begin = end < text.size() ? end + 1 : end;
      first = false;
    }
  }

  // The width a table of `columns` of the forces takes (fixed-fit columns: the widest cell, the
  // cell padding, an inner border).
  static float table_width(const ForcesText& t, std::initializer_list<int> columns) {
    const ImGuiStyle& style = ImGui::GetStyle();
    float total = 0.0f;
    for (const int c : columns) {
      float w = ImGui::CalcTextSize(t.header[static_cast<std::size_t>(c)]).x;
      for (const auto& row : t.rows) w = std::max(w, ImGui::CalcTextSize(row[static_cast<std::size_t>(c)].c_str()).x);
      w = std::max(w, ImGui::CalcTextSize(t.sum[static_cast<std::size_t>(c)].c_str()).x);
      total += w + 2.0f * style.CellPadding.x + 1.0f;
    }
    return total;
  }

  // A table of the forces' `columns` (0: the point, a row to click; 3, 4: F_rep, F_att, coloured).
  // `rows`: record where its rows are (the tests click them).
  void forces_table(const ForcesText& t, const char* id, std::initializer_list<int> columns, bool rows) {
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_NoHostExtendX;
    const float left = ImGui::GetCursorScreenPos().x;
    if (!ImGui::BeginTable(id, static_cast<int>(columns.size()), flags)) return;
    for (const int c : columns) ImGui::TableSetupColumn(t.header[static_cast<std::size_t>(c)]);
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const bool chosen = static_cast<int>(i) == t.chosen;
      const ImGuiSelectableFlags fixed = instructor::param_locked("point") ? ImGuiSelectableFlags_Disabled : 0;
      if (ImGui::Selectable(t.rows[i][0].c_str(), chosen, ImGuiSelectableFlags_SpanAllColumns | fixed)) chosen_ = static_cast<int>(i);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("work (5.5) and (5.6) for %s", t.rows[i][0].c_str());
      const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
      if (rows) layout_.rows.push_back({lo.x, lo.y, hi.x, hi.y});
      for (const int c : columns) {
        if (c == 0) continue;  // the point: the row's Selectable
        ImGui::TableNextColumn();
        const ImVec4 colour = c == 3 ? (t.outside[i] ? theme::vec4(theme::kTextDim) : theme::vec4(theme::kTextBad))
                              : c == 4 ? theme::vec4(theme::kTextGood) : ImGui::GetStyleColorVec4(ImGuiCol_Text);
        ImGui::TextColored(colour, "%s", t.rows[i][static_cast<std::size_t>(c)].c_str());
      }
    }
    ImGui::TableNextRow();
    for (const int c : columns) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(t.sum[static_cast<std::size_t>(c)].c_str());
    }
    ImGui::EndTable();
    // (The item's rectangle ends at the clip: the width it needs tells a table cut off.)
    layout_.table_right = std::max({layout_.table_right, ImGui::GetItemRectMax().x, left + table_width(t, columns)});
  }

  // The forces area's height on the panel: all of its content (the panel scrolls).
  float forces_panel_height() const {
    ImGui::PushFont(fonts().small);
    const float header = ImGui::GetFrameHeightWithSpacing();
    ImGui::PopFont();
    if (!forces_open_) return header;
    return header + forces_content_h_ + (title_fits_ ? 0.0f : ImGui::GetTextLineHeightWithSpacing());
  }

  // How tall the area under the views is: what its content took last frame, at most half of
  // the main area (a small window scrolls it rather than squeeze the views to nothing).
  float forces_height(ImVec2 size) const {
    ImGui::PushFont(fonts().small);
    const float header = ImGui::GetFrameHeightWithSpacing();
    ImGui::PopFont();
    if (!forces_open_) return header;
    return std::min(header + forces_content_h_, 0.5f * size.y);
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

    const bool dragging = robot_drag(q);
    if (refused_) {
      ctx.notify(instructor::param_refusal("from") + ": the descent starts where it is.", 4.0);
      refused_ = false;
    }
    if (dragging) return;
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
    if (robot_kind() != Kind::Polygon || r.contact) return point_labels(q, r);
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
    point_labels(q, r);  // over the arrows
  }

  // The table's names at the control points (a₁..a₄ at the polygon's vertices, outward from
  // its centre), and a ring around the one whose equations are worked.
  void point_labels(const Config& q, const PotentialReport& r) {
    if (r.points.empty()) return;
    ImDrawList* dl = view_.draw_list();
    const int chosen = chosen_point(r);
    // Outward from the polygon's reference point, or from the arm's base.
    const ImVec2 centre = view_.to_screen(robot_kind() == Kind::Arm ? std::get<ArmRobot>(scene_.robot).base : Vec2(q[0], q[1]));
    ImGui::PushFont(fonts().small);
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const ImVec2 at = view_.to_screen(r.points[i].position);
      if (static_cast<int>(i) == chosen) dl->AddCircle(at, 7.5f, theme::kBlue, 16, 2.0f);
      if (robot_kind() == Kind::Point) continue;  // one point: nothing to tell apart
      ImVec2 d(at.x - centre.x, at.y - centre.y);
      const float len = std::sqrt(d.x * d.x + d.y * d.y);
      d = len > 1e-3f ? ImVec2(d.x / len, d.y / len) : ImVec2(0.0f, -1.0f);
      const std::string name = point_label(static_cast<int>(i));
      const ImVec2 ts = ImGui::CalcTextSize(name.c_str());
      const ImVec2 c(at.x + d.x * (10.0f + 0.5f * ts.x), at.y + d.y * (8.0f + 0.5f * ts.y));
      const ImVec2 lo(c.x - 0.5f * ts.x, c.y - 0.5f * ts.y);
      dl->AddRectFilled(ImVec2(lo.x - 2, lo.y), ImVec2(lo.x + ts.x + 2, lo.y + ts.y), theme::with_alpha(theme::kLabelBox, 190), 3.0f);
      dl->AddText(lo, theme::kLabel, name.c_str());
    }
    ImGui::PopFont();
  }

  // Press on the robot and drag: it moves (the point and the polygon translate; the arm's links
  // turn their joints); the descent restarts from there. Returns true while dragging.
  bool robot_drag(const Config& q) {
    const Vec2 m = view_.mouse_world();
    if (drag_ == 0 && view_.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && editor_.tool() == SceneEditor::Tool::Select) {
      drag_ = grab(q, m);
      grab_offset_ = Vec2(q[0], q.size() > 1 ? q[1] : 0.0) - m;
      if (drag_ != 0 && instructor::param_locked("from")) {  // where the descent starts is fixed
        drag_ = 0;
        refused_ = true;
      }
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
    const double near = view_.reach(8.0f);
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
    cspace_view_.set_angular(arm, arm);
    cspace_view_.draw_grid(arm ? "θ₁" : "x", arm ? "θ₂" : "y");
    cspace_view_.push_clip();
    draw_heat_map(cspace_view_, map_u_);
    draw_level_set(cspace_view_, map_u_.levels, kIso, 1.0f);
    // Over the level lines: the exact edges are the ones seen.
    if (arm) draw_arm_cobstacles(cspace_view_, *map_, theme::with_alpha(theme::kCObstacle, 255));
    const Space& space = world_->space();
    if (descent_) {
      const auto& t = descent_->trajectory();
      for (std::size_t i = 1; i < t.size(); ++i) draw_chart_segment(cspace_view_, space, t[i - 1], space.difference(t[i - 1], t[i]), kTrajectory, 2.0f);
    }
    cspace_view_.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G");
    const Config q = shown();
    const ImVec2 at = cspace_view_.to_screen(Vec2(q[0], q[1]));
    cspace_view_.draw_list()->AddCircleFilled(at, 6.0f, world_->is_free(q) ? theme::kRobot : theme::kHit, 16);
    cspace_view_.draw_list()->AddCircle(at, 6.0f, theme::kCanvasBg, 16, 2.0f);
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
  int chosen_ = -1;  // the control point whose equations are worked; -1: the one pushed hardest
  bool forces_open_ = true;
  float forces_content_h_ = 200.0f;  // the forces area's content, measured each frame...
  float forces_width_ = 0.0f;        // ...at this width
  struct Layout {                    // where the forces area drew, for the tests (state {layout: true})
    std::vector<std::array<float, 4>> rows;  // each row's first cell: x0, y0, x1, y1
    float bottom = 0.0f;                     // the last line's bottom
    float table_right = 0.0f;                // the table's right edge...
    float area_right = 0.0f;                 // ...and the visible area's (without a scrollbar)
    bool scrolls = false;                    // its content did not fit
    float header_right = 0.0f;               // the header's title ends here...
    float header_clip = 0.0f;                // ...and its frame here
  } layout_;
  bool title_fits_ = true;      // the header's whole title fits its width (forces_area)
  bool reveal_forces_ = false;  // scroll the panel to the forces area next frame (numbers_shown)
  int drag_ = 0;
  bool refused_ = false;  // a press on the robot while its start is fixed (the notice says so)
  Vec2 grab_offset_{0, 0};
  bool placing_ = false;
};

}  // namespace

CSL_REGISTER_LESSON(PotentialLesson, "potential", "Potential fields", "Planning");

}  // namespace csl::app
