#pragma once
// Small widgets the panels share.
#include "imgui.h"

namespace csl::app::ui {

/// Width of a button (or a small button) with this label.
inline float button_width(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
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

}  // namespace csl::app::ui
