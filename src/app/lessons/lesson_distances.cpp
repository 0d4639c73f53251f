// Lesson "Distances": the two distance derivations of the homework, each as a tool to drag and
// type into, with every intermediate number on screen.
// - Angles on S^1 (P10): two directions on the unit circle; their distance by the modulus and by
//   rotation matrices, the shorter arc drawn, equal and opposite directions explained, and what
//   the lab's PRM does with this distance on S^1 and T^2.
// - Segment to disk (P11): the centre projected onto the segment, the parameter clamped, the
//   nearest point, the distance max(0, |q - c| - r), which special case holds, and the signed
//   clearance the lab's collision checker keeps instead.
// The numbers come from core/teaching/distances.hpp; this file lays them out and handles the mouse.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

#include "app/shell/input_mode.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/fonts.hpp"
#include "app/shell/js_api.hpp"
#include "app/shell/lesson.hpp"
#include "core/base/text.hpp"
#include "app/shell/panel.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "core/base/angles.hpp"
#include "core/base/detmath.hpp"
#include "core/teaching/distances.hpp"

namespace csl::app {
namespace {

using json = nlohmann::json;
using ui::text_flow;

// What the lesson takes: angles of a few hundred turns and coordinates far beyond the unit
// workspace are allowed, nothing where a double's spacing would show in the printed digits.
constexpr double kMaxAngle = 1000.0;
constexpr double kMaxCoordinate = 1000.0;
constexpr double kCircleHalf = 1.45;  // the circle view shows [-1.45, 1.45]^2: the unit circle and its labels

// Colours: q1 and q2 as the lab's start and goal, the short arc as a path.
constexpr ImU32 kQ1 = theme::kBlue;
constexpr ImU32 kQ2 = theme::kVermillion;
constexpr ImU32 kShortArc = theme::kOrange;
// The names of the circle's ticks at 0, π/2, π and 3π/2.
const char* const kTickNames[] = {"0 = 2π", "π/2", "π", "3π/2"};
constexpr ImU32 kLongArc = theme::rgba(86, 180, 233, 110);  // sky blue, faint
const ImU32& kSegment = theme::kInk;
constexpr ImU32 kClosest = theme::kPurple;
const ImU32& kGuide = theme::kFaint;
constexpr ImU32 kMeetColour = theme::kVermillion;

// By touch there is no Shift to hold: that hint is for a keyboard.
const char* s1_hint() {
  return input::touch() ? "Drag q₁ or q₂ round the circle (they snap onto equal and opposite directions), "
                          "or type radians in the panel."
                        : "Drag q₁ or q₂ round the circle (they snap onto equal and opposite directions; hold "
                          "Shift not to snap), or type radians in the panel.";
}
const char* const kSegmentHint = "Drag p₁, p₂, the centre q or the disk's rim, or type them in the panel.";


// A number as the panel prints it: 4 decimals, no "-0.0000".
std::string num(double v) {
  if (std::isnan(v)) return "undefined";
  std::string s = ui::format("%.4f", v);
  return s == "-0.0000" ? "0.0000" : s;
}
// A negative number in parentheses, for products written out.
std::string factor(double v) {
  const std::string s = num(v);
  return s[0] == '-' ? "(" + s + ")" : s;
}
std::string point(const Vec2& p) { return "(" + num(p.x()) + ", " + num(p.y()) + ")"; }
double degrees(double radians) { return radians * (180.0 / kPi); }

json vec_json(const Vec2& v) { return json::array({v.x(), v.y()}); }
// NaN and infinities have no JSON: null says "undefined" (t* of a one-point segment).
json number_json(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// The direction of a in [0, 2pi), as the P10 tool shows angles.
double wrap_positive(double a) {
  double w = wrap_angle(a);
  if (w < 0.0) w += kTwoPi;
  return w < kTwoPi ? w : 0.0;
}

// Text wrapped at spaces only. ImGui's own wrapping also breaks after a '.', which cut numbers
// in two ("0." at a line's end, "9832" on the next).
// A dashed line between two screen points.
void dashed(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 colour, float thickness = 1.5f, float dash = 6.0f) {
  const float length = std::hypot(b.x - a.x, b.y - a.y);
  if (!(length > 0.5f) || !std::isfinite(length)) return;
  const int pieces = std::min(400, static_cast<int>(length / dash));
  for (int i = 0; i < pieces; i += 2) {
    const float t0 = static_cast<float>(i) * dash / length,
                t1 = std::min(1.0f, static_cast<float>(i + 1) * dash / length);
    dl->AddLine(ImVec2(a.x + t0 * (b.x - a.x), a.y + t0 * (b.y - a.y)),
                ImVec2(a.x + t1 * (b.x - a.x), a.y + t1 * (b.y - a.y)), colour, thickness);
  }
}

// Text with a white box behind it, so that it stays readable over lines and fills; moved inside
// the clip rectangle when it would stick out (a label of a point near the view's edge).
void boxed_text(ImDrawList* dl, ImVec2 at, ImU32 colour, const std::string& text) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const ImVec2 lo = dl->GetClipRectMin(), hi = dl->GetClipRectMax();
  at.x = std::max(lo.x + 4.0f, std::min(at.x, hi.x - size.x - 4.0f));
  at.y = std::max(lo.y + 2.0f, std::min(at.y, hi.y - size.y - 2.0f));
  dl->AddRectFilled(ImVec2(at.x - 3, at.y - 1), ImVec2(at.x + size.x + 3, at.y + size.y + 1),
                    theme::kLabelBox, 3.0f);
  dl->AddText(at, colour, text.c_str());
}
// The same, centred on a point.
void boxed_text_centred(ImDrawList* dl, ImVec2 centre, ImU32 colour, const std::string& text) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  boxed_text(dl, ImVec2(centre.x - 0.5f * size.x, centre.y - 0.5f * size.y), colour, text);
}
// The same beside a point: `gap` pixels from it towards `dir` (a unit vector on the screen).
void boxed_text_beside(ImDrawList* dl, ImVec2 anchor, ImVec2 dir, float gap, ImU32 colour, const std::string& text) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const float reach = gap + 0.5f * (std::fabs(dir.x) * size.x + std::fabs(dir.y) * size.y);
  boxed_text_centred(dl, ImVec2(anchor.x + dir.x * reach, anchor.y + dir.y * reach), colour, text);
}
// The screen direction from one point to another (`fallback` when they coincide).
ImVec2 unit_between(ImVec2 from, ImVec2 to, ImVec2 fallback) {
  const float length = std::hypot(to.x - from.x, to.y - from.y);
  return length > 0.5f ? ImVec2((to.x - from.x) / length, (to.y - from.y) / length) : fallback;
}

class DistancesLesson : public Lesson {
 public:
  DistancesLesson() { recompute(); }

  void panel(LabContext& ctx) override {
    int tool = segment_tool_ ? 1 : 0;
    {
      instructor::FixedParam fixed("tool");
      if (ImGui::RadioButton("Angles on S¹ (P10)", &tool, 0)) switch_tool(false);
      web::record_control("distances-tool-s1");
      ui::flow(ui::toggle_width("Segment to disk (P11)"));
      if (ImGui::RadioButton("Segment to disk (P11)", &tool, 1)) switch_tool(true);
      web::record_control("distances-tool-segment");
    }
    ImGui::Separator();
    if (segment_tool_) segment_panel(ctx);
    else s1_panel(ctx);
  }

  void views(LabContext& ctx, ImVec2 size) override {
    if (!refused_.empty()) {  // (a press last frame on a fixed handle)
      ctx.notify(refused_, 4.0);
      refused_.clear();
    }
    if (segment_tool_) {
      ctx.views.erase("circle");
      segment_view(ctx, size);
    } else {
      ctx.views.erase("workspace");
      s1_view(ctx, size);
    }
  }

  std::vector<LessonView> views_kept() override {
    fit_bounds();  // (the segment tool's rectangle follows its segment and disk)
    return {{"circle", &circle_view_, Vec2(-kCircleHalf, -kCircleHalf), Vec2(kCircleHalf, kCircleHalf)}, {"workspace", &view_, bounds_lo_, bounds_hi_}};
  }

  json state(const json& args) const override {
    const S1DistanceReport& a = s1_;
    const SegmentDiskReport& s = segment_;
    json out = params();
    out["s1"] = {{"q1", a.q1},
                 {"q2", a.q2},
                 {"wrapped", {a.wrapped1, a.wrapped2}},
                 {"degrees", {degrees(a.q1), degrees(a.q2)}},
                 {"raw_difference", a.raw_difference},
                 {"modulus", a.modulus},
                 {"other_way", a.other_way},
                 {"modular_distance", a.modular_distance},
                 {"cos", {a.cos1, a.cos2}},
                 {"sin", {a.sin1, a.sin2}},
                 {"dot", a.dot},
                 {"cross", a.cross},
                 {"arccos_distance", a.arccos_distance},
                 {"distance", a.distance},
                 {"rotation_distance", a.rotation_distance},
                 {"signed_turn", a.signed_turn},
                 {"wraps_around", a.wraps_around},
                 {"case", s1_case_name(a.kind)}};
    out["segment"] = {{"p1", vec_json(s.p1)},
                      {"p2", vec_json(s.p2)},
                      {"q", vec_json(s.q)},
                      {"r", s.r},
                      {"direction", vec_json(s.direction)},
                      {"length_squared", s.length_squared},
                      {"dot", s.dot},
                      {"t_raw", number_json(s.t_raw)},
                      {"t", s.t},
                      {"foot", {number_json(s.foot.x()), number_json(s.foot.y())}},
                      {"closest", vec_json(s.closest)},
                      {"centre_distance", s.centre_distance},
                      {"distance", s.distance},
                      {"signed_distance", s.signed_distance},
                      {"lab_clearance", s.lab_clearance},
                      {"meets", s.meets},
                      {"case", segment_disk_case_name(s.where)}};
    out["dragging"] = drag_name();
    // Where the caption was drawn last frame (canvas px): only when asked, as it depends on the window.
    if (args.is_object() && args.value("layout", false)) {
      out["caption_layout"] = {{"box", std::vector<float>(caption_box_.begin(), caption_box_.begin() + 4)},
                               {"view_right", caption_box_[4]}};
      // P10's circle: the arcs' length labels ("d = …" first); the handles' dots (q₁'s, q₂'s),
      // then their names (each box: left, top, right, bottom).
      json labels = json::array(), handles = json::array();
      for (const Box& b : arc_boxes_) labels.push_back({b.x0, b.y0, b.x1, b.y1});
      for (const Box& b : handle_boxes_) handles.push_back({b.x0, b.y0, b.x1, b.y1});
      out["circle_layout"] = {{"arc_labels", labels}, {"handles", handles}};
    }
    return out;
  }

  // Everything checked first; a refusal names the key and changes nothing.
  void set_params(const json& j) override {
    if (!j.is_object()) throw ApiError("params must be an object");
    bool segment = segment_tool_;
    double q1 = q1_, q2 = q2_, r = r_;
    Vec2 p1 = p1_, p2 = p2_, q = q_;
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& key = it.key();
      if (key == "tool") {
        if (!it->is_string() || (*it != "s1" && *it != "segment")) throw ApiError("tool: \"s1\" or \"segment\"");
        segment = *it == "segment";
      } else if (key == "q1" || key == "q2") {
        (key == "q1" ? q1 : q2) = number(*it, key, -kMaxAngle, kMaxAngle, "an angle in radians within ±1000");
      } else if (key == "p1" || key == "p2" || key == "q") {
        if (!it->is_array() || it->size() != 2) throw ApiError(key + ": [x, y], each within ±1000");
        const Vec2 v(number((*it)[0], key, -kMaxCoordinate, kMaxCoordinate, "[x, y], each within ±1000"),
                     number((*it)[1], key, -kMaxCoordinate, kMaxCoordinate, "[x, y], each within ±1000"));
        (key == "p1" ? p1 : key == "p2" ? p2 : q) = v;
      } else if (key == "r") {
        r = number(*it, key, 0.0, kMaxCoordinate, "a radius in [0, 1000]");
      } else {
        throw ApiError("unknown parameter \"" + key + "\" (tool, q1, q2, p1, p2, q, r)");
      }
    }
    segment_tool_ = segment;
    q1_ = q1;
    q2_ = q2;
    p1_ = p1;
    p2_ = p2;
    q_ = q;
    r_ = r;
    drag_ = Drag::None;
    recompute();
  }

  std::vector<ParamField> param_fields() const override {
    return {{"tool", "tool", nullptr, {"s1", "segment"}}};
  }

  std::string describe() const override {
    const std::string hidden = std::string(" is ") + instructor::kHidden + ".";
    if (!segment_tool_)
      return "Two angles on the circle S1: q1 = " + significant(s1_.q1) + " and q2 = " + significant(s1_.q2) +
             " radians. Their distance on the circle" +
             (instructor::hidden("s1_distance") ? hidden
                                                : " is " + significant(s1_.distance) + " (case: " + s1_case_name(s1_.kind) + ").");
    return "A segment from (" + significant(p1_.x()) + ", " + significant(p1_.y()) + ") to (" + significant(p2_.x()) +
           ", " + significant(p2_.y()) + ") and a disk at (" + significant(q_.x()) + ", " + significant(q_.y()) +
           ") of radius " + significant(r_) + ". The segment's distance to the disk" +
           (instructor::hidden("segment_distance")
                ? hidden
                : " is " + significant(segment_.distance) + (segment_.meets ? ": they meet." : ": they do not meet."));
  }

  json params() const override {
    return {{"tool", segment_tool_ ? "segment" : "s1"},
            {"q1", q1_},
            {"q2", q2_},
            {"p1", vec_json(p1_)},
            {"p2", vec_json(p2_)},
            {"q", vec_json(q_)},
            {"r", r_}};
  }

 private:
  enum class Drag { None, Q1, Q2, P1, P2, Centre, Rim };

  static double number(const json& v, const std::string& key, double lo, double hi, const char* what) {
    if (!v.is_number()) throw ApiError(key + ": " + what);
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi) throw ApiError(key + ": " + what);
    return x;
  }

  // A handle of a parameter the instructor fixed does not move: a press on it says why.
  bool fixed(Drag which) {
    const json name = drag_name(which);
    if (name.is_null() || !instructor::param_locked(name.get<std::string>())) return false;
    refused_ = instructor::param_refusal(name.get<std::string>());
    return true;
  }

  json drag_name() const { return drag_name(drag_); }
  static json drag_name(Drag drag) {
    switch (drag) {
      case Drag::Q1: return "q1";
      case Drag::Q2: return "q2";
      case Drag::P1: return "p1";
      case Drag::P2: return "p2";
      case Drag::Centre: return "q";
      case Drag::Rim: return "r";
      case Drag::None: break;
    }
    return nullptr;
  }

  void switch_tool(bool segment) {
    segment_tool_ = segment;
    drag_ = Drag::None;
  }

  void recompute() {
    s1_ = s1_distance_report(q1_, q2_);
    segment_ = segment_disk_report(p1_, p2_, q_, r_);
  }

  // ------------------------------------------------------------------ P10: the panel

  // One angle's row: the field (radians), its degrees. Out-of-range input is refused with a notice.
  void angle_field(LabContext& ctx, const char* label, const char* id, const char* control, double& value) {
    instructor::FixedParam fixed(control + std::string(control).rfind('-') + 1);  // "distances-q1": q1
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(label);
    ImGui::SameLine(28.0f);
    ImGui::SetNextItemWidth(std::min(130.0f, ImGui::GetContentRegionAvail().x * 0.45f));
    double v = value;
    if (ImGui::InputDouble(id, &v, 0.0, 0.0, "%.4f")) {
      if (std::isfinite(v) && std::fabs(v) <= kMaxAngle) {
        value = v;
        recompute();
      } else {
        ctx.notify(std::string(label) + ": an angle in radians within ±1000");
      }
    }
    web::record_control(control);
    ImGui::SameLine();
    ImGui::Text("rad = %.2f°", degrees(value));
  }

  void s1_panel(LabContext& ctx) {
    angle_field(ctx, "q₁", "##q1", "distances-q1", q1_);
    angle_field(ctx, "q₂", "##q2", "distances-q2", q2_);
    const S1DistanceReport& a = s1_;
    const auto outside = [](double q) { return q < 0.0 || q >= kTwoPi; };
    if (outside(a.q1) || outside(a.q2))
      text_flow(
          ui::format("outside [0, 2π): the same directions as %s and %s", num(a.wrapped1).c_str(), num(a.wrapped2).c_str()));
    {
      instructor::FixedParam fixed("q2");
      if (ImGui::Button("q₂ = q₁")) set_q2(q1_);
      web::record_control("distances-equal");
      ui::flow(ui::button_width("q₂ = q₁ + π"));
      if (ImGui::Button("q₂ = q₁ + π")) set_q2(wrap_positive(q1_ + kPi));
      web::record_control("distances-antipodal");
    }

    ImGui::Separator();
    if (instructor::hidden("s1_distance")) {
      // P10's answer, and every step that gives it (the case names it too: "opposite" is pi).
      instructor::hidden_line("d(q₁, q₂), the case and the steps (a) and (b)");
      return;
    }
    ImGui::PushFont(fonts().title);
    ImGui::TextColored(theme::vec4(theme::kTextAmount), "d(q₁, q₂) = %s rad", num(a.distance).c_str());
    ImGui::PopFont();
    text_flow(ui::format("= %.2f°: %s", degrees(a.distance), case_line().c_str()));

    if (panel::fold("(a) by the modulus")) {
      text_flow(ui::format("|q₁ − q₂| = |%s − %s| = %s", num(a.q1).c_str(), factor(a.q2).c_str(),
                           num(a.raw_difference).c_str()));
      text_flow(ui::format("%s mod 2π = %s", num(a.raw_difference).c_str(), num(a.modulus).c_str()));
      text_flow(ui::format("d = min(%s, 2π − %s) = min(%s, %s) = %s", num(a.modulus).c_str(), num(a.modulus).c_str(),
                           num(a.modulus).c_str(), num(a.other_way).c_str(), num(a.modular_distance).c_str()));
    }
    if (panel::fold("(b) by rotation matrices")) {
      text_flow("trace(R₁^T R₂)/2 = cos q₁ cos q₂ + sin q₁ sin q₂");
      text_flow(ui::format("= %s·%s + %s·%s = %s", factor(a.cos1).c_str(), factor(a.cos2).c_str(), factor(a.sin1).c_str(),
                           factor(a.sin2).c_str(), num(a.dot).c_str()));
      text_flow(ui::format("d = arccos(%s) = %s", num(a.dot).c_str(), num(a.arccos_distance).c_str()));
    }
    if (panel::fold("this case")) text_flow(case_text());
    // Folded at first (the panel's default fits 1280 x 800): depth for whoever asks.
    if (panel::fold("why the lab computes (b) with atan2", false))
      text_flow(
          ui::format("arccos is steep next to 1 and −1: a rounding of 1e-16 in the dot product moves arccos "
              "near 0 by 1e-8. The lab takes atan2(|sin d|, cos d) with sin d = cos q₁ sin q₂ − sin q₁ cos q₂ "
              "instead, accurate everywhere: %s.",
              ui::format("%.10f", a.rotation_distance).c_str()));
    if (panel::fold("in the lab's PRM", false))
      text_flow(
          "The lab keeps angles in [−π, π) and measures each one's difference by way (a), the short way round: "
          "|wrap(q₂ − q₁)|. For the 2-link arm, whose C-space is T² = S¹ × S¹, it combines the two joints as "
          "d = √(d₁² + d₂²), with d₁ and d₂ the S¹ distances of the joint angles (the flat torus metric, both joints "
          "weighted 1); PRM's nearest neighbours are nearest in it. A straight edge turns each joint by its shorter "
          "turn, so it may leave the square [−π, π)² on one side and come back on the other; for exactly opposite "
          "angles it turns clockwise (a half turn counts as −π).");
  }

  void set_q2(double v) {
    q2_ = v;
    recompute();
  }

  std::string case_line() const {
    switch (s1_.kind) {
      case S1Case::Equal: return "equal directions";
      case S1Case::Antipodal: return "opposite directions, two shortest arcs";
      case S1Case::General: return s1_.wraps_around ? "general, the short way passes 0" : "general";
    }
    return "";
  }

  std::string case_text() const {
    const S1DistanceReport& a = s1_;
    switch (a.kind) {
      case S1Case::Equal:
        return "Equal: q₁ and q₂ are the same direction (they may differ by whole turns, 2πk). d = 0 and there is "
               "no arc: in (a) one of the two ways round is 0, in (b) the dot product is 1 and arccos(1) = 0.";
      case S1Case::Antipodal:
        return "Opposite: d = π, the largest distance two directions can have. Both arcs are π long, so there are "
               "two shortest paths: the dashed halves are equally short. The dot product is −1 and arccos(−1) = π.";
      case S1Case::General:
        if (a.modulus > kPi)
          return "General. " + num(a.modulus) + " is more than π: that arc is the long way round; the short one is " +
                 std::string("2π − ") + num(a.modulus) + " = " + num(a.other_way) +
                 (a.wraps_around ? ", passing the angle 0 (= 2π). Taking |q₁ − q₂| alone would be wrong here." : ".");
        return "General. |q₁ − q₂| mod 2π = " + num(a.modulus) +
               " is at most π, so it is the short arc itself; the other way round is " + num(a.other_way) + ".";
    }
    return "";
  }

  // ------------------------------------------------------------------ P10: the circle

  void s1_view(LabContext& ctx, ImVec2 size) {
    WorkspaceView& v = circle_view_;
    v.begin("##distances-circle", ImVec2(size.x, size.y - hint_height(s1_hint(), size.x)),
            Vec2(-kCircleHalf, -kCircleHalf), Vec2(kCircleHalf, kCircleHalf));
    ctx.views["circle"] = &v;
    v.draw_grid("cos q", "sin q");
    s1_drag(v);
    v.push_clip();
    ImDrawList* dl = v.draw_list();
    const S1DistanceReport& a = s1_;
    const ImVec2 o = v.to_screen(Vec2(0, 0));
    const float radius = v.scale();
    // The axes through the centre, the circle, and where the angle 0 (= 2pi) is.
    dl->AddLine(v.to_screen(Vec2(-1.3, 0)), v.to_screen(Vec2(1.3, 0)), kGuide, 1.0f);
    dl->AddLine(v.to_screen(Vec2(0, -1.3)), v.to_screen(Vec2(0, 1.3)), kGuide, 1.0f);
    dl->AddCircle(o, radius, theme::rgba(150, 150, 150), 128, 2.0f);
    for (int k = 0; k < 4; ++k) {
      const double angle = k * kPi / 2;
      const ImVec2 in = v.to_screen(Vec2(0.95 * std::cos(angle), 0.95 * std::sin(angle)));
      const ImVec2 out = v.to_screen(Vec2(1.05 * std::cos(angle), 1.05 * std::sin(angle)));
      dl->AddLine(in, out, kGuide, 2.0f);
    }
    // The arcs: from q1 by the shorter turn (orange), and the rest of the circle (faint). When
    // they are equally long both are drawn alike, dashed by alternating colours.
    const double turn = a.signed_turn;
    const double other = turn >= 0 ? turn - kTwoPi : turn + kTwoPi;
    const bool hidden = instructor::hidden("s1_distance");  // the arcs say which way is shorter
    if (hidden) {
      // nothing: the handles alone
    } else if (a.kind == S1Case::General) {
      arc(v, a.wrapped1, other, kLongArc, 5.0f);
      arc(v, a.wrapped1, turn, kShortArc, 8.0f);
    } else if (a.kind == S1Case::Antipodal) {
      dashed_arc(v, a.wrapped1, turn);
      dashed_arc(v, a.wrapped1, other);
    }
    // The unit vectors (cos q, sin q): the first columns of R(q1) and R(q2).
    for (int which = 0; which < 2; ++which) {
      const double w = which == 0 ? a.wrapped1 : a.wrapped2;
      const ImU32 colour = which == 0 ? kQ1 : kQ2;
      dl->AddLine(o, v.to_screen(Vec2(std::cos(w), std::sin(w))), theme::with_alpha(colour, 170), 2.0f);
    }
    // The ticks' names over the arcs (on a phone "0 = 2π" reaches the circle), then the arcs'
    // lengths, over the vectors (which may cross them once moved aside).
    for (int k = 0; k < 4; ++k) boxed_text_centred(dl, tick_name_at(v, k), theme::kLabel, kTickNames[k]);
    // The handles, q2 over q1 (equal angles: both show, q2's ring around q1's dot), their labels
    // one above the other when the points coincide. Where they are drawn is known first: the
    // arcs' lengths keep off them (on a phone on its side "d = …" sat on q2's dot).
    const bool same = a.kind == S1Case::Equal;
    const Handle h1{a.wrapped1, kQ1, "q₁", drag_ == Drag::Q1 || hover_ == Drag::Q1, 9.0f, same ? -11.0f : 0.0f};
    const Handle h2{a.wrapped2, kQ2, "q₂", drag_ == Drag::Q2 || hover_ == Drag::Q2, same ? 14.0f : 9.0f, same ? 11.0f : 0.0f};
    std::vector<Box> dots{dot_box(v, h1), dot_box(v, h2)};
    std::vector<Box> names{handle_label_box(v, h1), handle_label_box(v, h2)};
    for (int k = 0; k < 4; ++k) names.push_back(tick_box(v, k));
    arc_boxes_.clear();
    const auto label = [&](double angle, const std::string& text, ImU32 colour) {
      arc_boxes_.push_back(arc_label(v, angle, text, colour, dots, names));
      dots.push_back(arc_boxes_.back());  // the second keeps off the first
    };
    if (!hidden && a.kind == S1Case::General) {
      label(a.wrapped1 + 0.5 * turn, "d = " + num(a.distance), theme::kTextAmount);
      label(a.wrapped1 + 0.5 * other, "2π − d = " + num(kTwoPi - a.distance), theme::kTextKey);
    } else if (!hidden && a.kind == S1Case::Antipodal) {
      label(a.wrapped1 + 0.5 * turn, "π", theme::kTextAmount);
      label(a.wrapped1 + 0.5 * other, "π", theme::kTextAmount);
    }
    handle(v, h1);
    handle(v, h2);
    handle_boxes_ = {dots[0], dots[1], names[0], names[1]};
    v.pop_clip();
    // The case, over the view's top left corner.
    caption(v, hidden ? std::string("d(q₁, q₂): ") + instructor::kHidden : "d(q₁, q₂) = " + num(a.distance) + " rad: " + case_line());
    hint(s1_hint());
  }

  // The result over the view's top left corner, broken at spaces into lines as wide as the view
  // (on a phone upright one line was cut at its right edge: "…the short way passes 0").
  void caption(const WorkspaceView& v, const std::string& title) {
    ImDrawList* dl = v.draw_list();
    const float left = v.canvas_min().x + 8, room = v.canvas_max().x - left - 7;  // boxed_text's margins
    std::string text = title;
    for (std::size_t begin = 0; ImGui::CalcTextSize(text.c_str() + begin).x > room;) {
      std::size_t cut = std::string::npos;
      for (std::size_t i = text.find(' ', begin); i != std::string::npos; i = text.find(' ', i + 1)) {
        if (i > begin && ImGui::CalcTextSize(text.c_str() + begin, text.c_str() + i).x > room) break;
        cut = i;
      }
      if (cut == std::string::npos || cut == begin) break;  // a word wider than the view
      text[cut] = '\n';
      while (cut + 1 < text.size() && text[cut + 1] == ' ') text.erase(cut + 1, 1);
      begin = cut + 1;
    }
    dl->PushClipRect(v.canvas_min(), v.canvas_max(), true);
    boxed_text(dl, ImVec2(left, v.canvas_min().y + 6), theme::kLabel, text);
    dl->PopClipRect();
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    caption_box_ = {left - 3, v.canvas_min().y + 5, left + size.x + 3, v.canvas_min().y + 7 + size.y, v.canvas_max().x};
  }

  // How to use a view, in small print under it: the height it takes at this width, then the text.
  static float hint_height(const char* text, float width) {
    ImGui::PushFont(fonts().small);
    const float height = ImGui::CalcTextSize(text, nullptr, false, width).y + ImGui::GetStyle().ItemSpacing.y;
    ImGui::PopFont();
    return height;
  }
  static void hint(const char* text) {
    ImGui::PushFont(fonts().small);
    ImGui::PushStyleColor(ImGuiCol_Text, theme::kLabel);
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
    ImGui::PopFont();
  }

  // An arc of the unit circle from angle `from` turning by `turn` (radians, either sign).
  static void arc(const WorkspaceView& v, double from, double turn, ImU32 colour, float thickness) {
    if (std::fabs(turn) < 1e-6) return;
    const int segments = std::max(4, static_cast<int>(std::fabs(turn) / kTwoPi * 180.0));
    // Screen angles turn the other way (y points down).
    v.draw_list()->PathArcTo(v.to_screen(Vec2(0, 0)), v.scale(), static_cast<float>(-from),
                             static_cast<float>(-(from + turn)), segments);
    v.draw_list()->PathStroke(colour, 0, thickness);
  }

  // Two equally short halves: drawn in short pieces, orange and sky blue in turn.
  static void dashed_arc(const WorkspaceView& v, double from, double turn) {
    constexpr int kPieces = 24;
    for (int i = 0; i < kPieces; ++i)
      arc(v, from + turn * i / kPieces, turn / kPieces, i % 2 == 0 ? kShortArc : theme::kSkyBlue, 6.0f);
  }

  // Where the name of the circle's tick k (at angle k π/2) is centred.
  static ImVec2 tick_name_at(const WorkspaceView& v, int k) {
    const double angle = k * kPi / 2;
    return v.to_screen(Vec2(1.17 * std::cos(angle), 1.12 * std::sin(angle)));
  }

  // A label's box on the screen (left, top, right, bottom) as boxed_text draws it, centred at
  // `c` and kept within the clip rectangle.
  struct Box {
    float x0, y0, x1, y1;
    bool meets(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  };
  static Box text_box(ImDrawList* dl, ImVec2 c, const std::string& text) {
    return text_box(dl, c, ImGui::CalcTextSize(text.c_str()));
  }
  // With the text's size measured once (arc_label tries up to 961 places in each font).
  static Box text_box(ImDrawList* dl, ImVec2 c, ImVec2 size) {
    const ImVec2 lo = dl->GetClipRectMin(), hi = dl->GetClipRectMax();
    const float x = std::max(lo.x + 4.0f, std::min(c.x - 0.5f * size.x, hi.x - size.x - 4.0f));
    const float y = std::max(lo.y + 2.0f, std::min(c.y - 0.5f * size.y, hi.y - size.y - 2.0f));
    return {x - 3, y - 1, x + size.x + 3, y + size.y + 1};
  }

  struct Handle {
    double angle;
    ImU32 colour;
    const char* name;
    bool hot;
    float size, label_dy;
    std::string label() const { return std::string(name) + " = " + num(angle); }
  };
  static ImVec2 on_circle(const WorkspaceView& v, double angle, double r = 1.0) {
    return v.to_screen(Vec2(r * std::cos(angle), r * std::sin(angle)));
  }
  static Box dot_box(const WorkspaceView& v, const Handle& h) {
    const ImVec2 c = on_circle(v, h.angle);
    // The dot, its edge and the ring it has when hot, hot or not: the arcs' labels, placed clear
    // of it, would jump as the pointer passed over the handle.
    const float e = h.size + 7.0f;
    return {c.x - e, c.y - e, c.x + e, c.y + e};
  }
  static ImVec2 handle_label_at(const WorkspaceView& v, const Handle& h) {
    const ImVec2 at = on_circle(v, h.angle, 1.3);
    return ImVec2(at.x, at.y + h.label_dy);
  }
  static Box handle_label_box(const WorkspaceView& v, const Handle& h) {
    return text_box(v.draw_list(), handle_label_at(v, h), h.label());
  }
  // Tick k's name where it is drawn (a narrow view moves "0 = 2π" in) and the tick itself (0.95
  // to 1.05 of the radius), as one rectangle.
  static Box tick_box(const WorkspaceView& v, int k) {
    const Box name = text_box(v.draw_list(), tick_name_at(v, k), kTickNames[k]);
    const ImVec2 tick = on_circle(v, k * kPi / 2);
    const float t = 0.06f * v.scale();
    return {std::min(name.x0, tick.x - t), std::min(name.y0, tick.y - t), std::max(name.x1, tick.x + t),
            std::max(name.y1, tick.y + t)};
  }

  // An arc's label at 0.58 of the radius towards the arc's middle (`angle`), or the nearest
  // place to it (2 px steps, the label's own side of that line first) where it keeps off the
  // handles' dots (`dots`, which the other arc's label joins) and every name (`names`: the
  // handles' and the ticks'). On a phone the circle is about as wide as "2π − d = 5.3000": the
  // label sat on the name "π" or "0 = 2π", and on its side on q₂'s dot. A desktop's circle
  // leaves the labels where they were.
  static Box arc_label(const WorkspaceView& v, double angle, const std::string& text, ImU32 colour,
                       const std::vector<Box>& dots, const std::vector<Box>& names) {
    ImDrawList* dl = v.draw_list();
    const float ux = static_cast<float>(std::cos(angle)), uy = static_cast<float>(-std::sin(angle));  // y down
    const ImVec2 o = v.to_screen(Vec2(0, 0));
    const float r = 0.58f * v.scale();
    const ImVec2 base(o.x + r * ux, o.y + r * uy);
    const auto clear = [&](const Box& b, bool of_names) {
      // 2 px between boxes
      const Box g{b.x0 - 1, b.y0 - 1, b.x1 + 1, b.y1 + 1};
      for (const Box& d : dots)
        if (g.meets(d)) return false;
      if (of_names)
        for (const Box& n : names)
          if (g.meets(n)) return false;
      return true;
    };
    constexpr int kDirections = 16;
    // Clear of everything in the lesson's font, else in the small one (a phone on its side has a
    // circle 120 px across), else clear of the dots.
    for (const int tier : {0, 1, 2}) {
      if (tier > 0) ImGui::PushFont(fonts().small);
      const ImVec2 size = ImGui::CalcTextSize(text.c_str());
      for (int step = 0; step <= 60; ++step) {
        const float reach = 2.0f * static_cast<float>(step);
        for (int i = 0; i < (step == 0 ? 1 : kDirections); ++i) {
          // From the label's own side of the line to the centre (-uy, ux), both ways round.
          const float turn = static_cast<float>(kPi * ((i + 1) / 2) * (i % 2 ? 1 : -1) / (kDirections / 2));
          const float dx = -uy * std::cos(turn) - ux * std::sin(turn), dy = ux * std::cos(turn) - uy * std::sin(turn);
          const ImVec2 at(base.x + reach * dx, base.y + reach * dy);
          const Box b = text_box(dl, at, size);
          if (clear(b, tier < 2)) {
            boxed_text_centred(dl, at, colour, text);
            if (tier > 0) ImGui::PopFont();
            return b;
          }
        }
      }
      if (tier > 0) ImGui::PopFont();
    }
    boxed_text_centred(dl, base, colour, text);
    return text_box(dl, base, text);
  }

  static void handle(const WorkspaceView& v, const Handle& h) {
    ImDrawList* dl = v.draw_list();
    const ImVec2 c = on_circle(v, h.angle);
    if (h.hot) dl->AddCircle(c, h.size + 5.0f, theme::with_alpha(h.colour, 140), 32, 3.0f);
    if (h.size > 10.0f) {
      dl->AddCircle(c, h.size, h.colour, 32, 4.0f);
    } else {
      dl->AddCircleFilled(c, h.size, h.colour, 24);
      dl->AddCircle(c, h.size, theme::kCanvasBg, 24, 2.0f);
    }
    boxed_text_centred(dl, handle_label_at(v, h), h.colour, h.label());
  }

  // Press on a handle and drag it round the circle: it turns by the mouse's turn about the
  // centre, snapping onto the other handle and onto its opposite point within a few pixels.
  void s1_drag(WorkspaceView& v) {
    const Vec2 m = v.mouse_world();
    const double grab = v.reach(14.0f);
    const auto near = [&](double w) { return (Vec2(std::cos(w), std::sin(w)) - m).norm() <= grab; };
    hover_ = Drag::None;
    if (drag_ == Drag::None && v.hovered()) {
      if (near(s1_.wrapped2)) hover_ = Drag::Q2;  // drawn on top
      else if (near(s1_.wrapped1)) hover_ = Drag::Q1;
    }
    if (hover_ != Drag::None || drag_ != Drag::None) ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
    if (drag_ == Drag::None && hover_ != Drag::None && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !fixed(hover_)) {
      drag_ = hover_;
      drag_from_ = drag_ == Drag::Q1 ? s1_.wrapped1 : s1_.wrapped2;
      grab_angle_ = det::atan2(m.y(), m.x());
    }
    if (drag_ != Drag::Q1 && drag_ != Drag::Q2) return;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      drag_ = Drag::None;
      return;
    }
    double w = wrap_positive(drag_from_ + wrap_angle(det::atan2(m.y(), m.x()) - grab_angle_));
    const double other = drag_ == Drag::Q1 ? s1_.wrapped2 : s1_.wrapped1;
    const double snap = v.pixels(5.0f);  // radians on the unit circle
    if (!ImGui::GetIO().KeyShift) {
      if (s1_distance(w, other) <= snap) w = other;
      else if (s1_distance(w, other + kPi) <= snap) w = wrap_positive(other + kPi);
    }
    (drag_ == Drag::Q1 ? q1_ : q2_) = w;
    recompute();
  }

  // ------------------------------------------------------------------ P11: the panel

  // A point's row: two fields. Coordinates beyond the lesson's range are refused with a notice.
  void point_field(LabContext& ctx, const char* label, const char* id, const char* control, Vec2& p) {
    instructor::FixedParam fixed(control + std::string(control).rfind('-') + 1);  // "distances-p1": p1
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(label);
    ImGui::SameLine(28.0f);
    ImGui::SetNextItemWidth(std::min(220.0f, ImGui::GetContentRegionAvail().x));
    double v[2] = {p.x(), p.y()};
    if (ImGui::InputScalarN(id, ImGuiDataType_Double, v, 2, nullptr, nullptr, "%.4f")) {
      if (std::isfinite(v[0]) && std::isfinite(v[1]) && std::fabs(v[0]) <= kMaxCoordinate &&
          std::fabs(v[1]) <= kMaxCoordinate) {
        p = Vec2(v[0], v[1]);
        recompute();
      } else {
        ctx.notify(std::string(label) + ": coordinates within ±1000");
      }
    }
    web::record_control(control);
  }

  void segment_panel(LabContext& ctx) {
    point_field(ctx, "p₁", "##p1", "distances-p1", p1_);
    point_field(ctx, "p₂", "##p2", "distances-p2", p2_);
    point_field(ctx, "q", "##q", "distances-q", q_);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("r");
    ImGui::SameLine(28.0f);
    ImGui::SetNextItemWidth(std::min(106.0f, ImGui::GetContentRegionAvail().x * 0.45f));
    double r = r_;
    {
      instructor::FixedParam fixed("r");
      if (ImGui::InputDouble("##r", &r, 0.0, 0.0, "%.4f")) {
        if (std::isfinite(r) && r >= 0.0 && r <= kMaxCoordinate) {
          r_ = r;
          recompute();
        } else {
          ctx.notify("r: a radius in [0, 1000]");
        }
      }
    }
    web::record_control("distances-r");
    ImGui::SameLine();
    {
      instructor::FixedParam fixed("p2");
      if (ImGui::Button("p₂ = p₁")) {
        p2_ = p1_;
        recompute();
      }
    }
    web::record_control("distances-degenerate");

    if (instructor::hidden("segment_distance")) {
      // P11's answer, and every step that gives it (t*, c, |q - c|, the case).
      instructor::hidden_line("d, and the steps to it (t*, c, |q − c|, the case)");
      return;
    }
    const SegmentDiskReport& s = segment_;
    if (panel::fold("project q onto the line p₁p₂")) {
      if (s.where == SegmentDiskCase::Degenerate) {
        text_flow(
            ui::format("p₂ − p₁ = (0, 0): there is no line. t* = 0/0 is undefined, and every point of the "
                "\"segment\" is p₁: c = p₁ = %s",
                point(s.closest).c_str()));
      } else {
        text_flow(ui::format("p₂ − p₁ = %s, |p₂ − p₁|² = %s", point(s.direction).c_str(), num(s.length_squared).c_str()));
        text_flow(ui::format("(q − p₁)·(p₂ − p₁) = %s", num(s.dot).c_str()));
        text_flow(ui::format("t* = %s / %s = %s", num(s.dot).c_str(), num(s.length_squared).c_str(), num(s.t_raw).c_str()));
        text_flow(ui::format("t = clamp(t*, 0, 1) = %s", num(s.t).c_str()));
        text_flow(ui::format("c = p₁ + t (p₂ − p₁) = %s", point(s.closest).c_str()));
      }
    }
    text_flow(ui::format("|q − c| = %s", num(s.centre_distance).c_str()));

    ImGui::Separator();
    ImGui::PushFont(fonts().title);
    ImGui::TextColored(theme::vec4(theme::kTextAmount), "d = %s", num(s.distance).c_str());
    ImGui::PopFont();
    text_flow(ui::format("= max(0, |q − c| − r) = max(0, %s − %s)", num(s.centre_distance).c_str(), num(s.r).c_str()));
    text_flow(segment_case_text());
    if (s.meets) ImGui::TextColored(theme::vec4(theme::kTextBad), "|q − c| ≤ r: they meet, so d = 0.");

    if (!panel::fold("the lab's clearance η keeps the sign", false)) return;
    text_flow(ui::format("η = |q − c| − r = %s", num(s.lab_clearance).c_str()));
    text_flow(
        "The collision checker computes this signed value for each arm link against each disk "
        "(segment_disk_signed_distance): positive is the gap, 0 touching, negative how far the disk "
        "reaches past the link. Its sign is the verdict (free exactly when η > 0: touching is a "
        "collision), its size how far the robot may move and stay clear (bisection's test "
        "λ < η(p) + η(q)). max(0, ·) would make every overlap look like a touch and lose the depth.");
  }

  std::string segment_case_text() const {
    switch (segment_.where) {
      case SegmentDiskCase::Interior:
        return "Case: 0 < t* < 1, the foot of the perpendicular from q lies on the segment; c is that foot, and "
               "q − c is perpendicular to p₁p₂.";
      case SegmentDiskCase::AtP1:
        return "Case: t* ≤ 0, q projects before p₁ on the line; t is clamped to 0 and the nearest point is p₁.";
      case SegmentDiskCase::AtP2:
        return "Case: t* ≥ 1, q projects beyond p₂; t is clamped to 1 and the nearest point is p₂.";
      case SegmentDiskCase::Degenerate:
        return "Case: p₁ = p₂, a segment of one point: the distance is that of p₁ to the disk.";
    }
    return "";
  }

  // ------------------------------------------------------------------ P11: the workspace

  // The unit square, grown to hold the segment and the disk (kept while dragging, so that the
  // picture does not move under the mouse).
  void fit_bounds() {
    if (drag_ != Drag::None) return;
    Vec2 lo(0, 0), hi(1, 1);
    for (const Vec2& p : {p1_, p2_, Vec2(q_.x() - r_, q_.y() - r_), Vec2(q_.x() + r_, q_.y() + r_)}) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const Vec2 margin = 0.05 * (hi - lo);
    if (lo != Vec2(0, 0) || hi != Vec2(1, 1)) {
      lo -= margin;
      hi += margin;
    }
    bounds_lo_ = lo;
    bounds_hi_ = hi;
  }

  void segment_view(LabContext& ctx, ImVec2 size) {
    fit_bounds();
    WorkspaceView& v = view_;
    v.begin("##distances-workspace", ImVec2(size.x, size.y - hint_height(kSegmentHint, size.x)), bounds_lo_,
            bounds_hi_);
    ctx.views["workspace"] = &v;
    v.draw_grid("x", "y");
    segment_drag(v);
    v.push_clip();
    ImDrawList* dl = v.draw_list();
    const SegmentDiskReport& s = segment_;
    if (instructor::hidden("segment_distance")) {
      // The given numbers only: the segment, the disk and the handles; no c, no d, no meeting.
      v.draw_disk(s.q, s.r, theme::with_alpha(theme::kObstacleFill, 110), theme::kObstacleEdge, 1.5f);
      if (hover_ == Drag::Rim || drag_ == Drag::Rim) v.draw_circle(s.q, s.r, theme::kSelectedEdge, 3.0f);
      v.draw_segment(s.p1, s.p2, kSegment, 4.0f);
      marker(v, s.p1, kQ1, "p₁", Drag::P1);
      marker(v, s.p2, theme::kGreen, "p₂", Drag::P2);
      marker(v, s.q, theme::rgba(70, 70, 80), "q", Drag::Centre);
      v.pop_clip();
      caption(v, std::string("d: ") + instructor::kHidden);
      hint(kSegmentHint);
      return;
    }
    // The disk: an obstacle, red-edged when the segment meets it.
    v.draw_disk(s.q, s.r, theme::with_alpha(theme::kObstacleFill, 110), s.meets ? kMeetColour : theme::kObstacleEdge,
                s.meets ? 3.0f : 1.5f);
    if (hover_ == Drag::Rim || drag_ == Drag::Rim) v.draw_circle(s.q, s.r, theme::kSelectedEdge, 3.0f);
    // The line through p1 and p2 beyond the segment, to the unclamped foot.
    const bool foot_shown = s.where != SegmentDiskCase::Degenerate && std::isfinite(s.foot.x()) &&
                            std::isfinite(s.foot.y()) && (s.foot - s.closest).norm() > v.pixels(1.0f);
    if (foot_shown) {
      dashed(dl, v.to_screen(s.closest), v.to_screen(s.foot), kGuide, 1.5f);
      dashed(dl, v.to_screen(s.q), v.to_screen(s.foot), kGuide, 1.5f);
      dl->AddCircle(v.to_screen(s.foot), 5.0f, kGuide, 16, 2.0f);
    }
    v.draw_segment(s.p1, s.p2, kSegment, 4.0f);
    // q to c: the part outside the disk is the distance (orange); inside, the overlap (red).
    const Vec2 qc = s.closest - s.q;
    const double length = qc.norm();
    if (length > 0.0) {
      const Vec2 rim = s.q + qc * (std::min(s.r, length) / length);
      v.draw_segment(s.q, rim, s.meets ? kMeetColour : kGuide, 2.0f);
      if (!s.meets) v.draw_segment(rim, s.closest, kShortArc, 5.0f);
    }
    if (s.where == SegmentDiskCase::Interior && length > v.pixels(12.0f)) right_angle(v, s);
    // c, labelled with t.
    dl->AddCircleFilled(v.to_screen(s.closest), 6.0f, kClosest, 16);
    dl->AddCircle(v.to_screen(s.closest), 6.0f, theme::kCanvasBg, 16, 1.5f);
    // The handles.
    marker(v, s.p1, kQ1, "p₁", Drag::P1);
    marker(v, s.p2, theme::kGreen, "p₂", Drag::P2);
    marker(v, s.q, theme::kLabel, "q", Drag::Centre);
    // Labels last, over everything, each pushed away from what it would cover: c's beyond c from
    // q, t*'s beyond the foot from c, d's across the line q - c on the side away from the foot.
    const ImVec2 cs = v.to_screen(s.closest), qs = v.to_screen(s.q), fs = v.to_screen(s.foot);
    boxed_text_beside(dl, cs, unit_between(qs, cs, ImVec2(0, -1)), 12.0f, kClosest, "c (t = " + num(s.t) + ")");
    if (foot_shown)
      boxed_text_beside(dl, fs, unit_between(cs, fs, ImVec2(1, 0)), 10.0f, theme::kLabel, "t* = " + num(s.t_raw));
    if (!s.meets && length > 0.0) {
      const Vec2 rim = s.q + qc * (s.r / length);
      const ImVec2 mid = v.to_screen(0.5 * (rim + s.closest));
      const ImVec2 along = unit_between(qs, cs, ImVec2(0, -1));
      ImVec2 across(-along.y, along.x);
      const bool towards_foot = foot_shown && (fs.x - mid.x) * across.x + (fs.y - mid.y) * across.y > 0.0f;
      if (towards_foot || (!foot_shown && across.x < 0.0f)) across = ImVec2(-across.x, -across.y);
      boxed_text_beside(dl, mid, across, 8.0f, theme::kTextAmount, "d = " + num(s.distance));
    } else if (s.meets) {
      boxed_text(dl, ImVec2(qs.x + 12, qs.y + 10), kMeetColour, "meets: d = 0, η = " + num(s.lab_clearance));
    }
    v.pop_clip();
    caption(v, "d = " + num(s.distance) + "   η = " + num(s.lab_clearance) +
                   "   case: " + segment_disk_case_name(s.where) + (s.meets ? ", meets the disk" : ""));
    hint(kSegmentHint);
  }

  void marker(const WorkspaceView& v, const Vec2& p, ImU32 colour, const char* label, Drag which) const {
    if (hover_ == which || drag_ == which)
      v.draw_list()->AddCircle(v.to_screen(p), 15.0f, theme::with_alpha(colour, 150), 32, 3.0f);
    v.draw_marker(p, colour, label);
  }

  // The square corner at c between the segment and q - c.
  static void right_angle(const WorkspaceView& v, const SegmentDiskReport& s) {
    const ImVec2 c = v.to_screen(s.closest), a = v.to_screen(s.p2), q = v.to_screen(s.q);
    const auto unit = [](ImVec2 from, ImVec2 to) {
      const float l = std::hypot(to.x - from.x, to.y - from.y);
      return l > 0 ? ImVec2((to.x - from.x) / l, (to.y - from.y) / l) : ImVec2(0, 0);
    };
    ImVec2 u = unit(c, a);
    if (u.x == 0 && u.y == 0) u = unit(c, v.to_screen(s.p1));
    const ImVec2 w = unit(c, q);
    const float k = 14.0f;
    const ImVec2 p1(c.x + k * u.x, c.y + k * u.y), p2(c.x + k * (u.x + w.x), c.y + k * (u.y + w.y)),
        p3(c.x + k * w.x, c.y + k * w.y);
    v.draw_list()->AddLine(p1, p2, kGuide, 1.5f);
    v.draw_list()->AddLine(p2, p3, kGuide, 1.5f);
  }

  // Press on p1, p2 or q (or the disk's rim) and drag: it moves by the mouse's offset from the
  // press, so a press a little off the handle does not make it jump.
  void segment_drag(WorkspaceView& v) {
    const Vec2 m = v.mouse_world();
    const double grab = v.reach(14.0f);
    hover_ = Drag::None;
    if (drag_ == Drag::None && v.hovered()) {
      if ((m - p2_).norm() <= grab) hover_ = Drag::P2;  // drawn last, on top
      else if ((m - p1_).norm() <= grab) hover_ = Drag::P1;
      else if ((m - q_).norm() <= grab) hover_ = Drag::Centre;
      else if (std::fabs((m - q_).norm() - r_) <= v.reach(7.0f)) hover_ = Drag::Rim;
    }
    if (hover_ != Drag::None || drag_ != Drag::None) ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
    if (drag_ == Drag::None && hover_ != Drag::None && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !fixed(hover_)) {
      drag_ = hover_;
      grab_point_ = m;
      drag_start_ = drag_ == Drag::P1 ? p1_ : drag_ == Drag::P2 ? p2_ : q_;
    }
    if (drag_ == Drag::None || drag_ == Drag::Q1 || drag_ == Drag::Q2) return;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      drag_ = Drag::None;
      return;
    }
    const auto clamp = [](const Vec2& p) {
      return Vec2(std::clamp(p.x(), -kMaxCoordinate, kMaxCoordinate),
                  std::clamp(p.y(), -kMaxCoordinate, kMaxCoordinate));
    };
    const Vec2 moved = clamp(drag_start_ + (m - grab_point_));
    switch (drag_) {
      case Drag::P1: p1_ = moved; break;
      case Drag::P2: p2_ = moved; break;
      case Drag::Centre: q_ = moved; break;
      case Drag::Rim: r_ = std::min((m - q_).norm(), kMaxCoordinate); break;
      default: break;
    }
    recompute();
  }

  bool segment_tool_ = false;
  double q1_ = 0.5, q2_ = 5.8;  // the short way between them crosses 0
  Vec2 p1_{0.2, 0.3}, p2_{0.8, 0.6}, q_{0.55, 0.2};
  double r_ = 0.1;
  // The last caption drawn: its box (left, top, right, bottom) and its view's right edge.
  std::array<float, 5> caption_box_{};
  // The last circle drawn: its arcs' labels, and its handles' dots then names (state's layout).
  std::vector<Box> arc_boxes_, handle_boxes_;
  S1DistanceReport s1_;
  SegmentDiskReport segment_;
  WorkspaceView circle_view_, view_;
  Vec2 bounds_lo_{0, 0}, bounds_hi_{1, 1};
  Drag drag_ = Drag::None, hover_ = Drag::None;
  std::string refused_;  // why a press on a handle did nothing (the notice, next frame)
  double drag_from_ = 0.0, grab_angle_ = 0.0;  // P10: the handle's angle and the mouse's at the press
  Vec2 grab_point_{0, 0}, drag_start_{0, 0};   // P11: the mouse and the handle at the press
};

}  // namespace

CSL_REGISTER_LESSON(DistancesLesson, "distances", "Distances", "Planning");

}  // namespace csl::app
