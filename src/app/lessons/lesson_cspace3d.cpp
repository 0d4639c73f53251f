// Lesson "C-spaces in 3-D": the handout's P1 (a robot that slides and turns in the plane, SE(2) =
// R^2 x S^1) and P2, P5 (3-link arms, T^3) as pictures. The workspace beside the C-obstacle
// volume (volume_view.*): a coarse voxel block for the shape, cut by a plane across the third
// coordinate (theta, or theta1) that shows the exact slice there (se2_slice, arm3_slice).
// Scrubbing the plane turns the robot in the workspace; moving the robot moves its point in the
// block. A planner (PRM, PRM*, Lazy PRM, RRT, RRT-Connect: the CLI's --planner) runs in the 3-D
// space and its roadmap or tree is drawn in the block, edges that leave through a glued face
// coming back through its twin. Checked questions (core/teaching/volume_questions.hpp) ask what
// the picture shows: the space's name and dimension, its glued faces, a way through a seam, the
// free share.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "app/lessons/planner_session.hpp"
#include "app/lessons/prm_controls.hpp"
#include "app/shell/bundled_scenes.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/lesson.hpp"
#include "app/shell/panel.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "app/views/draw.hpp"
#include "app/views/scene_editor.hpp"
#include "app/views/split.hpp"
#include "app/views/volume_view.hpp"
#include "core/base/angles.hpp"
#include "core/base/text.hpp"
#include "core/checking/scene_text.hpp"
#include "core/geometry/geometry.hpp"
#include "core/planning/planner_choice.hpp"
#include "core/planning/planner_json.hpp"
#include "core/planning/planner_text.hpp"
#include "core/teaching/cspace_volume.hpp"
#include "core/teaching/volume_questions.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;

// The block drawn: coarse enough for a few thousand faces a frame. The free fraction the lesson
// reports is counted on a finer volume (the core's exact cells at their centres).
constexpr int kDrawXY = 32, kDrawZ = 32;
constexpr int kFineSe2XY = 128, kFineSe2Z = 64, kFineArm = 96;
// Columns of the arm's exact slice drawn in the plane (each exact along theta3).
constexpr int kArmColumns = 128;

class Cspace3dLesson : public Lesson {
 public:
  Cspace3dLesson() : scene_(bundled_scene("polygon-robot")), session_(scene_, params_) {
    q_ = scene_.start;
    rebuild_volumes();
  }

  void on_show() override { session_.forget_log(); }
  void update(LabContext& ctx) override { session_.update(ctx, "ready: press Step or Play to grow a roadmap in 3-D"); }

  void panel(LabContext& ctx) override {
    ImGui::TextWrapped(arm() ? "Three joint angles fix the arm: Q = S¹ × S¹ × S¹ = T³, drawn as a cube whose "
                               "opposite faces are glued. The plane cuts it at one θ₁: there the rest is the "
                               "(θ₂, θ₃) square of links 2 and 3, or all blocked where link 1 hits."
                             : "Where the robot is and how it is turned: Q = R² × S¹ = SE(2), drawn as x and y "
                               "across and θ up, the top and bottom glued (θ = π is θ = -π). The plane cuts "
                               "it at one θ: there the C-obstacle is the obstacles grown by the turned robot.");
    ImGui::AlignTextToFramePadding();
    ImGui::TextDisabled("robot:");
    ImGui::SameLine();
    int choice = arm() ? 1 : 0;
    if (ImGui::RadioButton("polygon (SE(2))", &choice, 0) && arm()) load(ctx, "polygon-robot");
    ui::flow(ui::toggle_width("3-link arm (T³)"));
    if (ImGui::RadioButton("3-link arm (T³)", &choice, 1) && !arm()) load(ctx, "arm-3link");
    float cut = static_cast<float>(q_[cut_axis()]);
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::SliderFloat("##cut", &cut, static_cast<float>(-kPi), static_cast<float>(kPi),
                           arm() ? "cut at θ₁ = %.2f" : "cut at θ = %.2f"))
      q_[cut_axis()] = wrap_angle(static_cast<double>(cut));
    ImGui::Text("q = %s  %s", config_text(q_).c_str(), world().is_free(q_) ? "free" : "in collision");
    ImGui::TextWrapped("free: %.1f%% of Q (%s cells)", 100.0 * fine_free_, fine_text().c_str());
    if (panel::fold("Planning in 3-D")) {
      if (planner_combo()) rebuild(0);
      // The trees and PRM* choose their own neighbours: no rule to set for them.
      const bool rule = kind_ == PlannerChoice::Kind::Prm || kind_ == PlannerChoice::Kind::LazyPrm;
      if (prm_controls(params_, world(), ctx, kLabTorusSamples, false, rule)) rebuild(0);
      ui::text_flow(ui::format("|V| = %zu  |E| = %ld, %d across a glued face", prm().roadmap().vertices.size(),
                               prm().edges_alive(), seam_edges()));
      if (prm().solved() && instructor::hidden("path_length")) {
        ImGui::TextColored(theme::vec4(theme::kTextGood), "path found, its length %s", instructor::kHidden);
      } else if (prm().solved()) {
        ImGui::TextColored(theme::vec4(theme::kTextGood), "path found, length %.3f", prm().path_length());
      } else if (prm().done()) {  // SE(2)'s default n = 200 misses most seeds' paths: say what helps
        ImGui::PushStyleColor(ImGuiCol_Text, theme::vec4(theme::kTextBad));
        ui::text_flow("no path found: a larger n or another seed may find one");
        ImGui::PopStyleColor();
      }
    }
    // Folded at first: the lesson's first state fits the panel at 1280 x 800 (panel-layout.test).
    if (panel::fold("Questions", false)) questions_panel();
    if (panel::fold("Reading the picture", false))
      ImGui::TextWrapped(arm() ? "Each cut fixes θ₁: links 2 and 3 are then a 2-link arm from the end of link 1, "
                                 "so the cut is a square with glued edges like the torus lesson's. Where link 1 "
                                 "itself hits an obstacle the whole cut is blocked: a slab through the cube. All "
                                 "three angles wrap, so a path may leave through any face and come back through "
                                 "the opposite one."
                               : "Each cut holds the robot at one angle: its C-obstacle is every obstacle grown by "
                                 "the robot turned that way. Scrub the plane and the grown shapes turn with it; a "
                                 "long robot blocks a gap it lies across and passes it end first. A path may climb "
                                 "in θ (the robot turns) while it moves; through the top it comes back at the "
                                 "bottom, the same angle.");
    if (panel::fold("Obstacles", false))
      if (editor_.toolbar(scene_, ctx)) {
        refuse_heavy_redo(ctx);
        rebuild(session_.wanted_steps());
      }
  }

  void views(LabContext& ctx, ImVec2 size) override {
    const Split s = split(size);
    workspace(ctx, s.first);
    between(s);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    volume(s.second);
    ctx.areas["volume"] = {at, ImVec2(at.x + s.second.x, at.y + s.second.y)};
    ctx.areas["volume_cut"] = {volume_view_.strip_min(), volume_view_.strip_max()};
    editor_.help_window();
  }

  Scene* scene() override { return &scene_; }
  std::vector<LessonView> views_kept() override {
    return {{"workspace", &view_, scene_.workspace_min, scene_.workspace_max},
            {"volume", nullptr, Vec2::Zero(), Vec2::Zero(), &volume_view_}};
  }
  SceneEditor* editor() override { return &editor_; }
  bool accept_scene(const Scene& s, std::string& why) override {
    const bool polygon = std::holds_alternative<PolygonRobot>(s.robot);
    const auto* a = std::get_if<ArmRobot>(&s.robot);
    if (!polygon && !(a && a->links() == 3)) {
      why = std::string("this lesson shows a polygon robot (SE(2)) or a 3-link arm (T^3); the scene has a '") +
            robot_type_name(s.robot) + "' robot with " + std::to_string(robot_dof(s.robot)) + " coordinates";
      return false;
    }
    // The volumes are built at once as the scene is taken (the roadmap runs in slices later).
    if (!(why = volume_problem(s)).empty()) return false;
    if (!(why = scene_budget_problem(params_, s)).empty()) return false;
    editor_.replace(scene_, s);
    q_ = scene_.start;
    rebuild(0);
    return true;
  }
  bool undo() override { return editor_.undo(scene_) && (after_undo(), true); }
  bool redo() override {
    if (!editor_.redo(scene_)) return false;
    if (!volume_problem(scene_).empty()) {  // a refused edit, back on the redo stack
      editor_.undo(scene_);
      return false;
    }
    after_undo();
    return true;
  }

  json state(const json& args) const override {
    json out{{"robot", arm() ? "arm3" : "polygon"},
             {"q", config_to_json(q_)},
             {"q_free", world().is_free(q_)},
             {"start", config_to_json(scene_.start)},
             {"goal", config_to_json(scene_.goal)},
             {"cut", {{"axis", arm() ? "theta1" : "theta"}, {"value", q_[cut_axis()]}, {"unit", unit(q_).z()}}},
             {"q_in_volume", {unit(q_).x(), unit(q_).y(), unit(q_).z()}},
             {"free_fraction", fine_free_},
             {"free_fraction_cells", fine_cells_},
             {"drawn", {{"cells", {kDrawXY, kDrawXY, kDrawZ}}, {"faces", volume_view_.faces()},
                        {"yaw", volume_view_.yaw()}, {"pitch", volume_view_.pitch()}, {"zoom", volume_view_.zoom()}}},
             {"prm", planner_state_json(prm(), args.value("roadmap", false))}};
    out["prm"]["planner"] = planner_kind_info(kind_).name;
    out["prm"]["params"] = prm_params_json(params_);
    const VolumeQuestion q = volume_question(question_, scene_);
    json choices = json::array();
    for (const auto& c : q.choices) choices.push_back({{"key", c.first}, {"text", c.second}});
    out["question"] = {{"id", q.id}, {"prompt", q.prompt}, {"answer_format", q.answer_format}, {"choices", choices},
                       {"answer", answer_}, {"check", nullptr}};
    if (check_)
      out["question"]["check"] = {{"correct", check_->correct}, {"readable", check_->readable},
                                  {"explanation", check_->explanation}};
    out["prm"]["seam_crossing_edges"] = seam_edges();
    out["prm"]["running"] = running_json(session_);
    return out;
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    json rest = j;
    const json prm_part = take_prm_params(rest);
    std::optional<Config> q;
    std::optional<double> cut;
    std::optional<PlannerChoice::Kind> kind;
    std::optional<std::string> question, answer;
    bool check = false;
    for (auto it = rest.begin(); it != rest.end(); ++it) {
      const std::string& k = it.key();
      if (k == "planner") {
        try {
          if (!it->is_string()) throw std::invalid_argument("a planner's name (" + planner_names(", ") + ")");
          kind = parse_planner_kind(it->get<std::string>());
        } catch (const std::invalid_argument& e) {
          throw ApiError(std::string("planner: ") + e.what());
        }
      } else if (k == "question") {
        const auto& ids = volume_question_ids();
        if (!it->is_string() || std::find(ids.begin(), ids.end(), it->get<std::string>()) == ids.end())
          throw ApiError("question: name, dimension, glued, seam or free");
        question = it->get<std::string>();
      } else if (k == "answer") {
        if (!it->is_string() || it->get<std::string>().size() > sizeof answer_buffer_ - 1)
          throw ApiError("answer: a string (at most " + std::to_string(sizeof answer_buffer_ - 1) + " bytes)");
        answer = it->get<std::string>();
      } else if (k == "check") {
        if (!it->is_boolean()) throw ApiError("check: true or false");
        check = it->get<bool>();
      } else if (k == "q") {
        // Angles wrap, within the range `cut` takes (beyond it a double wraps to noise); x and y
        // must be in the workspace box, the space the volume and the planner cover.
        const Vec2 lo = scene_.workspace_min, hi = scene_.workspace_max;
        const auto in = [](const json& v, double a, double b) {
          return v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= a && v.get<double>() <= b;
        };
        bool ok = it->is_array() && it->size() == 3;
        for (int i = 0; ok && i < 3; ++i)
          ok = arm() || i == 2 ? in((*it)[i], -1000, 1000) : in((*it)[i], lo[i], hi[i]);
        if (!ok)
          throw ApiError(arm() ? std::string("q: [theta1, theta2, theta3], three angles in [-1000, 1000] (radians)")
                               : "q: [x, y, theta], x in [" + significant(lo.x()) + ", " + significant(hi.x()) +
                                     "], y in [" + significant(lo.y()) + ", " + significant(hi.y()) +
                                     "], theta in [-1000, 1000] (radians)");
        q = config({(*it)[0].get<double>(), (*it)[1].get<double>(), (*it)[2].get<double>()});
      } else if (k == "cut") {
        if (!it->is_number() || !std::isfinite(it->get<double>()) || std::fabs(it->get<double>()) > 1000)
          throw ApiError("cut: a number in [-1000, 1000] (radians)");
        cut = it->get<double>();
      } else {
        throw ApiError("unknown parameter \"" + k + "\"");
      }
    }
    const PrmParams p = prm_params_from_json(prm_part, params_, world(), kLabTorusSamples);
    if (q) q_ = world().space().wrap(*q);
    if (cut) q_[cut_axis()] = wrap_angle(*cut);
    if (!prm_part.empty() || (kind && *kind != kind_)) {
      params_ = p;
      if (kind) kind_ = *kind;
      rebuild(0);
    }
    // After the rebuild, which forgets a verdict: the answer is checked on the lesson as it is now.
    if (question && *question != question_) open_question(*question);
    if (answer) set_answer(*answer);
    if (check) run_check();
  }

  json params() const override {
    json p = prm_params_json(params_);
    p["planner"] = planner_kind_info(kind_).name;
    p["q"] = config_to_json(q_);
    p["cut"] = q_[cut_axis()];
    p["question"] = question_;
    return p;
  }
  std::vector<ParamField> param_fields() const override {
    std::vector<ParamField> f = prm_param_fields(kLabTorusSamples);
    std::vector<std::string> planners;
    for (const PlannerKindInfo& k : planner_kinds()) planners.emplace_back(k.name);
    f.push_back({"planner", "planner", nullptr, planners, "as cspacelab plan --planner names it"});
    f.push_back({"question", "question", nullptr, volume_question_ids(), "the question the panel asks"});
    f.push_back({"q", "configuration",
                 nullptr, {}, "x, y, theta (polygon; x, y in the workspace box) or theta1, theta2, theta3 (arm)"});
    f.push_back({"cut", "cut plane", nullptr, {},
                 "theta (polygon) or theta1 (arm) of the cut, radians (a number in [-1000, 1000])"});
    return f;
  }

  std::string describe() const override {
    return describe_scene(scene_, world()) + " Its C-space is drawn in 3-D (" +
           (arm() ? "T^3, a cube with opposite faces glued" : "SE(2): x, y across, theta up, top and bottom glued") +
           "), cut at " + (arm() ? "theta1 = " : "theta = ") + ui::format("%.3f", q_[cut_axis()]) +
           "; the robot is at " + config_text(q_) + ", " + (world().is_free(q_) ? "free" : "in collision") +
           ". " + ui::format("%.1f", 100.0 * fine_free_) + " percent of the C-space is free. The roadmap: " +
           describe_planner(prm(), !instructor::hidden("path_length"));
  }

  Stepper* stepper() override { return &session_; }

 private:
  bool arm() const { return std::holds_alternative<ArmRobot>(scene_.robot); }
  // The coordinate the plane cuts: theta (the polygon's third) or theta1 (the arm's first).
  int cut_axis() const { return arm() ? 0 : 2; }
  // The planner on screen, whichever kind_ is (the trees are a Roadmap of child-parent edges).
  const Planner& prm() const { return session_.shown(); }
  PlannerFactory factory() const {
    if (kind_ == PlannerChoice::Kind::Prm) return prm_factory(params_);
    PlannerChoice c;
    c.kind = kind_;
    c.samples = params_.samples;
    c.neighbors = params_.neighbors;
    c.checker = params_.checker;
    c.seed = params_.seed;
    return make_planner_factory(c);
  }
  // The planner's combo (PRM's controls below it set n, the checker and the seed of any; the
  // neighbour rule of the roadmap planners). True if the choice changed.
  bool planner_combo() {
    instructor::FixedParam fixed("planner");
    bool changed = false;
    ImGui::SetNextItemWidth(ui::toggle_width("RRT-Connect") * 1.6f);
    if (ImGui::BeginCombo("planner", planner_kind_info(kind_).name)) {
      for (const PlannerKindInfo& k : planner_kinds()) {
        if (ImGui::Selectable(k.name, k.kind == kind_) && k.kind != kind_) {
          kind_ = k.kind;
          changed = true;
        }
        web::record_control((std::string("c3d-planner:") + k.name).c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", k.summary);
      }
      ImGui::EndCombo();
    }
    web::record_control("c3d-planner");
    return changed;
  }

  // --- the questions: one at a time, answered by a choice or typed, checked by the core.
  void open_question(const std::string& id) {
    question_ = id;
    set_answer("");
  }
  void set_answer(const std::string& a) {
    answer_ = a;
    std::snprintf(answer_buffer_, sizeof answer_buffer_, "%s", a.c_str());
    check_.reset();
  }
  void run_check() { check_ = check_volume_question(question_, scene_, fine_free_, answer_); }
  void questions_panel() {
    const std::vector<std::string>& ids = volume_question_ids();
    const auto at = std::find(ids.begin(), ids.end(), question_);
    const int index = static_cast<int>(at - ids.begin());
    const VolumeQuestion q = volume_question(question_, scene_);
    ImGui::TextDisabled("question %d of %zu", index + 1, ids.size());
    ImGui::TextWrapped("%s", q.prompt.c_str());
    if (q.answer_format == "choice") {
      for (const auto& c : q.choices) {
        if (ImGui::RadioButton(c.second.c_str(), answer_ == c.first)) set_answer(c.first);
        web::record_control(("c3d-choice:" + c.first).c_str());
      }
    } else {
      ImGui::SetNextItemWidth(-FLT_MIN);
      ImGui::PushID(question_.c_str());
      const bool enter = ImGui::InputTextWithHint("##answer", q.format_hint.c_str(), answer_buffer_,
                                                  sizeof answer_buffer_, ImGuiInputTextFlags_EnterReturnsTrue);
      ImGui::PopID();
      web::record_control("c3d-answer");
      if (answer_ != answer_buffer_) {
        answer_ = answer_buffer_;
        check_.reset();
      }
      if (enter) run_check();
    }
    if (ImGui::Button("Check")) run_check();
    web::record_control("c3d-check");
    ui::flow(ui::button_width("Next question"));
    {
      instructor::FixedParam fixed("question");
      if (ImGui::Button("Next question")) open_question(ids[static_cast<std::size_t>(index + 1) % ids.size()]);
      web::record_control("c3d-next-question");
    }
    if (check_) {
      ImGui::PushStyleColor(ImGuiCol_Text, theme::vec4(check_->correct ? theme::kTextGood : theme::kTextBad));
      ImGui::TextWrapped("%s%s", check_->readable ? "" : "not an answer: ", check_->explanation.c_str());
      ImGui::PopStyleColor();
    }
  }
  const CollisionWorld& world() const { return session_.world(); }
  std::string fine_text() const {
    return ui::format("%d × %d × %d", fine_cells_[0], fine_cells_[1], fine_cells_[2]);
  }

  // The robot choice loads its bundled scene as one undoable edit.
  void load(LabContext& ctx, const char* name) {
    std::string why;
    if (!accept_scene(bundled_scene(name), why)) ctx.notify(why);
  }
  void after_undo() { rebuild(session_.wanted_steps()); }

  // What is wrong with building `s`'s volumes (the fine one and the drawn one) in the lab, or
  // "": they are built at once when the scene changes, so a heavy scene would hang the page.
  static std::string volume_problem(const Scene& s) {
    const bool polygon = std::holds_alternative<PolygonRobot>(s.robot);
    const VolumeWork fine = polygon ? cspace_volume_work(s, kFineSe2XY, kFineSe2Z) : cspace_volume_work(s, kFineArm, kFineArm);
    const VolumeWork drawn = cspace_volume_work(s, kDrawXY, kDrawZ);
    if (fine.units + drawn.units <= kLabMaxVolumeWork) return "";
    return "this scene's 3-D C-space is too much work for the lab: " + fine.text + " = " + significant(fine.units) +
           ", plus " + significant(drawn.units) + " for the drawn block, over the lab's " +
           significant(kLabMaxVolumeWork) + "; use fewer or simpler obstacles (the CLI's cspace command takes more)";
  }
  // The toolbar's (or a key's) Redo may bring back an edit refused by volume_problem() (undone
  // then, so it waits on the redo stack): refuse it again. Undo and Delete only go back to, or
  // lighten, scenes accepted before.
  void refuse_heavy_redo(LabContext& ctx) {
    if (const std::string why = volume_problem(scene_); !why.empty()) {
      editor_.undo(scene_);
      ctx.notify(why);
    }
  }

  void rebuild(long steps) {
    keep_within_budget(params_, robot_space(scene_.robot, scene_.workspace_min, scene_.workspace_max));
    session_.rebuild(scene_, factory(), steps);
    check_.reset();  // a verdict on another scene
    // Both robots have three coordinates: an undo across the robot choice starts at the start.
    if (q_.size() != robot_dof(scene_.robot) || arm() != q_arm_) q_ = scene_.start;
    q_arm_ = arm();
    rebuild_volumes();
    session_.forget_log();
  }

  // The exact slicers, the block drawn and the free fraction, from the scene as it is.
  // While an obstacle is dragged only the drawn block follows (`fine_too` false); the fine volume
  // and its free fraction wait for the release (fine_stale_).
  void rebuild_volumes(bool fine_too = true) {
    se2_.reset();
    arm3_.reset();
    arm_slice_.reset();
    CSpaceVolume drawn, fine;
    if (arm()) {
      arm3_ = std::make_unique<Arm3Slices>(std::get<ArmRobot>(scene_.robot), scene_.obstacles);
      drawn = arm3_volume(*arm3_, kDrawXY, kDrawZ);
      if (fine_too) fine = arm3_volume(*arm3_, kFineArm, kFineArm);
      fine_cells_ = {kFineArm, kFineArm, kFineArm};
      volume_view_.set_volume(drawn, Vec3(1, 1, 1));
    } else {
      se2_ = std::make_unique<Se2CObstacles>(std::get<PolygonRobot>(scene_.robot), scene_.obstacles);
      drawn = se2_volume(*se2_, scene_.workspace_min, scene_.workspace_max, kDrawXY, kDrawXY, kDrawZ);
      if (fine_too)
        fine = se2_volume(*se2_, scene_.workspace_min, scene_.workspace_max, kFineSe2XY, kFineSe2XY, kFineSe2Z);
      fine_cells_ = {kFineSe2XY, kFineSe2XY, kFineSe2Z};
      const Vec2 size = scene_.workspace_max - scene_.workspace_min;
      const double m = std::max(size.x(), size.y());
      volume_view_.set_volume(drawn, Vec3(size.x() / m, size.y() / m, 0.8));
    }
    fine_stale_ = !fine_too;
    if (fine_too) fine_free_ = fine.free_fraction;
  }

  // A configuration in the block's unit coordinates: x, y, theta for the polygon (the workspace
  // box, theta from -pi); theta2, theta3, theta1 for the arm.
  Vec3 unit(const Config& q) const {
    const auto turn = [](double a) { return (wrap_angle(a) + kPi) / kTwoPi; };
    if (arm()) return Vec3(turn(q[1]), turn(q[2]), turn(q[0]));
    const Vec2 lo = scene_.workspace_min, size = scene_.workspace_max - scene_.workspace_min;
    return Vec3((q[0] - lo.x()) / size.x(), (q[1] - lo.y()) / size.y(), turn(q[2]));
  }
  Vec3 unit_delta(const Config& d) const {
    if (arm()) return Vec3(d[1], d[2], d[0]) / kTwoPi;
    const Vec2 size = scene_.workspace_max - scene_.workspace_min;
    return Vec3(d[0] / size.x(), d[1] / size.y(), d[2] / kTwoPi);
  }

  int seam_edges() const {
    int n = 0;
    const auto& v = prm().roadmap().vertices;
    for (const RoadmapEdge& e : prm().roadmap().edges) {
      if (!e.alive) continue;
      const Config& a = v[static_cast<std::size_t>(e.a)];
      const Config& b = v[static_cast<std::size_t>(e.b)];
      const Vec3 end = unit(a) + unit_delta(world().space().difference(a, b));
      n += end.minCoeff() < -1e-9 || end.maxCoeff() > 1 + 1e-9;
    }
    return n;
  }

  // --- the workspace: drag the polygon to slide it, a link to turn its joint; obstacles else.
  void workspace(LabContext& ctx, ImVec2 size) {
    view_.begin("##c3d-workspace", size, scene_.workspace_min, scene_.workspace_max);
    ctx.views["workspace"] = &view_;
    view_.draw_grid();
    view_.push_clip();
    for (const Obstacle& o : scene_.obstacles) view_.draw_obstacle(o);
    const Robot& robot = scene_.robot;
    draw_robot(view_, robot, scene_.start, theme::with_alpha(theme::kStart, 110), 2.0f);
    draw_robot(view_, robot, scene_.goal, theme::with_alpha(theme::kGoal, 110), 2.0f);
    draw_robot(view_, robot, q_, world().is_free(q_) ? theme::kRobot : theme::kHit, 3.0f);
    view_.pop_clip();
    // The long hint where it fits (a phone's view cut it at "turn"), else its first half.
    const Vec2 corner(scene_.workspace_min.x(), scene_.workspace_max.y());
    const char* hint = arm() ? "drag a link to turn its joint" : "drag the robot to slide it; the plane turns it";
    // Measured over the workspace itself: beside it, the 3-D view's side of the window is not room.
    const float room = view_.to_screen(scene_.workspace_max).x - view_.to_screen(corner).x - 6;
    if (!arm() && ImGui::CalcTextSize(hint).x > room) hint = "drag the robot to slide it";
    view_.draw_label(corner, hint, theme::kLabel, ImVec2(6, -22));
    if (grab_ == 0 && view_.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      grab_ = part_under_mouse();
      grab_offset_ = view_.mouse_world() - (arm() ? Vec2::Zero() : Vec2(q_[0], q_[1]));
    }
    if (grab_ > 0) {
      if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        grab_ = 0;
        return;
      }
      const Vec2 m = view_.mouse_world();
      if (!arm()) {
        q_[0] = m.x() - grab_offset_.x();
        q_[1] = m.y() - grab_offset_.y();
      } else {
        Vec2 joints[ArmRobot::kMaxLinks + 1];
        arm_joints(std::get<ArmRobot>(robot), q_, joints);
        const Vec2 from = joints[grab_ - 1];
        double before = 0;  // the absolute angle of the link before the one dragged
        for (int i = 0; i + 1 < grab_; ++i) before += q_[i];
        q_[grab_ - 1] = wrap_angle(std::atan2(m.y() - from.y(), m.x() - from.x()) - before);
      }
      return;
    }
    SceneEditor::Options options;
    options.endpoints_are_points = !arm();
    if (editor_.edit(view_, scene_, ctx, options)) edited(ctx);
    if ((session_.replay_pending() || fine_stale_) && !editor_.dragging()) edited(ctx);  // released
  }

  // An edit in the workspace (each frame of a drag, and its release). A finished edit whose
  // volumes would cost past the lab's limit is undone with the reason; during a drag the cost
  // cannot be known to settle, and only the drawn block is built.
  void edited(LabContext& ctx) {
    const bool dragging = editor_.dragging();
    if (!dragging) {
      if (const std::string why = volume_problem(scene_); !why.empty()) {
        editor_.undo(scene_);
        after_undo();
        ctx.notify(why);
        return;
      }
    }
    session_.edited(scene_, dragging);
    rebuild_volumes(!dragging);
    check_.reset();  // a verdict on the scene before the edit (its free share, its start)
  }

  // 1.. the link under the mouse (arm), 1 if on the polygon's body, else 0.
  int part_under_mouse() const {
    const Vec2 m = view_.mouse_world();
    if (!arm()) {
      Polygon body;
      polygon_pose(std::get<PolygonRobot>(scene_.robot), q_, body);
      return point_in_polygon(m, body) || (m - Vec2(q_[0], q_[1])).norm() <= view_.reach(8.0f) ? 1 : 0;
    }
    const ArmRobot& a = std::get<ArmRobot>(scene_.robot);
    Vec2 joints[ArmRobot::kMaxLinks + 1];
    arm_joints(a, q_, joints);
    for (int i = a.links(); i >= 1; --i)
      if (point_segment_distance(m, joints[i - 1], joints[i]) <= view_.reach(7.0f)) return i;
    return 0;
  }

  // --- the block: C-obstacle faces, the exact slice at the cut, roadmap, path, points.
  void volume(ImVec2 size) {
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    double cut = unit(q_).z();
    if (volume_view_.begin("##c3d-volume", size, cut)) q_[cut_axis()] = wrap_angle(-kPi + kTwoPi * cut);
    cut = unit(q_).z();
    volume_view_.draw_block(cut, [&] { draw_slice(cut); });
    if (arm()) volume_view_.draw_frame("θ₂", "θ₃", "θ₁");
    else volume_view_.draw_frame("x", "y", "θ");
    const bool glued[3] = {arm(), arm(), true};
    const Space& space = world().space();
    const Roadmap& r = prm().roadmap();
    const bool show = !session_.replay_pending() && !session_.replaying();
    if (show && r.edges.size() <= 6000)
      for (const RoadmapEdge& e : r.edges) {
        if (!e.alive) continue;
        const Config& a = r.vertices[static_cast<std::size_t>(e.a)];
        const Config& b = r.vertices[static_cast<std::size_t>(e.b)];
        volume_view_.draw_segment(unit(a), unit_delta(space.difference(a, b)), glued,
                                  theme::with_alpha(theme::kBlue, r.edges.size() > 1500 ? 45 : 110), 1.0f);
      }
    const std::vector<int>& path = prm().path();
    for (std::size_t i = 0; show && prm().solved() && i + 1 < path.size(); ++i) {
      const Config& a = r.vertices[static_cast<std::size_t>(path[i])];
      const Config& b = r.vertices[static_cast<std::size_t>(path[i + 1])];
      volume_view_.draw_segment(unit(a), unit_delta(space.difference(a, b)), glued, theme::kPath, 4.0f);
    }
    volume_view_.draw_point(unit(scene_.start), theme::kStart, 5.0f, "S");
    volume_view_.draw_point(unit(scene_.goal), theme::kGoal, 5.0f, "G");
    volume_view_.draw_point(unit(q_), world().is_free(q_) ? theme::kRobot : theme::kHit, 6.0f);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddText(ImVec2(corner.x + 6, corner.y + 4), theme::kLabel,
                arm() ? "T³: opposite faces glued" : "SE(2): θ up, top and bottom glued");
  }

  // The exact C-obstacle at the cut, filled in the plane.
  void draw_slice(double cut) {
    const ImU32 color = theme::kCObstacle;
    if (!arm()) {
      se2_->slice(q_[2], pieces_);
      const Vec2 lo = scene_.workspace_min, size = scene_.workspace_max - scene_.workspace_min;
      for (const RoundedPolygon& piece : pieces_) {
        std::vector<Vec2> unit_xy;
        for (const Vec2& p : clip_to_box(rounded_polygon_outline(piece, 0.2)))
          unit_xy.push_back(Vec2((p.x() - lo.x()) / size.x(), (p.y() - lo.y()) / size.y()));
        volume_view_.fill_in_plane(unit_xy, cut, color);
      }
      return;
    }
    if (!arm_slice_ || arm_slice_->theta1() != q_[0]) arm_slice_.emplace(arm3_->slice(q_[0]));
    if (arm_slice_->all_blocked()) {
      volume_view_.fill_in_plane({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}, cut, color);
      return;
    }
    std::vector<AngleInterval> blocked;
    for (int c = 0; c < kArmColumns; ++c) {
      const double u0 = double(c) / kArmColumns, u1 = double(c + 1) / kArmColumns;
      arm_slice_->blocked_theta3(-kPi + kTwoPi * 0.5 * (u0 + u1), blocked);
      for (const AngleInterval& i : blocked) {
        const double v0 = (i.lo + kPi) / kTwoPi, v1 = (i.hi + kPi) / kTwoPi;
        volume_view_.fill_in_plane({Vec2(u0, v0), Vec2(u1, v0), Vec2(u1, v1), Vec2(u0, v1)}, cut, color);
      }
    }
  }

  // A convex polygon clipped to the workspace box (Sutherland-Hodgman, one side at a time).
  Polygon clip_to_box(Polygon poly) const {
    for (int side = 0; side < 4 && !poly.empty(); ++side) {
      const int axis = side / 2;
      const bool upper = side % 2;
      const double bound = upper ? scene_.workspace_max[axis] : scene_.workspace_min[axis];
      const auto inside = [&](const Vec2& p) { return upper ? p[axis] <= bound : p[axis] >= bound; };
      Polygon out;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2& a = poly[i];
        const Vec2& b = poly[(i + 1) % poly.size()];
        if (inside(a)) out.push_back(a);
        if (inside(a) != inside(b)) out.push_back(a + (b - a) * ((bound - a[axis]) / (b[axis] - a[axis])));
      }
      poly = std::move(out);
    }
    return poly;
  }

  Scene scene_;
  SceneEditor editor_;
  WorkspaceView view_;
  VolumeView volume_view_;
  PrmParams params_;
  PlannerSession session_;  // after scene_ and params_, from which it starts
  PlannerChoice::Kind kind_ = PlannerChoice::Kind::Prm;
  std::string question_ = volume_question_ids().front();
  std::string answer_;
  char answer_buffer_[64] = "";
  std::optional<ExerciseCheck> check_;
  std::unique_ptr<Se2CObstacles> se2_;
  std::unique_ptr<Arm3Slices> arm3_;
  std::optional<Arm3Slices::Slice> arm_slice_;  // the arm's slice at the cut, kept while it stays
  std::vector<RoundedPolygon> pieces_;
  double fine_free_ = 0.0;
  bool fine_stale_ = false;  // the scene changed in a drag since fine_free_ was counted
  std::array<int, 3> fine_cells_{0, 0, 0};
  Config q_;
  bool q_arm_ = false;  // q_ is an arm's angles
  int grab_ = 0;
  Vec2 grab_offset_{0, 0};
};

}  // namespace

CSL_REGISTER_LESSON(Cspace3dLesson, "cspace-3d", "C-spaces in 3-D", "Configuration spaces");

}  // namespace csl::app
