#pragma once
// The tinted cards at the top of the side panel (the homework's problem, the assignment) and
// the text in them.
#include <string>

#include "app/shell/input_mode.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "imgui.h"

namespace csl::app::card {

/// Text with line breaks, each line wrapped at spaces only (numbers stay whole).
inline void paragraphs(const std::string& text) {
  std::size_t i = 0;
  while (i <= text.size()) {
    std::size_t j = text.find('\n', i);
    if (j == std::string::npos) j = text.size();
    ui::text_flow(text.substr(i, j - i));
    i = j + 1;
  }
}

/// A tinted box behind what `body` draws, as wide as the panel (ImGui 1.86 has no child window
/// that fits its content's height).
template <class Body>
void boxed(ImU32 colour, Body body) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->ChannelsSplit(2);
  dl->ChannelsSetCurrent(1);
  const float pad = ImGui::GetStyle().FramePadding.x;
  ImGui::Dummy(ImVec2(0, pad * 0.5f));
  ImGui::Indent(pad);
  ImGui::BeginGroup();
  body();
  ImGui::EndGroup();
  ImGui::Unindent(pad);
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  ImGui::Dummy(ImVec2(0, pad * 0.5f));
  dl->ChannelsSetCurrent(0);
  const float left = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMin().x;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  dl->AddRectFilled(ImVec2(left, lo.y - pad), ImVec2(right, hi.y + pad), colour, 4.0f);
  // High contrast: the tint is gone (white or black), an edge marks the card instead.
  if (theme::look().high_contrast) dl->AddRect(ImVec2(left, lo.y - pad), ImVec2(right, hi.y + pad), theme::kInk, 4.0f);
  dl->ChannelsMerge();
}

/// An exercise's answer row, the homework card's and the assignment card's: the format hint, a
/// field and Check beside it (`field_control` and `check_control` for the page's buttons map).
/// The field takes the keyboard when `focus` is set (not by touch), which this clears. True when Check is
/// pressed or Enter typed in the field: the caller checks `buffer` (and sets `focus` again, so
/// that a wrong answer is corrected and Enter pressed again at once).
inline bool answer_row(const char* id, const std::string& hint, char* buffer, std::size_t size, bool& focus,
                       const char* field_control, const char* check_control) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("Answer: %s", hint.c_str());
  ImGui::PopStyleColor();
  const float check_w = ui::button_width("Check");
  ImGui::PushItemWidth(-check_w - ImGui::GetStyle().ItemSpacing.x);
  if (focus) {
    // Not by touch: the field's focus opens a phone's on-screen keyboard over half the screen
    // unasked, and scrolled the card's title away; a finger taps the field when it wants to type.
    if (!input::touch()) ImGui::SetKeyboardFocusHere();
    focus = false;
  }
  const bool enter = ImGui::InputTextWithHint(id, "your answer", buffer, size, ImGuiInputTextFlags_EnterReturnsTrue);
  web::record_control(field_control);
  ImGui::PopItemWidth();
  ImGui::SameLine();
  const bool checked = ImGui::Button("Check") || enter;
  web::record_control(check_control);
  return checked;
}

}  // namespace csl::app::card
