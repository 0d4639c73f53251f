#pragma once
// Small widgets the panels share.
#include <cstdarg>
#include <cstdio>
#include <string>

#include "app/shell/input_mode.hpp"
#include "imgui.h"

namespace csl::app::ui {

/// Width of a button (or a small button) with this label.
inline float button_width(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
}
/// ImGui's SmallButton by mouse; by touch a whole button: a small one is 16 px high, under the
/// 24 px that a finger's target needs at least (WCAG 2.5.8), and "Open the tool" was missed.
inline bool small_button(const char* label) { return input::touch() ? ImGui::Button(label) : ImGui::SmallButton(label); }
/// The top bar's buttons (Homework, Share, Embed, File; the wide layout's lesson buttons).
/// `tall` (LabContext::tall_bar): by touch, in the compact layout (a phone's) and the wide one
/// on a tablet, where they are 44 px high as the compact tabs and lesson menu are, the size a
/// finger is sure of (they were 26 px, above WCAG's 24 but often missed beside each other). By
/// mouse they keep ImGui's size; one row of the bar is always one height.
/// The vertical frame padding of the bar's items in the current font: 44 px high when `tall`.
inline float bar_padding_y(bool tall) {
  return tall ? 0.5f * (44.0f - ImGui::GetFontSize()) : ImGui::GetStyle().FramePadding.y;
}
inline bool bar_button(const char* label, bool tall) {
  if (!tall) return ImGui::Button(label);
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, bar_padding_y(true)));
  const bool pressed = ImGui::Button(label);
  ImGui::PopStyleVar();
  return pressed;
}
/// Text that comes next on the bar's row (the title, a category's label) centred on its buttons.
inline void align_to_bar(bool tall) {
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, bar_padding_y(tall)));
  ImGui::AlignTextToFramePadding();
  ImGui::PopStyleVar();
}

/// Width of a radio button or checkbox with this label.
inline float toggle_width(const char* label) {
  return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

/// Before the second and later items of a row: on the same line while the next item (`width`
/// wide) fits in the panel, else on the next line. A narrow panel (an embed, a small window)
/// wraps the row instead of cutting its last items off.
inline void flow(float width) {
  const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

/// A section heading: some space, the title dimmed, a rule.
inline void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

/// printf into a string, of any length (the lessons' formulas with their numbers put in).
inline std::string format(const char* pattern, ...) IM_FMTARGS(1);
inline std::string format(const char* pattern, ...) {
  va_list args, again;
  va_start(args, pattern);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, pattern, args);
  va_end(args);
  std::string out(static_cast<std::size_t>(n > 0 ? n : 0), '\0');
  std::vsnprintf(out.data(), out.size() + 1, pattern, again);
  va_end(again);
  return out;
}

/// Wrapped text that breaks only at spaces: ImGui's own wrapping also breaks after '.', which
/// split numbers ("0." and "9832" on two lines).
inline void text_flow(const std::string& text) {
  // Lines of one paragraph as close as ImGui's wrapped text sets them; the usual gap after it.
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, 0.0f));
  const float space = ImGui::CalcTextSize(" ").x;
  const float right = ImGui::GetContentRegionMax().x;
  bool first = true;
  for (std::size_t i = 0; i <= text.size();) {
    std::size_t j = text.find(' ', i);
    if (j == std::string::npos) j = text.size();
    if (j > i) {
      const std::string word = text.substr(i, j - i);
      const float width = ImGui::CalcTextSize(word.c_str()).x;
      if (!first) {
        ImGui::SameLine(0.0f, space);
        if (ImGui::GetCursorPosX() + width > right) ImGui::NewLine();
      }
      ImGui::TextUnformatted(word.c_str());
      first = false;
    }
    i = j + 1;
  }
  ImGui::PopStyleVar();
  ImGui::Dummy(ImVec2(0.0f, 0.0f));
}

}  // namespace csl::app::ui
