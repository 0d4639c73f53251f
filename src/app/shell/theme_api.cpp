#include "app/shell/theme_api.hpp"

#include "app/shell/theme.hpp"
#include "imgui.h"

namespace csl::app::theme {

namespace {

using json = nlohmann::json;

json rgba_of(ImU32 c) { return json::array({c & 0xFF, (c >> 8) & 0xFF, (c >> 16) & 0xFF, (c >> 24) & 0xFF}); }

// An ImGui style colour, composited over an opaque background (a button's tint over the panel).
ImU32 style_over(ImGuiCol which, ImU32 bg) {
  const ImVec4 c = ImGui::GetStyle().Colors[which];
  const ImVec4 b = vec4(bg);
  const auto mix = [&](float f, float g) { return static_cast<unsigned>((f * c.w + g * (1.0f - c.w)) * 255.0f + 0.5f); };
  return rgba(mix(c.x, b.x), mix(c.y, b.y), mix(c.z, b.z));
}
ImU32 style(ImGuiCol which) { return ImGui::ColorConvertFloat4ToU32(ImGui::GetStyle().Colors[which]); }

}  // namespace

void register_api(JsApi& api) {
  api.add("theme", "the colours that carry meaning in the look in use: {look: {dark, high_contrast}, colours: {role: [r,g,b,a]}, components, text: [{name, fg, bg}]}",
          [](const json&) {
            const json colours = {
                {"canvas", rgba_of(kCanvasBg)},       {"obstacle", rgba_of(kObstacleFill)},
                {"obstacle_edge", rgba_of(kObstacleEdge)}, {"start", rgba_of(kStart)},
                {"goal", rgba_of(kGoal)},             {"path", rgba_of(kPath)},
                {"path_outline", rgba_of(kPathOutline)}, {"free", rgba_of(kFree)},
                {"hit", rgba_of(kHit)},               {"warning", rgba_of(kWarning)},
                {"robot", rgba_of(kRobot)},           {"current", rgba_of(kCurrent)},
                {"preview", rgba_of(kPreview)},       {"selected", rgba_of(kSelectedEdge)},
                {"label", rgba_of(kLabel)},           {"grid_major", rgba_of(kGridMajor)},
            };
            json components = json::array();
            for (ImU32 c : kComponents) components.push_back(rgba_of(c));
            const ImU32 panel = style(ImGuiCol_WindowBg);
            const ImU32 popup = style_over(ImGuiCol_PopupBg, panel);
            const ImU32 button = style_over(ImGuiCol_Button, panel);
            const ImU32 hovered = style_over(ImGuiCol_ButtonHovered, panel);
            const ImU32 text = style(ImGuiCol_Text);
            const ImU32 dim = style(ImGuiCol_TextDisabled);
            json pairs = json::array();
            const auto pair = [&](const char* name, ImU32 fg, ImU32 bg) {
              pairs.push_back({{"name", name}, {"fg", rgba_of(fg)}, {"bg", rgba_of(bg)}});
            };
            pair("text on the panel", text, panel);
            pair("secondary text on the panel", dim, panel);
            pair("text in a popup", text, popup);
            pair("secondary text in a popup", dim, popup);
            pair("a button's label", text, button);
            pair("a hovered button's label", text, hovered);
            pair("the restore button's label", text, kRestoreButton);
            pair("a found path, a passed check", kTextGood, panel);
            pair("no path, a missed collision", kTextBad, panel);
            pair("a headline figure", kTextKey, panel);
            pair("a distance being measured", kTextAmount, panel);
            pair("the log's newest line", kTextLog, panel);
            pair("the notice", kTextNotice, panel);
            pair("text on the welcome card", text, kCardWelcome);
            pair("secondary text on the welcome card", dim, kCardWelcome);
            pair("text on the homework card", text, kCardProblem);
            pair("secondary text on the homework card", dim, kCardProblem);
            pair("a found path on the homework card", kTextGood, kCardProblem);
            pair("a wrong answer on the homework card", kTextBad, kCardProblem);
            pair("a label's text in its box on the canvas", kLabel, kLabelBox);
            pair("a measured distance's label on the canvas", kTextAmount, kLabelBox);
            pair("a label on the canvas", kLabel, kCanvasBg);
            pair("the start marker's letter", text_on(kStart), kStart);
            pair("the goal marker's letter", text_on(kGoal), kGoal);
            pair("a blue marker's letter", text_on(kBlue), kBlue);
            const Look l = look();
            return json{{"look", {{"dark", l.dark}, {"high_contrast", l.high_contrast}}},
                        {"colours", colours}, {"components", components}, {"text", pairs}};
          });
}

}  // namespace csl::app::theme
