#include "app/views/drag_replay.hpp"

#include <algorithm>

#include "app/shell/theme.hpp"

namespace csl::app {

void draw_replay_pending(const WorkspaceView& view, const std::string& why) {
  ImDrawList* dl = view.draw_list();
  // The clip rectangle is the visible world rectangle: the caller's push_clip().
  const ImVec2 lo = dl->GetClipRectMin(), hi = dl->GetClipRectMax();
  dl->AddRectFilled(lo, hi, theme::with_alpha(theme::kLabelBox, 175));
  const char* text = why.empty() ? "roadmap from before this drag: it is replayed when you release" : why.c_str();
  const float wrap = std::max(60.0f, hi.x - lo.x - 24.0f);
  const ImVec2 size = ImGui::CalcTextSize(text, nullptr, false, wrap);
  const ImVec2 at(lo.x + 10.0f, lo.y + 8.0f);
  dl->AddRectFilled(ImVec2(at.x - 4.0f, at.y - 2.0f), ImVec2(at.x + size.x + 4.0f, at.y + size.y + 2.0f),
                    theme::with_alpha(theme::kLabelBox, 235), 3.0f);
  dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, theme::kWarning, text, nullptr, wrap);
}

}  // namespace csl::app
