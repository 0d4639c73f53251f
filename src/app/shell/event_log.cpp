#include "app/shell/event_log.hpp"

#include "app/shell/theme.hpp"

#include "imgui.h"

namespace csl::app {

void EventLog::add(long step, std::string text) {
  lines_.emplace_back(step, std::move(text));
  while (lines_.size() > kKeep) lines_.pop_front();
}

void EventLog::draw(const char* id, float height) const {
  ImGui::BeginChild(id, ImVec2(0, height), true);
  if (!note_.empty()) {  // secondary: the lines below are the news; wrapped, it may be long
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", note_.c_str());
    ImGui::PopTextWrapPos();
  }
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    const auto& [step, text] = lines_[i];
    const bool newest = i + 1 == lines_.size();
    if (step > 0) {
      ImGui::TextDisabled("%6ld", step);
      ImGui::SameLine();
    }
    if (newest)
      ImGui::TextColored(theme::vec4(theme::kTextLog), "%s", text.c_str());
    else
      ImGui::TextUnformatted(text.c_str());
  }
  if (!lines_.empty() || !note_.empty()) ImGui::SetScrollHereY(1.0f);
  ImGui::EndChild();
}

}  // namespace csl::app
