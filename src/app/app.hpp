#pragma once
// The lab's user interface: a control panel and the workspace canvas where dragging draws disks.
#include <optional>
#include <string>

#include "app/platform.hpp"
#include "app/workspace_view.hpp"
#include "core/scene.hpp"

namespace csl::app {

class App {
 public:
  explicit App(const Platform& platform);
  /// Builds one frame of UI (between ImGui::NewFrame and ImGui::Render).
  void frame();

 private:
  void register_api();
  void draw_panel();
  void draw_workspace(ImVec2 size);
  void handle_disk_drag();

  const Platform& platform_;
  Scene scene_;
  WorkspaceView view_;
  std::optional<Vec2> drag_from_;  // press point of a disk being drawn
  std::string message_;            // last notice for the user
};

}  // namespace csl::app
