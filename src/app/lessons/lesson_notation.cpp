// Lesson "C-space notation": build a robot (base, joints, wrist) and read its configuration
// space in the course's notation, with the reason for every factor; practise writing Q for
// described robots, with the lab checking and explaining; and see why S^1 x S^1 is the torus
// and not the sphere. In practice nothing on screen names Q or any factor of it before the
// student has checked an answer: the pictures show the robot (a drone flies, a gantry crane
// runs on its frame), the texts describe it in words.
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <optional>

#include "app/shell/instructor.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/lesson.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "app/views/split.hpp"
#include "app/views/surface_view.hpp"
#include "core/base/angles.hpp"
#include "core/teaching/notation.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;

// What the picture draws. The description alone cannot tell a drone from any other free body,
// or a gantry crane from any arm of three prismatic joints, so an exercise names its picture.
enum class Picture { Arm, Pendulum, Vacuum, Gantry, Drone, Cart, MobileArm };
const char* const kPictureNames[] = {"arm", "pendulum", "vacuum", "gantry", "drone", "cart", "mobile-arm"};

struct Exercise {
  const char* text;         // in our words
  const char* description;  // for the checker
  Picture picture;
};
// The kinds of robots of the homework's P1-P7, and a few more.
const std::array<Exercise, 9> kExercises = {{
    {"A robot vacuum: it slides over the floor and turns on the spot.", "base=planar", Picture::Vacuum},
    {"An arm bolted to a table, with three revolute joints.", "joints=RRR", Picture::Arm},
    {"A single revolute joint: a pendulum.", "joints=R", Picture::Pendulum},
    {"An arm with two revolute joints and then a prismatic joint that extends the last link.", "joints=RRP", Picture::Arm},
    {"A gantry crane: three prismatic joints, along x, y and z.", "joints=PPP", Picture::Gantry},
    {"A six-link arm whose last three revolute joints form a spherical wrist.", "joints=RRR wrist=spherical", Picture::Arm},
    {"The same six-link arm, on a base that slides and turns in the plane.", "base=planar joints=RRR wrist=spherical",
     Picture::MobileArm},
    {"A drone: a rigid body that moves and turns freely in space.", "base=spatial", Picture::Drone},
    {"A cart that slides in the plane without turning, carrying a prismatic then a revolute joint.",
     "base=planar-translating joints=PR", Picture::Cart},
}};

// The picture of a robot built with the controls: by how its base moves.
Picture picture_of(const RobotDescription& r) {
  switch (r.base) {
    case RobotDescription::Base::Fixed: return Picture::Arm;
    case RobotDescription::Base::PlanarTranslating: return Picture::Cart;
    case RobotDescription::Base::PlanarMobile: return r.joints.empty() && !r.spherical_wrist ? Picture::Vacuum : Picture::MobileArm;
    case RobotDescription::Base::SpatialTranslating:
    case RobotDescription::Base::SpatialMobile: return Picture::Drone;
  }
  return Picture::Arm;
}

const char* const kBaseNames[] = {"fixed", "planar, sliding only", "planar, sliding and turning", "spatial, sliding only",
                                  "spatial, free"};
const char* const kBaseTokens[] = {"fixed", "planar-translating", "planar", "spatial-translating", "spatial"};

const ImU32& kInk = theme::kInk;
const ImU32 kMotion = theme::kOrange;  // arrows: how the robot moves

ImVec2 add(ImVec2 a, ImVec2 b) { return ImVec2(a.x + b.x, a.y + b.y); }
ImVec2 lerp(ImVec2 a, ImVec2 b, float t) { return ImVec2(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t); }

// A straight arrow from a to b, its head at b (both heads: `both`).
void arrow(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 col, float width = 2.5f, bool both = false) {
  const float dx = b.x - a.x, dy = b.y - a.y, len = std::max(1.0f, std::sqrt(dx * dx + dy * dy));
  const ImVec2 u(dx / len, dy / len), n(-u.y, u.x);
  const float h = 4.0f * width;
  dl->AddLine(a, b, col, width);
  dl->AddTriangleFilled(b, ImVec2(b.x - u.x * h + n.x * h * 0.6f, b.y - u.y * h + n.y * h * 0.6f),
                        ImVec2(b.x - u.x * h - n.x * h * 0.6f, b.y - u.y * h - n.y * h * 0.6f), col);
  if (both) arrow(dl, b, a, col, width);
}

// An arc of an ellipse (radii rx, ry) around c from angle a0 to a1 with a head at a1: turning.
void turn_arrow(ImDrawList* dl, ImVec2 c, float rx, float ry, float a0, float a1, ImU32 col) {
  constexpr int kN = 28;
  for (int i = 0; i <= kN; ++i) {
    const float a = a0 + (a1 - a0) * static_cast<float>(i) / kN;
    dl->PathLineTo(ImVec2(c.x + rx * std::cos(a), c.y + ry * std::sin(a)));
  }
  dl->PathStroke(col, 0, 2.5f);
  const float e = a1 - 0.12f * (a1 > a0 ? 1.0f : -1.0f);
  arrow(dl, ImVec2(c.x + rx * std::cos(e), c.y + ry * std::sin(e)), ImVec2(c.x + rx * std::cos(a1), c.y + ry * std::sin(a1)),
        col, 2.5f);
}

void ellipse(ImDrawList* dl, ImVec2 c, float rx, float ry, ImU32 fill, ImU32 edge) {
  ImVec2 pts[32];
  for (int i = 0; i < 32; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / 32.0f;
    pts[i] = ImVec2(c.x + rx * std::cos(a), c.y + ry * std::sin(a));
  }
  dl->AddConvexPolyFilled(pts, 32, fill);
  dl->AddPolyline(pts, 32, edge, ImDrawFlags_Closed, 1.5f);
}

// Hatching under (or above) a line from a to b: a fixed mount, the ground or a ceiling.
void hatched(ImDrawList* dl, ImVec2 a, ImVec2 b, float unit, bool above = false) {
  dl->AddLine(a, b, kInk, 2.0f);
  const float s = above ? -1.0f : 1.0f;
  for (float x = a.x; x <= b.x; x += 0.4f * unit)
    dl->AddLine(ImVec2(x, a.y), ImVec2(x - 0.3f * unit, a.y + s * 0.4f * unit), kInk, 1.0f);
}

class NotationLesson : public Lesson {
 public:
  NotationLesson() { robot_ = parse_robot_description("joints=RR"); }

  void panel(LabContext&) override {
    panel_texts_.clear();
    int mode = practice_ ? 1 : 0;
    {
      instructor::FixedParam fixed("mode");
      if (ImGui::RadioButton("Build a robot", &mode, 0)) practice_ = false;
      ui::flow(ui::toggle_width("Practice"));
      if (ImGui::RadioButton("Practice", &mode, 1) && !practice_) {
        practice_ = true;
        focus_answer_ = true;
      }
    }
    said("Build a robot");
    said("Practice");
    if (!practice_) builder();
    else practice();
    // The torus and the sphere name T^2 = S^1 x S^1: in practice, only once an answer is checked.
    if (practice_ && !checked_) return;
    section("Why S^1 x S^1 is not S^2");
    text("Two angles make a torus, the surface of a ring: going once around the ring, or once "
         "around its tube, brings you back where you started, and such a loop can never be pulled "
         "tight to a point without leaving the surface. On a sphere every loop can be shrunk to a "
         "point. So a 2-link arm's C-space is T^2 = S^1 x S^1, not S^2; likewise SO(2) x SO(2) is "
         "not SO(3). Drag the pictures to turn them.");
  }

  void views(LabContext& ctx, ImVec2 size) override {
    const ImGuiWindowFlags still = ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;
    Split s = split(size);
    if (!s.stacked) {  // (half the width to the robot exactly, as the golden pictures have it)
      s.first.x = 0.5f * size.x;
      s.second.x = size.x - s.first.x - ImGui::GetStyle().ItemSpacing.x;
    }
    ImGui::BeginChild("robot-picture", s.first, true, still);
    robot_picture(ImGui::GetContentRegionAvail());
    ImGui::EndChild();
    web::record_control("notation-picture");  // (its rectangle: the tests compare it with a reference)
    ctx.areas["robot"] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
    between(s);
    ImGui::BeginChild("surfaces", s.second, true, still);
    surfaces(ImGui::GetContentRegionAvail());
    ImGui::EndChild();
    web::record_control("notation-surfaces");
    ctx.areas["surfaces"] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
  }

  std::vector<LessonView> views_kept() override {
    return {{"torus", nullptr, Vec2::Zero(), Vec2::Zero(), &torus_}, {"sphere", nullptr, Vec2::Zero(), Vec2::Zero(), &sphere_}};
  }

  json state(const json&) const override {
    const RobotDescription robot = shown();
    const ConfigSpaceInfo info = configuration_space(robot);
    json factors = json::array();
    for (const NotationFactor& f : info.factors)
      factors.push_back({{"factor", f.notation}, {"dimension", f.dimension}, {"reason", f.reason}});
    json out{{"mode", practice_ ? "practice" : "build"},
             {"description", description(robot)},
             {"notation", info.notation},
             {"dimension", info.dimension},
             {"factors", factors},
             {"equivalent", info.equivalent},
             {"exercise", exercise_},
             {"exercise_text", kExercises[static_cast<std::size_t>(exercise_)].text},
             {"answer", answer_}};
    if (checked_) out["check"] = {{"correct", check_.correct}, {"explanation", check_.explanation}};
    // What was on screen last frame, for the tests: the picture and every text in it and in the
    // surfaces' view, and the panel's texts.
    json& picture = out["picture"];
    picture["kind"] = kPictureNames[static_cast<int>(drawn_.kind)];
    picture["captions"] = drawn_.captions;
    picture["joints"] = drawn_.joints;
    json& parts = picture["parts"] = json::array();
    for (const char* p : drawn_.parts) parts.push_back(p);
    out["surface_captions"] = surface_captions_;
    out["panel_texts"] = panel_texts_;
    return out;
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    RobotDescription robot = robot_;
    bool practice = practice_;
    int exercise = exercise_;
    std::optional<std::string> answer;
    bool check = false;
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& k = it.key();
      if (k == "description") {
        if (!it->is_string()) throw ApiError("description: a string like \"base=planar joints=RRR\"");
        try {
          robot = parse_robot_description(it->get<std::string>());
        } catch (const NotationError& e) {
          throw ApiError(std::string("description: ") + e.what());
        }
      } else if (k == "mode") {
        if (*it != "build" && *it != "practice") throw ApiError("mode: \"build\" or \"practice\"");
        practice = *it == "practice";
      } else if (k == "exercise") {
        if (!it->is_number_integer() || it->get<int>() < 0 || it->get<int>() >= static_cast<int>(kExercises.size()))
          throw ApiError("exercise: 0.." + std::to_string(kExercises.size() - 1));
        exercise = it->get<int>();
      } else if (k == "answer") {
        if (!it->is_string() || it->get<std::string>().size() > 200) throw ApiError("answer: a string (at most 200 bytes)");
        answer = it->get<std::string>();
      } else if (k == "check") {
        check = it->is_boolean() && it->get<bool>();
      } else {
        throw ApiError("unknown parameter \"" + k + "\" (description, mode, exercise, answer, check)");
      }
    }
    robot_ = robot;
    if (practice && (!practice_ || exercise != exercise_)) focus_answer_ = true;
    practice_ = practice;
    if (exercise != exercise_) {
      checked_ = false;
      if (!answer) answer = "";  // a new exercise starts with an empty field, as "Next exercise" does
    }
    exercise_ = exercise;
    if (answer) answer_ = *answer;
    std::snprintf(answer_buffer_, sizeof answer_buffer_, "%s", answer_.c_str());
    if (check) run_check();
  }

  std::vector<ParamField> param_fields() const override {
    return {{"mode", "mode", nullptr, {"build", "practice"}},
            {"description", "robot", nullptr, {}, "base=..., joints=..., wrist=spherical, as the panel builds it"}};
  }

  std::string describe() const override {
    const ConfigSpaceInfo info = configuration_space(shown());
    if (instructor::hidden("q_notation"))
      return "The robot (" + description(shown()) + "); its configuration space is " + instructor::kHidden + ".";
    return "The robot (" + description(shown()) + ") has the configuration space " + info.notation + ", of dimension " +
           std::to_string(info.dimension) + ".";
  }

  json params() const override {
    return {{"description", description(robot_)}, {"mode", practice_ ? "practice" : "build"}, {"exercise", exercise_}};
  }

 private:
  static std::string description(const RobotDescription& r) {
    std::string out = std::string("base=") + kBaseTokens[static_cast<int>(r.base)];
    if (!r.joints.empty()) out += " joints=" + r.joints;
    if (r.spherical_wrist) out += " wrist=spherical";
    return out;
  }

  void builder() {
    ui::section("The robot");
    std::optional<instructor::FixedParam> fixed(std::in_place, "description");  // the robot built
    int base = static_cast<int>(robot_.base);
    ImGui::PushItemWidth(-60);
    if (ImGui::Combo("base", &base, kBaseNames, 5)) robot_.base = static_cast<RobotDescription::Base>(base);
    ImGui::PopItemWidth();
    ImGui::Text("joints, base to tip: %s", robot_.joints.empty() ? "(none)" : robot_.joints.c_str());
    if (ImGui::Button("+ revolute") && robot_.joints.size() < 12) robot_.joints += 'R';
    ui::flow(ui::button_width("+ prismatic"));
    if (ImGui::Button("+ prismatic") && robot_.joints.size() < 12) robot_.joints += 'P';
    ui::flow(ui::button_width("remove last"));
    if (ImGui::Button("remove last") && !robot_.joints.empty()) robot_.joints.pop_back();
    ImGui::Checkbox("spherical wrist", &robot_.spherical_wrist);
    ui::flow(ImGui::CalcTextSize("(3 more revolute joints)").x);
    ImGui::AlignTextToFramePadding();
    ImGui::TextDisabled("(3 more revolute joints)");
    ImGui::TextDisabled("the homework's robots:");
    static const char* const kPresets[][2] = {{"P1 mobile", "base=planar"},
                                              {"3R arm", "joints=RRR"},
                                              {"P6 arm", "joints=RRR wrist=spherical"},
                                              {"P7", "base=planar joints=RRR wrist=spherical"}};
    for (std::size_t i = 0; i < std::size(kPresets); ++i) {
      if (i > 0) ui::flow(ui::button_width(kPresets[i][0]));
      if (ui::small_button(kPresets[i][0])) robot_ = parse_robot_description(kPresets[i][1]);
    }

    fixed.reset();
    const ConfigSpaceInfo info = configuration_space(robot_);
    ui::section("Its configuration space");
    if (instructor::hidden("q_notation")) {  // P1-P7: the student writes Q
      instructor::hidden_line("Q, its dimension and a reason for each factor");
      return;
    }
    ImGui::TextColored(theme::vec4(theme::kTextKey), "Q = %s", info.notation.c_str());
    ImGui::TextWrapped("dimension %d: that many numbers fix a configuration", info.dimension);
    for (const NotationFactor& f : info.factors) {
      ImGui::Bullet();
      ImGui::TextWrapped("%s", f.reason.c_str());
    }
    if (!info.equivalent.empty()) {
      std::string also;
      for (const std::string& e : info.equivalent) also += (also.empty() ? "" : ",  ") + e;
      ImGui::TextWrapped("also written: %s", also.c_str());
    }
  }

  // The robot on screen: the exercise's in practice, the one built otherwise.
  RobotDescription shown() const {
    return practice_ ? parse_robot_description(kExercises[static_cast<std::size_t>(exercise_)].description) : robot_;
  }

  // Panel text that is also reported (state's panel_texts): what a student reads before answering.
  void said(const std::string& t) { panel_texts_.push_back(t); }
  void text(const std::string& t) {
    ImGui::TextWrapped("%s", t.c_str());
    said(t);
  }
  void section(const char* title) {
    ui::section(title);
    said(title);
  }

  void practice() {
    const Exercise& e = kExercises[static_cast<std::size_t>(exercise_)];
    section("Exercise");
    text(std::to_string(exercise_ + 1) + " of " + std::to_string(kExercises.size()));
    text(e.text);
    // The hint shows the syntax without any space in it: an example like "SE(2) x T^3" would
    // hand out the answer of some exercise.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    text("Write Q in the course's notation: powers with \"^\" (or superscripts), products with \"x\" (or \"×\").");
    ImGui::PopStyleColor();
    ImGui::PushItemWidth(-1);
    // A new exercise puts the cursor in the answer field: the student can type at once.
    if (focus_answer_) {
      ImGui::SetKeyboardFocusHere();
      focus_answer_ = false;
    }
    ImGui::PushID(exercise_);  // a fresh field for each exercise (an active one keeps its own text)
    const bool enter = ImGui::InputText("##answer", answer_buffer_, sizeof answer_buffer_,
                                        ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::PopID();
    ImGui::PopItemWidth();
    answer_ = answer_buffer_;
    if (ImGui::Button("Check") || enter) {
      run_check();
      focus_answer_ = true;  // keep typing: correct the answer and Enter again
    }
    said("Check");
    ui::flow(ui::button_width("Next exercise"));
    {
      instructor::FixedParam fixed("exercise");
      if (ImGui::Button("Next exercise")) {
        exercise_ = (exercise_ + 1) % static_cast<int>(kExercises.size());
        checked_ = false;
        answer_buffer_[0] = '\0';
        answer_.clear();
        focus_answer_ = true;
      }
    }
    said("Next exercise");
    if (checked_) {
      const ImVec4 colour = check_.correct ? theme::vec4(theme::kTextGood) : theme::vec4(theme::kTextBad);
      ImGui::PushStyleColor(ImGuiCol_Text, colour);
      text(check_.explanation);
      ImGui::PopStyleColor();
    }
  }

  void run_check() {
    check_ = check_answer(answer_, parse_robot_description(kExercises[static_cast<std::size_t>(exercise_)].description));
    checked_ = true;
  }

  // ---- The picture of the robot. Everything drawn is recorded in drawn_ (state reports it):
  // its kind, every text, the joints as drawn (R, P, W for the wrist) and its parts.
  struct Drawn {
    Picture kind = Picture::Arm;
    std::vector<std::string> captions;
    std::string joints;
    std::vector<const char*> parts;  // (literals: no string to build per part)
  };

  void caption(ImDrawList* dl, ImVec2 at, ImU32 col, const char* t, float wrap = 0.0f) {
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, col, t, nullptr, wrap);
    drawn_.captions.push_back(t);
  }
  void part(const char* name) { drawn_.parts.push_back(name); }

  // A joint: a circle turns (revolute; a small purple one for the wrist), a box slides.
  void joint(ImDrawList* dl, ImVec2 at, char kind, float unit) {
    drawn_.joints += kind;
    if (kind == 'P') {
      const float h = 0.25f * unit;
      dl->AddRectFilled(ImVec2(at.x - h, at.y - h), ImVec2(at.x + h, at.y + h), theme::kOrange, 2.0f);
      dl->AddRect(ImVec2(at.x - h, at.y - h), ImVec2(at.x + h, at.y + h), kInk);
      return;
    }
    const bool wrist = kind == 'W';
    const float r = (wrist ? 0.16f : 0.24f) * unit;
    dl->AddCircleFilled(at, r, wrist ? theme::kPurple : theme::kGreen, 20);
    dl->AddCircle(at, r, kInk, 20);
  }

  // The arm's joints from `at`, zigzagging up (dir -1) or down (dir +1), links between; returns
  // the tip.
  ImVec2 chain(ImDrawList* dl, ImVec2 at, const std::string& joints, float unit, float room, float dir = -1.0f) {
    const float link = std::min(1.3f * unit, 0.8f * room / static_cast<float>(joints.size() + 1));
    for (std::size_t i = 0; i < joints.size(); ++i) {
      const float angle = 1.25f + (i % 2 == 0 ? -0.45f : 0.35f);
      const ImVec2 next(at.x + link * std::cos(angle) * 0.9f, at.y + dir * link * std::sin(angle));
      dl->AddLine(at, next, kInk, 3.0f);
      joint(dl, at, joints[i], unit);
      at = next;
    }
    if (!joints.empty()) {
      dl->AddCircle(at, 0.15f * unit, kInk, 12, 2.0f);
      part("end effector");
    }
    return at;
  }

  void robot_picture(ImVec2 size) {
    const RobotDescription robot = shown();
    drawn_ = Drawn{};
    drawn_.kind = practice_ ? kExercises[static_cast<std::size_t>(exercise_)].picture : picture_of(robot);
    const ImVec2 o = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##robot", size);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), theme::kCanvasBg);
    dl->PushClipRect(o, ImVec2(o.x + size.x, o.y + size.y), true);
    const float unit = std::min(size.x, size.y) / 6.5f;
    const std::string joints = robot.joints + (robot.spherical_wrist ? "WWW" : "");
    const Frame f{o, size, unit};
    switch (drawn_.kind) {
      case Picture::Arm: fixed_arm(dl, f, joints); break;
      case Picture::Pendulum: pendulum(dl, f); break;
      case Picture::Vacuum: vacuum(dl, f); break;
      case Picture::Gantry: gantry(dl, f); break;
      case Picture::Drone: drone(dl, f, robot, joints); break;
      case Picture::Cart:
      case Picture::MobileArm: cart(dl, f, robot, joints, drawn_.kind == Picture::MobileArm); break;
    }
    legend(dl, f, robot);
    dl->PopClipRect();
  }

  struct Frame {
    ImVec2 o, size;
    float unit;
    ImVec2 at(float fx, float fy) const { return ImVec2(o.x + fx * size.x, o.y + fy * size.y); }
  };

  // The legend at the top, wrapped to the picture; and Q at the bottom (building only: in
  // practice nothing may name a factor, so the legend says what the symbols are, not their spaces).
  void legend(ImDrawList* dl, const Frame& f, const RobotDescription& robot) {
    ImFont* font = ImGui::GetFont();
    const float fs = ImGui::GetFontSize(), wrap = std::max(40.0f, f.size.x - 16);
    float y = f.o.y + 8;
    const bool joints = !drawn_.joints.empty();
    bool arrows = false;
    for (const char* p : drawn_.parts) arrows = arrows || std::strstr(p, "arrow") != nullptr;
    const char* lines[] = {
        !joints ? "" : practice_ ? "circles: revolute joints   boxes: prismatic joints" : "circles: revolute joints (S^1 each)   boxes: prismatic (R)",
        robot.spherical_wrist ? "small circles: the spherical wrist's three revolute joints" : "",
        arrows ? "orange arrows: how it moves" : ""};
    for (const char* line : lines) {
      if (!*line) continue;
      dl->AddRectFilled(ImVec2(f.o.x + 4, y), ImVec2(f.o.x + 12 + std::min(wrap, font->CalcTextSizeA(fs, 1e9f, wrap, line).x), y + font->CalcTextSizeA(fs, 1e9f, wrap, line).y),
                        theme::with_alpha(theme::kLabelBox, 220));
      caption(dl, ImVec2(f.o.x + 8, y), theme::kLabel, line, wrap);
      y += font->CalcTextSizeA(fs, 1e9f, wrap, line).y;
    }
    if (!practice_ && !instructor::hidden("q_notation")) {
      const std::string q = "Q = " + configuration_space(robot).notation;
      caption(dl, ImVec2(f.o.x + 8, f.o.y + f.size.y - 28), theme::kBlue, q.c_str());
    }
  }

  // An arm bolted down: hatching, then its chain upwards.
  void fixed_arm(ImDrawList* dl, const Frame& f, const std::string& joints) {
    const ImVec2 at = f.at(0.25f, 0.8f);
    hatched(dl, ImVec2(at.x - f.unit, at.y + 0.3f * f.unit), ImVec2(at.x + f.unit, at.y + 0.3f * f.unit), f.unit);
    part("fixed base");
    chain(dl, at, joints, f.unit, 0.65f * f.size.y);
    if (!practice_) caption(dl, ImVec2(at.x - f.unit, at.y + 0.8f * f.unit), theme::kLabel, "bolted down: adds nothing");
  }

  // A pendulum: a pivot under a ceiling, a rod hanging down, a bob, its swing.
  void pendulum(ImDrawList* dl, const Frame& f) {
    const ImVec2 pivot = f.at(0.5f, 0.22f);
    hatched(dl, ImVec2(pivot.x - 1.2f * f.unit, pivot.y - 0.3f * f.unit), ImVec2(pivot.x + 1.2f * f.unit, pivot.y - 0.3f * f.unit),
            f.unit, /*above=*/true);
    dl->AddLine(ImVec2(pivot.x, pivot.y - 0.3f * f.unit), pivot, kInk, 3.0f);
    part("ceiling");
    const float len = std::min(3.6f * f.unit, 0.55f * f.size.y), swing = 0.3f;  // rad from straight down
    const ImVec2 bob(pivot.x + len * std::sin(swing), pivot.y + len * std::cos(swing));
    dl->AddLine(pivot, bob, kInk, 3.0f);
    dl->AddCircleFilled(bob, 0.4f * f.unit, theme::rgba(90, 90, 100), 24);
    dl->AddCircle(bob, 0.4f * f.unit, kInk, 24, 1.5f);
    part("hanging bob");
    joint(dl, pivot, 'R', f.unit);
    // The swing: an arc around the pivot beyond the bob, heads both ways.
    const float r = len + 0.7f * f.unit, mid = 1.5708f;  // screen angle of straight down
    turn_arrow(dl, pivot, r, r, mid - 0.05f, mid - 0.55f, kMotion);
    turn_arrow(dl, pivot, r, r, mid + 0.05f, mid + 0.55f, kMotion);
    part("swing arrow");
  }

  // A robot vacuum seen from above: a round body on a tiled floor, arrows for sliding in two
  // directions and for turning on the spot.
  void vacuum(ImDrawList* dl, const Frame& f) {
    const ImVec2 lo = f.at(0.05f, 0.2f), hi = f.at(0.95f, 0.92f);
    dl->AddRectFilled(lo, hi, theme::rgba(236, 230, 218));
    for (float x = lo.x; x < hi.x; x += 0.9f * f.unit) dl->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), theme::rgba(215, 205, 190));
    for (float y = lo.y; y < hi.y; y += 0.9f * f.unit) dl->AddLine(ImVec2(lo.x, y), ImVec2(hi.x, y), theme::rgba(215, 205, 190));
    part("floor");
    const ImVec2 c = lerp(lo, hi, 0.45f);
    const float r = 1.1f * f.unit;
    dl->AddCircleFilled(c, r, theme::rgba(120, 125, 140), 48);
    dl->AddCircleFilled(c, 0.8f * r, theme::rgba(165, 170, 185), 48);
    dl->AddCircle(c, r, kInk, 48, 2.0f);
    dl->PathArcTo(c, 0.92f * r, -2.4f, -0.74f, 20);  // the bumper at its front
    dl->PathStroke(kInk, 0, 3.0f);
    dl->AddCircleFilled(ImVec2(c.x, c.y - 0.55f * r), 0.1f * r, kInk, 12);
    part("round body");
    arrow(dl, ImVec2(c.x + 1.15f * r, c.y), ImVec2(c.x + 2.1f * r, c.y), kMotion);
    caption(dl, ImVec2(c.x + 2.15f * r, c.y - 8), kMotion, "x");
    arrow(dl, ImVec2(c.x, c.y - 1.15f * r), ImVec2(c.x, c.y - 2.1f * r), kMotion);
    caption(dl, ImVec2(c.x + 6, c.y - 2.1f * r), kMotion, "y");
    turn_arrow(dl, c, 1.3f * r, 1.3f * r, 1.9f, 2.9f, kMotion);
    caption(dl, ImVec2(c.x - 1.9f * r, c.y + 1.25f * r), kMotion, "turns");
    part("slide arrows");
    part("turn arrow");
    caption(dl, ImVec2(lo.x + 6, hi.y - 22), theme::kLabel, "seen from above");
    if (!practice_) caption(dl, ImVec2(lo.x + 6, hi.y - 42), theme::kLabel, "slides and turns: SE(2)");
  }

  // A gantry crane in an oblique view: four posts, two rails along x, a bridge across them that
  // runs along x, a trolley on the bridge that runs along y, and a hoist block on its cable that
  // moves along z. The three carriages are the prismatic joints (boxes).
  void gantry(ImDrawList* dl, const Frame& f) {
    const float W = 4.0f, D = 2.4f, H = 3.2f, bx = 2.2f, ty = 1.3f, hz = 1.0f;
    const float u = std::min(f.size.x / (W + 0.55f * D + 1.4f), f.size.y / (H + 0.45f * D + 3.0f));
    // Centred: from the floor's front edge to the arrows over the bridge.
    const ImVec2 base(f.o.x + 0.06f * f.size.x, f.o.y + 0.5f * (f.size.y + u * (H + 0.45f * D + 0.8f)));
    const auto P = [&](float x, float y, float z) { return ImVec2(base.x + u * (x + 0.55f * y), base.y - u * (z + 0.45f * y)); };
    const ImU32 steel = theme::rgba(70, 80, 95), beam = theme::rgba(170, 95, 20);
    const ImVec2 floor[4] = {P(-0.3f, -0.3f, 0), P(W + 0.3f, -0.3f, 0), P(W + 0.3f, D + 0.3f, 0), P(-0.3f, D + 0.3f, 0)};
    dl->AddConvexPolyFilled(floor, 4, theme::rgba(236, 230, 218));
    part("floor");
    // Back to front: the back posts and rail, the bridge and what hangs from it, the front.
    for (float x : {0.0f, W}) dl->AddLine(P(x, D, 0), P(x, D, H), steel, 4.0f);
    dl->AddLine(P(-0.2f, D, H), P(W + 0.2f, D, H), steel, 5.0f);
    dl->AddLine(P(bx, -0.1f, H + 0.12f), P(bx, D + 0.1f, H + 0.12f), beam, 7.0f);
    part("bridge");
    dl->AddLine(P(bx, ty, H), P(bx, ty, hz), kInk, 1.5f);
    part("cable");
    joint(dl, P(bx, ty, H + 0.12f), 'P', 0.8f * u);  // the trolley on the bridge
    part("trolley");
    joint(dl, P(bx, ty, hz), 'P', 0.8f * u);  // the hoist block on its cable
    const ImVec2 hook = P(bx, ty, hz - 0.3f);
    dl->PathArcTo(ImVec2(hook.x, hook.y + 0.1f * u), 0.13f * u, -0.3f, 3.6f, 12);
    dl->PathStroke(kInk, 0, 2.0f);
    part("hoist");
    for (float x : {0.0f, W}) dl->AddLine(P(x, 0, 0), P(x, 0, H), steel, 4.0f);
    dl->AddLine(P(-0.2f, 0, H), P(W + 0.2f, 0, H), steel, 5.0f);
    part("posts");
    part("rails");
    joint(dl, P(bx, 0, H + 0.12f), 'P', 0.8f * u);  // the bridge's carriage on the front rail
    // How the carriages move: the bridge along the rails, the trolley along the bridge, the
    // hoist up and down.
    arrow(dl, P(bx - 1.7f, 0, H + 0.7f), P(bx + 0.2f, 0, H + 0.7f), kMotion, 2.5f, true);  // left of the trolley
    caption(dl, add(P(bx - 1.75f, 0, H + 0.7f), ImVec2(-12, -9)), kMotion, "x");
    arrow(dl, P(bx + 0.5f, 0.5f, H + 0.45f), P(bx + 0.5f, D - 0.3f, H + 0.45f), kMotion, 2.5f, true);
    caption(dl, add(P(bx + 0.5f, D - 0.2f, H + 0.45f), ImVec2(4, -16)), kMotion, "y");
    arrow(dl, P(bx + 0.55f, ty, hz), P(bx + 0.55f, ty, H - 0.45f), kMotion, 2.5f, true);
    caption(dl, add(P(bx + 0.55f, ty, 0.5f * (hz + H)), ImVec2(6, -8)), kMotion, "z");
    part("arrows x y z");
  }

  // A quadcopter in the air: a body, four arms, four spinning rotors, no wheels and no ground;
  // arrows for moving along three directions and for turning. A built robot's arm hangs below.
  void drone(ImDrawList* dl, const Frame& f, const RobotDescription& robot, const std::string& joints) {
    const float u = std::min(f.size.y / 7.0f, f.size.x / 6.4f);
    const ImVec2 c = f.at(0.5f, joints.empty() ? 0.5f : 0.36f);
    const ImVec2 rotors[4] = {ImVec2(c.x - 1.6f * u, c.y - 0.55f * u), ImVec2(c.x + 1.6f * u, c.y - 0.55f * u),
                              ImVec2(c.x - 2.0f * u, c.y + 0.3f * u), ImVec2(c.x + 2.0f * u, c.y + 0.3f * u)};
    const ImU32 body = theme::rgba(70, 80, 95);
    for (const ImVec2& r : rotors) {
      dl->AddLine(c, r, body, 5.0f);
      dl->AddLine(r, ImVec2(r.x, r.y - 0.2f * u), kInk, 3.0f);
      ellipse(dl, ImVec2(r.x, r.y - 0.22f * u), 0.75f * u, 0.16f * u, theme::rgba(150, 190, 230, 110), theme::rgba(60, 90, 130));
      part("rotor");
    }
    dl->AddRectFilled(ImVec2(c.x - 0.65f * u, c.y - 0.3f * u), ImVec2(c.x + 0.65f * u, c.y + 0.3f * u), body, 0.25f * u);
    dl->AddCircleFilled(ImVec2(c.x + 0.35f * u, c.y + 0.05f * u), 0.1f * u, theme::kSkyBlue, 12);  // its camera
    part("body");
    const bool turns = robot.base == RobotDescription::Base::SpatialMobile;
    const ImVec2 ax(c.x + 1.7f * u, c.y + 1.9f * u);  // the axes, off to the side below
    arrow(dl, ax, ImVec2(ax.x + 0.8f * u, ax.y), kMotion);
    caption(dl, ImVec2(ax.x + 0.85f * u, ax.y - 8), kMotion, "x");
    arrow(dl, ax, ImVec2(ax.x + 0.5f * u, ax.y - 0.45f * u), kMotion);
    caption(dl, ImVec2(ax.x + 0.55f * u, ax.y - 0.6f * u - 8), kMotion, "y");
    arrow(dl, ax, ImVec2(ax.x, ax.y - 0.8f * u), kMotion);
    caption(dl, ImVec2(ax.x - 14, ax.y - 0.95f * u - 8), kMotion, "z");
    part("arrows x y z");
    if (turns) {
      // Under the body, or over the rotors when an arm hangs below.
      const float y = joints.empty() ? c.y + 0.75f * u : c.y - 1.2f * u;
      turn_arrow(dl, ImVec2(c.x, y), 1.2f * u, 0.3f * u, 0.4f, 2.7f, kMotion);
      caption(dl, ImVec2(c.x - 2.0f * u, y + 0.4f * u), kMotion, "turns any way");
      part("turn arrow");
    }
    if (!practice_) {
      const char* what = turns ? "moves and turns in space: SE(3)" : "slides in space: R^3";
      caption(dl, ImVec2(f.o.x + 8, f.o.y + f.size.y - 50), theme::kLabel, what);
    }
    chain(dl, ImVec2(c.x, c.y + 0.3f * u), joints, f.unit, 0.55f * f.size.y, +1.0f);
  }

  // A wheeled base on the floor, seen from the side with the floor in perspective, its arm on
  // top: arrows for sliding along the floor both ways; a turning arrow only if it turns.
  void cart(ImDrawList* dl, const Frame& f, const RobotDescription& robot, const std::string& joints, bool turns) {
    (void)robot;
    const float u = f.unit;
    const ImVec2 at = f.at(0.35f, 0.78f);
    const ImVec2 floor[4] = {ImVec2(f.o.x + 4 + 0.8f * u, at.y + 0.2f * u), ImVec2(f.o.x + f.size.x - 4, at.y + 0.2f * u),
                             ImVec2(f.o.x + f.size.x - 4 - 0.8f * u, at.y + 1.5f * u), ImVec2(f.o.x + 4, at.y + 1.5f * u)};
    dl->AddConvexPolyFilled(floor, 4, theme::rgba(236, 230, 218));
    part("floor");
    dl->AddRectFilled(ImVec2(at.x - u, at.y - 0.2f * u), ImVec2(at.x + u, at.y + 0.4f * u), theme::with_alpha(theme::kSkyBlue, 200), 4.0f);
    dl->AddRect(ImVec2(at.x - u, at.y - 0.2f * u), ImVec2(at.x + u, at.y + 0.4f * u), kInk, 4.0f);
    for (float dx : {-0.6f, 0.6f}) {
      dl->AddCircleFilled(ImVec2(at.x + dx * u, at.y + 0.55f * u), 0.22f * u, kInk, 16);
      part("wheel");
    }
    arrow(dl, ImVec2(at.x + 1.3f * u, at.y + 0.15f * u), ImVec2(at.x + 2.2f * u, at.y + 0.15f * u), kMotion, 2.5f, true);
    caption(dl, ImVec2(at.x + 2.25f * u, at.y + 0.15f * u - 8), kMotion, "x");
    arrow(dl, ImVec2(at.x + 1.35f * u, at.y + 0.9f * u), ImVec2(at.x + 1.95f * u, at.y + 1.4f * u), kMotion, 2.5f, true);
    caption(dl, ImVec2(at.x + 2.0f * u, at.y + 1.3f * u), kMotion, "y");
    part("slide arrows");
    if (turns) {
      turn_arrow(dl, ImVec2(at.x, at.y + 0.1f * u), 1.5f * u, 0.45f * u, 0.3f, 2.8f, kMotion);
      caption(dl, ImVec2(at.x - 2.2f * u, at.y + 0.55f * u), kMotion, "turns");
      part("turn arrow");
    }
    if (!practice_)
      caption(dl, ImVec2(f.o.x + 8, f.o.y + f.size.y - 50), theme::kLabel, turns ? "slides and turns: SE(2)" : "slides only: R^2");
    chain(dl, ImVec2(at.x, at.y - 0.2f * u), joints, u, 0.6f * f.size.y);
  }

  // The torus with a loop around its hole, the sphere with a loop shrinking to a point.
  void surfaces(ImVec2 size) {
    const float h = 0.5f * size.y - 6.0f;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImU32 surface = theme::rgba(200, 205, 215);
    const double t = ImGui::GetTime();

    torus_.begin("##torus", ImVec2(size.x, h), 1.5);
    torus_.draw_surface([](double u, double v) { return torus_point(u, v); }, 48, 20,
                        [&](double, double) { return surface; });
    std::vector<SurfacePoint> around, small;
    for (int i = 0; i <= 96; ++i) {
      around.push_back(torus_point(i / 96.0, 0.25));
      small.push_back(torus_point(0.12 + 0.05 * std::cos(kTwoPi * i / 96.0), 0.25 + 0.1 * std::sin(kTwoPi * i / 96.0)));
    }
    torus_.draw_curve(around, theme::kVermillion, 3.0f);
    torus_.draw_curve(small, theme::kGreen, 3.0f);
    const ImVec2 t0 = ImGui::GetItemRectMin();
    surface_captions_.clear();
    // In practice, before an answer is checked, the names stay off: T^2 is a factor of many answers.
    const bool named = !practice_ || checked_;
    surface_caption(dl, ImVec2(t0.x + 6, t0.y + 4), named ? "T^2: the loop around the hole cannot shrink"
                                                         : "a torus: the loop around the hole cannot shrink", size.x - 12);

    ImGui::Dummy(ImVec2(0, 4));
    sphere_.begin("##sphere", ImVec2(size.x, h), 1.3);
    sphere_.draw_surface(sphere_point, 40, 20, [&](double, double) { return surface; });
    // A loop of latitude sliding towards the pole and shrinking, again and again; with reduced
    // motion (the page's prefers-reduced-motion) the same story still: three loops, each smaller.
    const auto loop = [&](double phase) {
      std::vector<SurfacePoint> latitude;
      for (int i = 0; i <= 96; ++i) latitude.push_back(sphere_point(i / 96.0, 0.02 + 0.5 * (1.0 - phase)));
      sphere_.draw_curve(latitude, theme::kGreen, 3.0f);
    };
    if (web::page().reduced_motion) {
      for (double phase : {0.95, 0.5, 0.1}) loop(phase);
    } else {
      loop(0.5 + 0.45 * std::cos(0.8 * t));
    }
    const ImVec2 s0 = ImGui::GetItemRectMin();
    surface_caption(dl, ImVec2(s0.x + 6, s0.y + 4), named ? "S^2: every loop shrinks to a point" : "a sphere: every loop shrinks to a point",
                    size.x - 12);
  }

  void surface_caption(ImDrawList* dl, ImVec2 at, const char* t, float wrap) {
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, theme::kLabel, t, nullptr, wrap);  // wrapped: a narrow panel
    surface_captions_.push_back(t);
  }

  RobotDescription robot_;
  bool practice_ = false;
  int exercise_ = 0;
  std::string answer_;
  char answer_buffer_[256] = "";
  bool focus_answer_ = false;
  bool checked_ = false;
  AnswerCheck check_;
  SurfaceView torus_, sphere_;
  Drawn drawn_;                                // the picture as drawn last frame
  std::vector<std::string> surface_captions_;  // the surfaces' texts, last frame
  std::vector<std::string> panel_texts_;       // the panel's texts, last frame
};

}  // namespace

CSL_REGISTER_LESSON(NotationLesson, "notation", "C-space notation", "Configuration spaces");

}  // namespace csl::app
