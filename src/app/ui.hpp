#pragma once
// Small widgets the panels share.
#include "imgui.h"

namespace csl::app::ui {

/// A section heading: some space, the title dimmed, a rule.
inline void section(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

}  // namespace csl::app::ui
