#include <algorithm>
#include <string>

#include "app/shell/app.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/fonts.hpp"
#include "app/shell/input_mode.hpp"
#include "app/shell/instructor.hpp"
#include "app/shell/panel.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "app/views/scene_editor.hpp"

// The lab's two layouts. The wide one (a laptop, a tablet, a course page's embed of some size):
// the lesson bar, the side panel, the views and the log beside each other. The compact one,
// for a phone held either way or a small embed, where a 280 px panel would leave the views a few
// pixels: a lesson menu, two tabs (View, Controls) that each take the whole width, a strip of
// the playback buttons over the views, and a log folded to its newest line.
namespace csl::app {

using json = nlohmann::json;

namespace {
// The compact layout below this width (logical = CSS px), or when short and not wide (a phone
// on its side). An embed without the lesson menu (ui=minimal) has one row of bar over its
// views, and keeps the wide layout down to kCompactMinimalWidth: its side panel and views
// side by side serve a 600 x 380 course-page embed better than tabs.
constexpr float kCompactWidth = 700.0f;
constexpr float kCompactHeight = 480.0f;
constexpr float kCompactHeightWidth = 900.0f;
constexpr float kCompactMinimalWidth = 520.0f;
// At least this wide, the compact layout's playback strip and tools follow the tabs on their
// row, each as wide as its label, wrapping where they no longer fit; narrower, each group has a
// row of its own, its buttons sharing the width.
constexpr float kCompactRowWidth = 460.0f;

// Narrower than this, the compact bar leaves the lab's name out.
constexpr float kTitledWidth = 480.0f;
// By touch, the wide layout's top bar (the lesson buttons, Homework, Share, Embed, File) is 44
// px high, as the compact one is, on a screen at least this tall (a tablet either way): its
// two or three rows then take about 40 px more. Shorter (a large phone on its side, 932 x 430,
// keeps the wide layout), the views need that height more.
constexpr float kTallBarMinHeight = 600.0f;

bool wants_compact(ImVec2 size) {
  if (web::page().minimal) return size.x < kCompactMinimalWidth;
  return size.x < kCompactWidth || (size.y < kCompactHeight && size.x < kCompactHeightWidth);
}

// A row of buttons a finger can hit: 44 px high (WCAG's target size) under a finger, else the
// usual frame height with room.
float bar_height() { return input::touch() ? 44.0f : ImGui::GetFrameHeight() + 8.0f; }

json rect_json(const std::string& name, ImVec2 min, ImVec2 max) {
  return {{"name", name}, {"x", min.x}, {"y", min.y}, {"w", max.x - min.x}, {"h", max.y - min.y}};
}
}  // namespace

void App::frame() {
  theme::apply_requested_look();  // a Display choice or the page's preference, from this frame on
  web::begin_controls();
  // A finger gets more room around every widget, and a scroll bar it can hold.
  ImGuiStyle& style = ImGui::GetStyle();
  style.TouchExtraPadding = input::touch() ? ImVec2(4, 4) : ImVec2(0, 0);
  style.ScrollbarSize = input::touch() ? 18.0f : 12.0f;
  shortcuts();
  work();
  finish_notes();  // a restore's replay that ended: its log's note says where it stands
  // Parameters the instructor fixed stay as they are, whatever the student's input reached.
  const Lesson* drawn = lesson_;
  const json params_before = instructor::restrictions().any_lock() ? lesson_->params() : json();
  lesson_->update(ctx_);
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(vp->WorkPos);
  ImGui::SetNextWindowSize(vp->WorkSize);
  ImGui::Begin("C-Space Lab", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoBringToFrontOnFocus |
                   ImGuiWindowFlags_NoSavedSettings);
  ctx_.compact = wants_compact(vp->WorkSize);
  ctx_.tall_bar = input::touch() && (ctx_.compact || vp->WorkSize.y >= kTallBarMinHeight);
  // What this frame draws, for status().layout and the view API (a hidden tab draws none).
  ctx_.views.clear();
  ctx_.plots.clear();
  ctx_.areas.clear();
  if (ctx_.compact)
    compact_frame();
  else
    wide_frame();
  ImGui::End();
  if (lesson_ == drawn && !params_before.is_null()) hold_locked_params(params_before);
  notice();
  layout_ = layout_json();
  name_scenes();  // after this frame's edits (the editor's, a marker dragged, a slider's p)
}

void App::wide_frame() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  top_bar();
  ImGui::Separator();
  const float panel_w = std::clamp(vp->WorkSize.x * 0.3f, 280.0f, 380.0f);
  panel::begin(panel_w);
  assignment_.card();
  homework_.card(lesson_id_);
  instructor_note();
  playback_controls();
  ImGui::PushID(lesson_id_.c_str());  // each lesson's folded sections its own
  lesson_->panel(ctx_);
  ImGui::PopID();
  panel::end();
  ImGui::SameLine();
  ImGui::BeginChild("main", ImVec2(0, 0), false, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  // The event log, for lessons that step through an algorithm or report progress.
  const bool log = shows_controls(*lesson_) || !ctx_.log.lines().empty();
  const float log_h = log ? std::clamp(ImGui::GetContentRegionAvail().y * 0.18f, 70.0f, 150.0f) : 0.0f;
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  lesson_->views(ctx_, ImVec2(avail.x, avail.y - (log ? log_h + ImGui::GetStyle().ItemSpacing.y : 0.0f)));
  if (log) ctx_.log.draw("log", log_h);
  ImGui::EndChild();
}

void App::compact_frame() {
  compact_bar();
  if (tab_ == Tab::Controls) {
    // The side panel as a page of its own, the whole width.
    panel::begin(ImGui::GetContentRegionAvail().x);
    assignment_.card();
    homework_.card(lesson_id_);
    instructor_note();
    playback_controls();
    ImGui::PushID(lesson_id_.c_str());
    lesson_->panel(ctx_);
    ImGui::PopID();
    panel::end();
    return;
  }
  if (shows_controls(*lesson_)) playback_strip();
  if (SceneEditor* editor = lesson_->editor()) editor->tool_buttons(bar_height(), strip_wide());
  const bool log = shows_controls(*lesson_) || !ctx_.log.lines().empty();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float avail_h = ImGui::GetContentRegionAvail().y;
  const float log_h = !log ? 0.0f : bar_height() + (log_open_ ? std::clamp(avail_h * 0.25f, 70.0f, 160.0f) + style.ItemSpacing.y : 0.0f);
  ImGui::BeginChild("main", ImVec2(0, avail_h - log_h - (log ? style.ItemSpacing.y : 0.0f)), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  lesson_->views(ctx_, ImGui::GetContentRegionAvail());
  ImGui::EndChild();
  if (log) compact_log();
}

void App::top_bar() {
  const LessonInfo* current_info = find_lesson(lesson_id_);
  const std::string current_name = current_info ? current_info->name : lesson_id_;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float right = ImGui::GetWindowContentRegionMax().x;  // window-local, like the cursor
  const float actions_w = web::top_bar_actions_width();
  // By touch on a tablet every button of the bar is 44 px high (ctx_.tall_bar), and the title
  // and the categories' labels are centred on them.
  const bool tall = ctx_.tall_bar;
  ImGui::PushFont(fonts().title);
  if (tall) ui::align_to_bar(true);
  ImGui::TextUnformatted(web::page().minimal ? current_name.c_str() : "C-Space Lab");
  ImGui::PopFont();
  ImGui::SameLine(0, 24);
  if (!web::page().minimal) {
    // The way in for students: the handout's problems by number, next to the title.
    homework_.menu_button(tall);
    ImGui::SameLine(0, 18);
  }
  const ImVec2 first_row = ImGui::GetCursorPos();
  if (!web::page().minimal) {
    // One button per lesson, grouped by category, in rows under each other when the window is
    // too narrow: the first row leaves room for the page's actions, so no button is ever
    // pushed off the edge (a restore button appearing must not hide Share or a lesson).
    const float indent = first_row.x;
    bool first = true, on_first_row = true;
    // Places the next `w` pixels wide: after the last item with `gap`, or at a new row.
    auto place = [&](float w, float gap) {
      if (first) {
        // Right after the title; on a narrow window (a phone) already on a row of its own.
        first = false;
        if (first_row.x + w > right - actions_w - 24) {
          on_first_row = false;
          ImGui::NewLine();
          ImGui::SetCursorPosX(indent);
        }
        return;
      }
      const float x = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x + gap;
      const float limit = on_first_row ? right - actions_w - 24 : right;
      if (x + w <= limit) {
        ImGui::SameLine(0, gap);
      } else {
        on_first_row = false;
        ImGui::SetCursorPosX(indent);
      }
    };
    std::string category;
    for (const LessonInfo& l : lessons()) {
      const float button_w = ImGui::CalcTextSize(l.name.c_str()).x + style.FramePadding.x * 2;
      if (l.category != category) {
        category = l.category;
        const std::string label = category + ":";
        // The label keeps its first lesson on the same row.
        place(ImGui::CalcTextSize(label.c_str()).x + style.ItemSpacing.x + button_w, 18);
        ui::align_to_bar(tall);
        ImGui::TextDisabled("%s", label.c_str());
        ImGui::SameLine();
      } else {
        place(button_w, style.ItemSpacing.x);
      }
      const bool current = l.id == lesson_id_;
      if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
      ImGui::BeginDisabled(!instructor::lesson_allowed(l.id));
      if (ui::bar_button(l.name.c_str(), tall)) select_lesson(l.id);
      web::record_control(("lesson:" + l.id).c_str());
      ImGui::EndDisabled();
      if (!instructor::lesson_allowed(l.id) && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", instructor::lesson_refusal().c_str());
      if (current) ImGui::PopStyleColor();
    }
  }
  // The page's actions (Share, Embed, File; or the version without a page), right-aligned on
  // the first row; then the cursor goes back under the lowest row.
  const ImVec2 below = ImGui::GetCursorPos();
  ImGui::SetCursorPos(ImVec2(std::max(first_row.x, right - actions_w), first_row.y));
  web::top_bar_actions(ctx_, current_name);
  ImGui::SetCursorPos(ImVec2(ImGui::GetCursorStartPos().x, std::max(below.y, ImGui::GetCursorPos().y)));
}

void App::compact_bar() {
  const LessonInfo* current_info = find_lesson(lesson_id_);
  const std::string current_name = current_info ? current_info->name : lesson_id_;
  const float right = ImGui::GetWindowContentRegionMax().x;
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float bar_h = bar_height();
  // Row 1: the title and Homework; on a wide screen the lesson menu next; the page's actions at
  // the right (or on a row of their own).
  // (On a phone upright the lab's name gives way: Homework and the page's actions then share
  // the first row, and the lesson menu below names what is on screen.)
  const bool titled = web::page().minimal || ImGui::GetContentRegionAvail().x >= kTitledWidth;
  if (titled) {
    ImGui::PushFont(fonts().title);
    ui::align_to_bar(ctx_.tall_bar);  // centred on the row's buttons, 44 px high by touch
    ImGui::TextUnformatted(web::page().minimal ? current_name.c_str() : "C-Space Lab");
    ImGui::PopFont();
  }
  if (!web::page().minimal) {
    if (titled) ImGui::SameLine(0, 12);
    homework_.menu_button(ctx_.tall_bar);
  }
  const float actions_w = web::top_bar_actions_width();
  const auto after = [&] { return ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x + 12; };
  // Which lesson, as a menu (the wide layout's row of buttons would take the screen).
  const auto lesson_menu = [&](float width) {
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(10, 0.5f * (bar_h - ImGui::GetFontSize())));
    ImGui::SetNextItemWidth(width);
    const std::string preview = "Lesson: " + current_name;
    // Rows as tall as a finger needs, but every lesson within the screen below the menu: a phone
    // on its side (390 px) cannot scroll the list by touch, and nine lessons at full height
    // left the last ones off the screen.
    int rows = 0, headings = 0;
    for (std::size_t i = 0; i < lessons().size(); ++i, ++rows)
      headings += i == 0 || lessons()[i].category != lessons()[i - 1].category;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float room = ImGui::GetIO().DisplaySize.y - ImGui::GetCursorScreenPos().y - bar_h - 2 * style.WindowPadding.y -
                       static_cast<float>(headings) * ImGui::GetTextLineHeightWithSpacing();
    const float row_h = std::clamp(room / static_cast<float>(std::max(rows, 1)) - style.ItemSpacing.y, 24.0f, bar_h - 8);
    if (ImGui::BeginCombo("##lesson", preview.c_str(), ImGuiComboFlags_HeightLargest)) {
      std::string category;
      for (const LessonInfo& l : lessons()) {
        if (l.category != category) {
          category = l.category;
          ImGui::TextDisabled("%s", category.c_str());
        }
        const ImGuiSelectableFlags off = instructor::lesson_allowed(l.id) ? 0 : ImGuiSelectableFlags_Disabled;
        if (ImGui::Selectable(l.name.c_str(), l.id == lesson_id_, off, ImVec2(0, row_h))) {
          select_lesson(l.id);
          tab_ = Tab::View;
        }
        web::record_control(("lesson:" + l.id).c_str());
      }
      ImGui::EndCombo();
    }
    web::record_control("lesson-menu");
    ImGui::PopStyleVar();
  };
  constexpr float kMenuWidth = 240.0f;
  bool menu_done = web::page().minimal;
  if (!menu_done && after() + 12 + kMenuWidth + 12 + actions_w <= right) {
    ImGui::SameLine(0, 12);
    lesson_menu(right - actions_w - 12 - (after() + 12));
    menu_done = true;
  }
  if (after() + actions_w <= right) ImGui::SameLine(std::max(after(), right - actions_w));
  web::top_bar_actions(ctx_, current_name);
  if (!menu_done) lesson_menu(-1);
  // Row 3: the tabs, each half the width (or, on a wide screen, the start of a row that holds
  // the playback strip and the tools too).
  const bool wide = strip_wide();
  const float w = wide ? 84.0f : 0.5f * (ImGui::GetContentRegionAvail().x - spacing);
  // With an assignment open its card heads the Controls tab, and the View tab showed no sign of
  // it: the tab says so, in the longest words that fit.
  const char* controls = "Controls";
  if (assignment_.active())
    for (const char* label : {"Assignment & controls", "Assignment"})
      if (ui::button_width(label) <= w) {
        controls = label;
        break;
      }
  const struct {
    Tab tab;
    const char* label;
    const char* control;
  } tabs[] = {{Tab::View, "View", "tab:view"}, {Tab::Controls, controls, "tab:controls"}};
  for (const auto& t : tabs) {
    if (t.tab == Tab::Controls) ImGui::SameLine();
    const bool on = tab_ == t.tab;
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button(t.label, ImVec2(w, bar_h))) tab_ = t.tab;
    if (on) ImGui::PopStyleColor();
    web::record_control(t.control);
  }
}

void App::playback_strip() {
  Stepper& s = stepping(*lesson_);
  Playback& pb = ctx_.playback;
  const float bar_h = bar_height();
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const bool wide = strip_wide();
  if (s.busy()) {
    pb.playing = false;
    const float cancel_w = ui::button_width("Cancel") + 8;
    if (wide) ui::flow(240.0f + spacing + cancel_w);
    ImGui::ProgressBar(static_cast<float>(s.progress()), ImVec2(wide ? 240.0f : -cancel_w - spacing, bar_h),
                       s.busy_text().c_str());
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(cancel_w, bar_h))) s.cancel_work();
    web::record_control("cancel");
    return;
  }
  // Four buttons: what a student does most while watching. A row of their own sharing the
  // width, or after the tabs, each as wide as its label, while they fit.
  const float share = (ImGui::GetContentRegionAvail().x - 3 * spacing) / 4;
  bool first = true;
  const auto size = [&](const char* label) {
    const float w = wide ? ui::button_width(label) + 12.0f : share;
    if (wide) ui::flow(w);
    else if (!first) ImGui::SameLine();
    first = false;
    return ImVec2(w, bar_h);
  };
  ImGui::BeginDisabled(s.steps() == 0);
  if (ImGui::Button("\xE2\x97\x80 Back", size("\xE2\x97\x80 Back"))) s.step_back();
  web::record_control("back");
  ImGui::EndDisabled();
  ImGui::BeginDisabled(s.finished());
  if (ImGui::Button("Step \xE2\x96\xB6", size("Step \xE2\x96\xB6"))) s.step_forward();
  web::record_control("step");
  if (ImGui::Button("Run all", size("Run all"))) s.run_all();
  web::record_control("run-all");
  ImGui::EndDisabled();
  ImGui::BeginDisabled(s.finished() && !pb.playing);
  const char* play = pb.playing ? "Pause" : "\xE2\x96\xB6 Play";
  if (ImGui::Button(play, size("\xE2\x96\xB6 Play"))) pb.playing = !pb.playing;
  web::record_control("play");
  ImGui::EndDisabled();
}

bool App::strip_wide() const {
  return ImGui::GetWindowContentRegionMax().x - ImGui::GetWindowContentRegionMin().x >= kCompactRowWidth;
}

void App::compact_log() {
  // Folded: one row with the newest line, a press unfolds it (and folds it again).
  const std::string newest = ctx_.log.last();
  const std::string label = std::string(log_open_ ? "\xE2\x96\xBC Log" : "\xE2\x96\xB6 Log") +
                            (newest.empty() ? std::string() : ": " + newest) + "##log-toggle";
  ImGui::PushStyleVar(ImGuiStyleVar_ButtonTextAlign, ImVec2(0.0f, 0.5f));
  if (ImGui::Button(label.c_str(), ImVec2(-1, bar_height()))) log_open_ = !log_open_;
  ImGui::PopStyleVar();
  web::record_control("log-toggle");
  if (log_open_) ctx_.log.draw("log", ImGui::GetContentRegionAvail().y);
}

json App::layout_json() const {
  json views = json::array();
  for (const auto& [name, v] : ctx_.views) views.push_back(rect_json(name, v->canvas_min(), v->canvas_max()));
  for (const auto& [name, p] : ctx_.plots) views.push_back(rect_json(name, p->box_min(), p->box_max()));
  for (const auto& [name, r] : ctx_.areas) views.push_back(rect_json(name, r.first, r.second));
  json out{{"mode", ctx_.compact ? "compact" : "wide"}, {"touch", input::touch()}, {"views", views}};
  // The one-line notice's window, while it shows.
  if (notice_box_.second.x > notice_box_.first.x) out["notice"] = rect_json("notice", notice_box_.first, notice_box_.second);
  if (ctx_.compact) {
    out["tab"] = tab_ == Tab::View ? "view" : "controls";
    out["log_open"] = log_open_;
  }
  return out;
}

}  // namespace csl::app
