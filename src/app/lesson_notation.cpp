// Lesson "C-space notation": build a robot (base, joints, wrist) and read its configuration
// space in the course's notation, with the reason for every factor; practise writing Q for
// described robots, with the lab checking and explaining; and see why S^1 x S^1 is the torus
// and not the sphere.
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>

#include "app/js_api.hpp"
#include "app/lesson.hpp"
#include "app/surface_view.hpp"
#include "app/theme.hpp"
#include "app/ui.hpp"
#include "core/angles.hpp"
#include "core/notation.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;

struct Exercise {
  const char* text;         // in our words
  const char* description;  // for the checker
};
// The kinds of robots of the homework's P1-P7, and a few more.
const std::array<Exercise, 9> kExercises = {{
    {"A robot vacuum: it slides over the floor and turns on the spot.", "base=planar"},
    {"An arm bolted to a table, with three revolute joints.", "joints=RRR"},
    {"A single revolute joint: a pendulum.", "joints=R"},
    {"An arm with two revolute joints and then a prismatic joint that extends the last link.", "joints=RRP"},
    {"A gantry crane: three prismatic joints, along x, y and z.", "joints=PPP"},
    {"A six-link arm whose last three revolute joints form a spherical wrist.", "joints=RRR wrist=spherical"},
    {"The same six-link arm, on a base that slides and turns in the plane.", "base=planar joints=RRR wrist=spherical"},
    {"A drone: a rigid body that moves and turns freely in space.", "base=spatial"},
    {"A cart that slides in the plane without turning, carrying a prismatic then a revolute joint.",
     "base=planar-translating joints=PR"},
}};

const char* const kBaseNames[] = {"fixed", "planar, sliding only", "planar, sliding and turning", "spatial, sliding only",
                                  "spatial, free"};
const char* const kBaseTokens[] = {"fixed", "planar-translating", "planar", "spatial-translating", "spatial"};

class NotationLesson : public Lesson {
 public:
  NotationLesson() { robot_ = parse_robot_description("joints=RR"); }

  void panel(LabContext&) override {
    int mode = practice_ ? 1 : 0;
    if (ImGui::RadioButton("Build a robot", &mode, 0)) practice_ = false;
    ui::flow(ui::toggle_width("Practice"));
    if (ImGui::RadioButton("Practice", &mode, 1) && !practice_) {
      practice_ = true;
      focus_answer_ = true;
    }
    if (!practice_) builder();
    else practice();
    ui::section("Why S^1 x S^1 is not S^2");
    ImGui::TextWrapped("Two angles make a torus, the surface of a ring: going once around the ring, or once "
                       "around its tube, brings you back where you started, and such a loop can never be pulled "
                       "tight to a point without leaving the surface. On a sphere every loop can be shrunk to a "
                       "point. So a 2-link arm's C-space is T^2 = S^1 x S^1, not S^2; likewise SO(2) x SO(2) is "
                       "not SO(3). Drag the pictures to turn them.");
  }

  void views(LabContext&, ImVec2 size) override {
    const ImGuiWindowFlags still = ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;
    ImGui::BeginChild("robot-picture", ImVec2(size.x * 0.5f, size.y), true, still);
    robot_picture(ImGui::GetContentRegionAvail());
    ImGui::EndChild();
    ImGui::SameLine();
    ImGui::BeginChild("surfaces", ImVec2(0, size.y), true, still);
    surfaces(ImGui::GetContentRegionAvail());
    ImGui::EndChild();
  }

  json state(const json&) const override {
    const ConfigSpaceInfo info = configuration_space(robot_);
    json factors = json::array();
    for (const NotationFactor& f : info.factors)
      factors.push_back({{"factor", f.notation}, {"dimension", f.dimension}, {"reason", f.reason}});
    json out{{"mode", practice_ ? "practice" : "build"},
             {"description", description(robot_)},
             {"notation", info.notation},
             {"dimension", info.dimension},
             {"factors", factors},
             {"equivalent", info.equivalent},
             {"exercise", exercise_},
             {"exercise_text", kExercises[static_cast<std::size_t>(exercise_)].text},
             {"answer", answer_}};
    if (checked_) out["check"] = {{"correct", check_.correct}, {"explanation", check_.explanation}};
    return out;
  }

  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    RobotDescription robot = robot_;
    bool practice = practice_;
    int exercise = exercise_;
    std::string answer = answer_;
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
    if (exercise != exercise_) checked_ = false;
    exercise_ = exercise;
    answer_ = answer;
    std::snprintf(answer_buffer_, sizeof answer_buffer_, "%s", answer_.c_str());
    if (check) run_check();
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
      if (ImGui::SmallButton(kPresets[i][0])) robot_ = parse_robot_description(kPresets[i][1]);
    }

    const ConfigSpaceInfo info = configuration_space(robot_);
    ui::section("Its configuration space");
    ImGui::TextColored(ImVec4(0.0f, 0.3f, 0.55f, 1.0f), "Q = %s", info.notation.c_str());
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

  void practice() {
    ui::section("Exercise");
    ImGui::Text("%d of %zu", exercise_ + 1, kExercises.size());
    ImGui::TextWrapped("%s", kExercises[static_cast<std::size_t>(exercise_)].text);
    ImGui::TextDisabled("Write Q, e.g.  SE(2) x T^3  or  R^2 x S^1");
    ImGui::PushItemWidth(-1);
    // A new exercise puts the cursor in the answer field: the student can type at once.
    if (focus_answer_) {
      ImGui::SetKeyboardFocusHere();
      focus_answer_ = false;
    }
    const bool enter = ImGui::InputText("##answer", answer_buffer_, sizeof answer_buffer_,
                                        ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::PopItemWidth();
    answer_ = answer_buffer_;
    if (ImGui::Button("Check") || enter) {
      run_check();
      focus_answer_ = true;  // keep typing: correct the answer and Enter again
    }
    ui::flow(ui::button_width("Next exercise"));
    if (ImGui::Button("Next exercise")) {
      exercise_ = (exercise_ + 1) % static_cast<int>(kExercises.size());
      checked_ = false;
      answer_buffer_[0] = '\0';
      focus_answer_ = true;
    }
    if (checked_) {
      const ImVec4 colour = check_.correct ? ImVec4(0.0f, 0.45f, 0.3f, 1.0f) : ImVec4(0.7f, 0.25f, 0.0f, 1.0f);
      ImGui::PushStyleColor(ImGuiCol_Text, colour);
      ImGui::TextWrapped("%s", check_.explanation.c_str());
      ImGui::PopStyleColor();
    }
    // The robot of the exercise is shown in the picture.
    robot_ = parse_robot_description(kExercises[static_cast<std::size_t>(exercise_)].description);
  }

  void run_check() {
    check_ = check_answer(answer_, parse_robot_description(kExercises[static_cast<std::size_t>(exercise_)].description));
    checked_ = true;
  }

  // A schematic of the robot: its base, then its joints in a chain (circles turn, boxes slide).
  void robot_picture(ImVec2 size) {
    const ImVec2 o = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##robot", size);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(o, ImVec2(o.x + size.x, o.y + size.y), theme::kCanvasBg);
    const float unit = std::min(size.x, size.y) / 6.5f;
    ImVec2 at(o.x + 0.2f * size.x, o.y + 0.78f * size.y);
    const ImU32 ink = theme::rgba(40, 40, 48);
    // The base.
    switch (robot_.base) {
      case RobotDescription::Base::Fixed:
        dl->AddLine(ImVec2(at.x - unit, at.y + 0.3f * unit), ImVec2(at.x + unit, at.y + 0.3f * unit), ink, 2.0f);
        for (int i = 0; i < 6; ++i) {
          const float x = at.x - unit + static_cast<float>(i) * unit * 0.4f;
          dl->AddLine(ImVec2(x, at.y + 0.3f * unit), ImVec2(x - 0.3f * unit, at.y + 0.7f * unit), ink, 1.0f);
        }
        break;
      case RobotDescription::Base::PlanarTranslating:
      case RobotDescription::Base::PlanarMobile:
      case RobotDescription::Base::SpatialTranslating:
      case RobotDescription::Base::SpatialMobile: {
        const bool turns = robot_.base == RobotDescription::Base::PlanarMobile ||
                           robot_.base == RobotDescription::Base::SpatialMobile;
        dl->AddRectFilled(ImVec2(at.x - unit, at.y - 0.2f * unit), ImVec2(at.x + unit, at.y + 0.4f * unit),
                          theme::with_alpha(theme::kSkyBlue, 160), 4.0f);
        dl->AddCircleFilled(ImVec2(at.x - 0.6f * unit, at.y + 0.55f * unit), 0.22f * unit, ink);
        dl->AddCircleFilled(ImVec2(at.x + 0.6f * unit, at.y + 0.55f * unit), 0.22f * unit, ink);
        dl->AddText(ImVec2(at.x - unit, at.y + 0.9f * unit), theme::kLabel,
                    robot_.base == RobotDescription::Base::SpatialMobile        ? "moves and turns in space: SE(3)"
                    : robot_.base == RobotDescription::Base::SpatialTranslating ? "slides in space: R^3"
                    : turns                                                    ? "slides and turns: SE(2)"
                                                                               : "slides only: R^2");
        if (turns) dl->PathArcTo(at, 1.4f * unit, -2.6f, -0.5f, 24), dl->PathStroke(theme::kOrange, 0, 2.0f);
        break;
      }
    }
    // The joints, alternating directions so the chain zigzags upwards.
    std::string chain = robot_.joints + (robot_.spherical_wrist ? "WWW" : "");
    const float link = std::min(1.3f * unit, 0.7f * size.y / static_cast<float>(chain.size() + 1));
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const float angle = 1.25f + (i % 2 == 0 ? -0.45f : 0.35f);
      const ImVec2 next(at.x + link * std::cos(angle) * 0.9f, at.y - link * std::sin(angle));
      dl->AddLine(at, next, ink, 3.0f);
      if (chain[i] == 'P') {
        dl->AddRectFilled(ImVec2(at.x - 0.25f * unit, at.y - 0.25f * unit), ImVec2(at.x + 0.25f * unit, at.y + 0.25f * unit),
                          theme::kOrange, 2.0f);
        dl->AddRect(ImVec2(at.x - 0.25f * unit, at.y - 0.25f * unit), ImVec2(at.x + 0.25f * unit, at.y + 0.25f * unit), ink);
      } else {
        const bool wrist = chain[i] == 'W';
        dl->AddCircleFilled(at, (wrist ? 0.16f : 0.24f) * unit, wrist ? theme::kPurple : theme::kGreen, 20);
        dl->AddCircle(at, (wrist ? 0.16f : 0.24f) * unit, ink, 20);
      }
      at = next;
    }
    dl->AddCircle(at, 0.15f * unit, ink, 12, 2.0f);
    // The legend, wrapped to the picture (a narrow panel cut it off).
    ImFont* font = ImGui::GetFont();
    const float fs = ImGui::GetFontSize(), wrap = std::max(40.0f, size.x - 16);
    float y = o.y + 8;
    for (const char* line : {"circles: revolute joints (S^1 each)   boxes: prismatic (R)",
                             robot_.spherical_wrist ? "small circles: the spherical wrist's three revolute joints" : ""}) {
      dl->AddText(font, fs, ImVec2(o.x + 8, y), theme::kLabel, line, nullptr, wrap);
      y += font->CalcTextSizeA(fs, 1e9f, wrap, line).y;
    }
    // In practice mode the picture must not give the answer away.
    if (!practice_) {
      char q[128];
      std::snprintf(q, sizeof q, "Q = %s", configuration_space(robot_).notation.c_str());
      dl->AddText(nullptr, 0.0f, ImVec2(o.x + 8, o.y + size.y - 28), theme::kBlue, q);
    }
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
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(t0.x + 6, t0.y + 4), theme::kLabel,
                "T^2: the loop around the hole cannot shrink", nullptr, size.x - 12);  // wrapped: a narrow panel

    ImGui::Dummy(ImVec2(0, 4));
    sphere_.begin("##sphere", ImVec2(size.x, h), 1.3);
    sphere_.draw_surface(sphere_point, 40, 20, [&](double, double) { return surface; });
    // A loop of latitude sliding towards the pole and shrinking, again and again.
    const double phase = 0.5 + 0.45 * std::cos(0.8 * t);
    std::vector<SurfacePoint> latitude;
    for (int i = 0; i <= 96; ++i) latitude.push_back(sphere_point(i / 96.0, 0.02 + 0.5 * (1.0 - phase)));
    sphere_.draw_curve(latitude, theme::kGreen, 3.0f);
    const ImVec2 s0 = ImGui::GetItemRectMin();
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(s0.x + 6, s0.y + 4), theme::kLabel,
                "S^2: every loop shrinks to a point", nullptr, size.x - 12);
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
};

}  // namespace

CSL_REGISTER_LESSON(NotationLesson, "notation", "C-space notation", "Configuration spaces");

}  // namespace csl::app
