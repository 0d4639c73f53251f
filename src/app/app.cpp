#include "app/app.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/fonts.hpp"
#include "app/js_api.hpp"
#include "app/theme.hpp"
#include "core/version.hpp"

namespace csl::app {

using json = nlohmann::json;

namespace {
// A drag shorter than this (logical pixels) is a click, not a disk.
constexpr float kMinDragPixels = 3.0f;

json vec_json(ImVec2 v) { return json::array({v.x, v.y}); }
}  // namespace

App::App(const Platform& platform) : platform_(platform) {
  theme::apply_style();
  register_api();
}

void App::register_api() {
  JsApi& api = js_api();
  api.add("status", "frames drawn, version, pixel ratio", [this](const json&) {
    return json{{"frames", platform_.frame_count()},
                {"version", kVersion},
                {"pixel_ratio", platform_.pixel_ratio()},
                {"obstacles", scene_.obstacles.size()}};
  });
  api.add("get_scene", "the current scene (schema version 1)",
          [this](const json&) { return scene_to_json(scene_); });
  api.add("set_scene", "replace the scene: {scene: {...}}; refused with a message if invalid",
          [this](const json& args) {
            if (!args.contains("scene")) throw ApiError("args.scene is missing");
            scene_ = scene_from_json(args["scene"]);  // throws before touching scene_
            return scene_to_json(scene_);
          });
  api.add("view", "the workspace canvas: CSS pixels of world points {points: [[x,y],...]}",
          [this](const json& args) {
            json points = json::array();
            for (const json& p : args.value("points", json::array())) {
              if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
                throw ApiError("points must be [[x, y], ...]");
              points.push_back(vec_json(view_.to_screen(Vec2(p[0].get<double>(), p[1].get<double>()))));
            }
            return json{{"canvas_min", vec_json(view_.canvas_min())},
                        {"canvas_max", vec_json(view_.canvas_max())},
                        {"scale", view_.scale()},
                        {"points", points}};
          });
}

void App::frame() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(vp->WorkPos);
  ImGui::SetNextWindowSize(vp->WorkSize);
  ImGui::Begin("C-Space Lab", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings);
  const float panel_w = std::clamp(vp->WorkSize.x * 0.3f, 240.0f, 340.0f);
  ImGui::BeginChild("panel", ImVec2(panel_w, 0), false);
  draw_panel();
  ImGui::EndChild();
  ImGui::SameLine();
  ImGui::BeginChild("workspace", ImVec2(0, 0), false, ImGuiWindowFlags_NoScrollbar);
  draw_workspace(ImGui::GetContentRegionAvail());
  ImGui::EndChild();
  ImGui::End();
}

void App::draw_panel() {
  ImGui::PushFont(fonts().title);
  ImGui::TextUnformatted("C-Space Lab");
  ImGui::PopFont();
  ImGui::TextDisabled("configuration spaces and roadmaps, v%s", kVersion);
  ImGui::Separator();
  ImGui::TextWrapped("Drag in the workspace to draw a disk obstacle: press at its centre, "
                     "release at its rim.");
  ImGui::Spacing();
  ImGui::Text("Obstacles: %zu", scene_.obstacles.size());
  int remove = -1;
  if (ImGui::BeginTable("obstacles", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH)) {
    ImGui::TableSetupColumn("disk", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("r", ImGuiTableColumnFlags_WidthFixed, 56.0f);
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 24.0f);
    for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) {
      const Obstacle& o = scene_.obstacles[i];
      ImGui::PushID(static_cast<int>(i));
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      const Box b = obstacle_bounds(o);
      const Vec2 c = 0.5 * (b.min + b.max);
      ImGui::Text("%zu %s (%.3f, %.3f)", i + 1, obstacle_type_name(o), c.x(), c.y());
      ImGui::TableNextColumn();
      if (const auto* d = std::get_if<Disk>(&o)) ImGui::Text("r %.3f", d->radius);
      ImGui::TableNextColumn();
      if (ImGui::SmallButton("×")) remove = static_cast<int>(i);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("delete this disk");
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  if (remove >= 0) scene_.obstacles.erase(scene_.obstacles.begin() + remove);
  if (!scene_.obstacles.empty() && ImGui::Button("Clear all")) scene_.obstacles.clear();
  if (!message_.empty()) {
    ImGui::Spacing();
    ImGui::TextWrapped("%s", message_.c_str());
  }
}

void App::handle_disk_drag() {
  if (view_.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) drag_from_ = view_.mouse_world();
  if (!drag_from_) return;
  const Vec2 to = view_.mouse_world();
  const double radius = (to - *drag_from_).norm();
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    view_.draw_disk(*drag_from_, radius, theme::with_alpha(theme::kPreview, 48), theme::kPreview, 2.0f);
    ImGui::SetTooltip("r = %.3f", radius);
    return;
  }
  // Released: a real drag makes a disk, a click does not.
  if (radius * static_cast<double>(view_.scale()) >= static_cast<double>(kMinDragPixels)) {
    scene_.obstacles.push_back(Disk{*drag_from_, radius});
    message_.clear();
  } else {
    message_ = "Drag (do not just click) to give the disk a radius.";
  }
  drag_from_.reset();
}

void App::draw_workspace(ImVec2 size) {
  view_.begin("##workspace", size, scene_.workspace_min, scene_.workspace_max);
  view_.draw_grid();
  ImDrawList* dl = view_.draw_list();
  dl->PushClipRect(view_.canvas_min(), view_.canvas_max(), true);
  for (const Obstacle& o : scene_.obstacles) view_.draw_obstacle(o);
  view_.draw_marker(Vec2(scene_.start[0], scene_.start[1]), theme::kStart, "S");
  view_.draw_marker(Vec2(scene_.goal[0], scene_.goal[1]), theme::kGoal, "G");
  handle_disk_drag();
  dl->PopClipRect();
  if (view_.hovered()) {
    const Vec2 m = view_.mouse_world();
    char text[64];
    std::snprintf(text, sizeof text, "(%.3f, %.3f)", m.x(), m.y());
    dl->AddText(ImVec2(view_.canvas_min().x + 8, view_.canvas_max().y - ImGui::GetTextLineHeight() - 6),
                theme::kLabel, text);
  }
}

}  // namespace csl::app
