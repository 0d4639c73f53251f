#include "app/shell/panel.hpp"

#include <algorithm>
#include <cmath>

#include "app/shell/input_mode.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/web_bridge.hpp"
#include "imgui.h"
#include "imgui_internal.h"

namespace csl::app::panel {
namespace {

struct Section {
  std::string title;
  bool open;
};

struct Measures {
  float height = 0, content = 0, scroll = 0, scroll_max = 0;
  bool more_below = false, cue = false;
  std::vector<Section> sections;
};

Measures& frame() {
  static Measures m;
  return m;
}
Measures& last() {  // the last whole frame's, for state()
  static Measures m;
  return m;
}

float g_width = 0.0f;
bool g_cue = false;  // the cue row is shown: the content did not fit the whole height last frame

// A finger's swipe scrolls the panel, as it scrolls any page on a phone or tablet: ImGui 1.86
// scrolls by wheel and scrollbar only, so a student's swipe did nothing, or moved the slider it
// began on. A press in the panel is a tap until the finger has gone kSlack px up or down (more
// than sideways, which stays a slider's); from then on the panel follows the finger, and what the
// press began on lets go: a button is not clicked. (A slider has taken the value under the finger
// at the press, as ImGui's sliders do; that is not undone.) A press in a popup over the panel (a
// combo's list, a modal) or on its scrollbar is left to them.
struct Swipe {
  bool armed = false, on = false;
  ImVec2 from{0, 0};
  float scroll = 0;
};
Swipe g_swipe;
constexpr float kSlack = 12.0f;

// Called inside the panel's child window, before it ends.
void follow_finger(ImGuiWindow* child) {
  const ImGuiIO& io = ImGui::GetIO();
  Swipe& s = g_swipe;
  if (!input::touch() || !io.MouseDown[0] || input::pinch().active) {
    s = Swipe{};
    return;
  }
  if (ImGui::IsMouseClicked(0)) {
    s = Swipe{};
    // IsWindowHovered counts a popup opened from the panel as one of its children (ImGui 1.86).
    s.armed = ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows | ImGuiHoveredFlags_AllowWhenBlockedByActiveItem) &&
              !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId) &&
              ImGui::GetActiveID() != ImGui::GetWindowScrollbarID(child, ImGuiAxis_Y);
    s.from = io.MousePos;
    s.scroll = child->Scroll.y;
  }
  if (!s.armed) return;
  const float dx = io.MousePos.x - s.from.x, dy = io.MousePos.y - s.from.y;
  if (!s.on && std::fabs(dy) > kSlack && std::fabs(dy) > std::fabs(dx)) {
    s.on = true;
    ImGui::ClearActiveID();
  }
  if (s.on) ImGui::SetScrollY(child, std::clamp(s.scroll - dy, 0.0f, child->ScrollMax.y));
}

}  // namespace

bool fold(const char* title, bool open) {
  ImGui::Spacing();
  ImGui::SetNextItemOpen(open, ImGuiCond_Once);
  const bool shown = ImGui::CollapsingHeader(title);
  web::record_control(("section:" + std::string(title)).c_str());
  frame().sections.push_back({title, shown});
  return shown;
}

void begin(float width) {
  frame() = Measures{};
  g_width = width;
  ImGui::BeginGroup();
  const float cue_h = g_cue ? ImGui::GetFrameHeightWithSpacing() : 0.0f;
  ImGui::BeginChild("panel", ImVec2(width, -cue_h), false);
}

void end() {
  Measures& m = frame();
  m.height = ImGui::GetWindowHeight();
  m.scroll = ImGui::GetScrollY();
  m.scroll_max = ImGui::GetScrollMaxY();
  m.content = m.height + m.scroll_max;
  const bool at_end = m.scroll >= m.scroll_max - 4.0f;  // within a few pixels of it
  ImGuiWindow* child = ImGui::GetCurrentWindow();
  follow_finger(child);
  ImGui::EndChild();
  const float cue_h = ImGui::GetFrameHeightWithSpacing();
  const float whole = m.height + (g_cue ? cue_h : 0.0f);  // the height with no cue row
  const bool cue = m.content > whole + 0.5f;
  if (cue && g_cue) {
    // Under the panel, full width: where the content goes on, and a click that gets there.
    ImGui::PushStyleColor(ImGuiCol_Button, theme::with_alpha(theme::kBlue, 60));
    const char* label = at_end            ? "\xE2\x96\xB2 back to the top"
                        : input::touch() ? "\xE2\x96\xBC more below: swipe up, or tap here"
                                         : "\xE2\x96\xBC more below: scroll, or click here";
    if (ImGui::Button(label, ImVec2(g_width, 0)))
      ImGui::SetScrollY(child, at_end ? 0.0f : std::min(m.scroll_max, m.scroll + std::max(40.0f, 0.7f * m.height)));
    ImGui::PopStyleColor();
    web::record_control("panel-more");
  }
  ImGui::EndGroup();
  m.cue = cue && g_cue;
  m.more_below = m.scroll_max > 0.5f && !at_end;
  g_cue = cue;
  last() = m;
}

nlohmann::json state() {
  const Measures& m = last();
  nlohmann::json sections = nlohmann::json::array();
  for (const Section& s : m.sections) sections.push_back({{"title", s.title}, {"open", s.open}});
  return {{"height", m.height},          {"content", m.content},
          {"scroll", m.scroll},          {"scroll_max", m.scroll_max},
          {"more_below", m.more_below},    {"cue", m.cue},
          {"sections", sections}};
}

}  // namespace csl::app::panel
