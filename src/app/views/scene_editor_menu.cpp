// The scene editor's context menu: what can be done here, on the thing under the pointer. A
// right-click that does not pan opens it with a mouse; a long press (a finger held still for
// half a second) opens it by touch, where there is no right button and no Delete key: deleting,
// duplicating or selecting an obstacle, adding a disk or a square, moving the start or goal
// here, undo and fitting the view all stay one press away on a phone.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/shell/input_mode.hpp"
#include "app/shell/web_bridge.hpp"
#include "app/views/scene_editor.hpp"
#include "core/geometry/obstacles.hpp"

namespace csl::app {
namespace {

constexpr float kLongPressSeconds = 0.5f;
// ... and this many frames: a stalled page (a slow phone, a busy machine) that draws two frames
// between a finger's press and its first move has not been held still.
constexpr int kLongPressFrames = 30;  // (0.5 s at 60 frames a second: there the time decides)
constexpr float kStillPixels = 10.0f;  // a press that moved farther is a swipe, not a long press...
constexpr float kStillGrabbing = 4.0f;  // ...or this far, holding what it grabbed: that moved with it
constexpr float kPanPixels = 4.0f;     // a right-drag farther than this panned: no menu
const char* const kMenuId = "##scene-context";

const char* shape_name(const Obstacle& o) {
  if (std::holds_alternative<Disk>(o)) return "disk";
  if (std::holds_alternative<PolygonObstacle>(o)) return "polygon";
  return "wall";
}

}  // namespace

bool SceneEditor::menu_right_click(const WorkspaceView& view) const {
  // The right button released where it was pressed (a right-drag pans the view).
  return view.hovered() && ImGui::IsMouseReleased(ImGuiMouseButton_Right) &&
         ImGui::GetIO().MouseDragMaxDistanceSqr[ImGuiMouseButton_Right] <= kPanPixels * kPanPixels;
}

bool SceneEditor::menu_long_press(const WorkspaceView& view) {
  // A finger held still, once per press, never during a pinch, and only with the Select tool:
  // with Disk, Wall or Polygon a press draws (a slow start of a drawing is no long press).
  const ImGuiIO& io = ImGui::GetIO();
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) long_pressed_ = false, press_frames_ = 0;
  else ++press_frames_;
  const bool long_press = input::touch() && tool_ == Tool::Select && !long_pressed_ && view.hovered() && !input::pinch().active &&
                          ImGui::IsMouseDown(ImGuiMouseButton_Left) &&
                          io.MouseDownDuration[ImGuiMouseButton_Left] >= kLongPressSeconds && press_frames_ >= kLongPressFrames &&
                          input::finger_travel() <= (drag_ != Drag::None ? kStillGrabbing : kStillPixels);
  if (long_press) long_pressed_ = true;
  return long_press;
}

bool SceneEditor::context_menu(WorkspaceView& view, Scene& scene, LabContext& ctx, const Options& options) {
  const bool right_click = menu_right_click(view);
  const bool long_press = menu_long_press(view);
  if (right_click || long_press) {
    if (long_press) {
      // The press may have begun a drag (of the start, an obstacle); a long press means the menu instead.
      if (drag_ != Drag::None) {
        if (before_drag_) scene = *before_drag_;
        drop_drag();
      }
    }
    menu_at_ = view.mouse_world();
    menu_target_ = obstacle_under(scene, menu_at_, view.pixels(4.0f));
    ImGui::OpenPopup(kMenuId);
  }

  bool changed = false;
  if (!ImGui::BeginPopup(kMenuId)) return changed;
  if (menu_target_ >= static_cast<int>(scene.obstacles.size())) menu_target_ = -1;  // gone meanwhile
  const auto edit = [&](auto&& apply) {
    const Scene before = scene;
    apply();
    if (!same_scene(before, scene)) {
      record(before);
      changed = true;
    }
    ImGui::CloseCurrentPopup();
  };
  // A new obstacle, selected (its handles show): one undo step, or the editor's refusal.
  const auto add = [&](const Obstacle& o) {
    const Scene before = scene;
    if (add_obstacle(scene, o, ctx)) {
      record(before);
      selected_ = static_cast<int>(scene.obstacles.size()) - 1;
      changed = true;
    }
    ImGui::CloseCurrentPopup();
  };
  char title[96];
  if (menu_target_ >= 0) {
    const Obstacle& o = scene.obstacles[static_cast<std::size_t>(menu_target_)];
    std::snprintf(title, sizeof title, "Obstacle %d (%s)", menu_target_ + 1, shape_name(o));
    ImGui::TextDisabled("%s", title);
    if (ImGui::MenuItem("Select (handles to resize)")) {
      set_tool(Tool::Select);
      selected_ = menu_target_;
      ImGui::CloseCurrentPopup();
    }
    web::record_control("context-select");
    if (ImGui::MenuItem("Duplicate")) {
      Obstacle copy = o;
      translate(copy, Vec2(view.pixels(24.0f), -view.pixels(24.0f)));  // beside it, visibly a second one
      add(copy);
    }
    web::record_control("context-duplicate");
    if (ImGui::MenuItem("Delete")) {
      edit([&] { scene.obstacles.erase(scene.obstacles.begin() + menu_target_); });
      selected_ = -1;
      focus_ = Focus::None;
    }
    web::record_control("context-delete");
  } else {
    std::snprintf(title, sizeof title, "Here: (%.3g, %.3g)", menu_at_.x(), menu_at_.y());
    ImGui::TextDisabled("%s", title);
    // A new obstacle where the menu was opened, its radius (half its width) a twelfth of the view.
    const double size = view.pixels(std::min(view.canvas_max().x - view.canvas_min().x,
                                             view.canvas_max().y - view.canvas_min().y) / 12.0f);
    if (ImGui::MenuItem("Add a disk here")) add(Disk{menu_at_, size});
    web::record_control("context-add-disk");
    if (ImGui::MenuItem("Add a square here")) {
      const Vec2 c = menu_at_;
      add(PolygonObstacle{{c + Vec2(-size, -size), c + Vec2(size, -size), c + Vec2(size, size), c + Vec2(-size, size)}});
    }
    web::record_control("context-add-square");
    if (options.endpoints_are_points && scene.start.size() >= 2 && scene.goal.size() >= 2) {
      if (ImGui::MenuItem("Move the start here")) edit([&] { scene.start[0] = menu_at_.x(), scene.start[1] = menu_at_.y(); });
      web::record_control("context-start");
      if (ImGui::MenuItem("Move the goal here")) edit([&] { scene.goal[0] = menu_at_.x(), scene.goal[1] = menu_at_.y(); });
      web::record_control("context-goal");
    }
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Undo", nullptr, false, can_undo())) {
    changed |= undo(scene);
    ImGui::CloseCurrentPopup();
  }
  web::record_control("context-undo");
  if (ImGui::MenuItem("Fit the view", nullptr, false, view.fit_button_shown())) {
    view.reset_view();
    ImGui::CloseCurrentPopup();
  }
  web::record_control("context-fit");
  ImGui::EndPopup();
  return changed;
}

}  // namespace csl::app
