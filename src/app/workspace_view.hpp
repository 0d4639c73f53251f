#pragma once
// A canvas showing a rectangle of the plane (the workspace) with y pointing up: the mapping
// between world and screen, the grid, and drawing helpers for the things lessons show.
#include "core/obstacles.hpp"
#include "imgui.h"

namespace csl::app {

class WorkspaceView {
 public:
  /// Lays out the canvas in the current ImGui window, filling `size` (logical pixels) and
  /// showing [world_min, world_max] as large as fits with equal scale on both axes.
  /// Returns true while the mouse hovers it. Call before the helpers below, once a frame.
  bool begin(const char* id, ImVec2 size, const Vec2& world_min, const Vec2& world_max);

  ImVec2 to_screen(const Vec2& p) const;
  Vec2 to_world(ImVec2 s) const;
  /// Logical pixels per world unit.
  float scale() const { return scale_; }
  ImVec2 canvas_min() const { return canvas_min_; }
  ImVec2 canvas_max() const { return canvas_max_; }
  bool hovered() const { return hovered_; }
  /// The mouse in world coordinates (meaningful while hovered or dragging).
  Vec2 mouse_world() const { return to_world(ImGui::GetIO().MousePos); }

  ImDrawList* draw_list() const { return ImGui::GetWindowDrawList(); }
  void draw_grid() const;
  void draw_disk(const Vec2& center, double radius, ImU32 fill, ImU32 edge, float thickness = 1.5f) const;
  void draw_polygon(const Polygon& poly, ImU32 fill, ImU32 edge, float thickness = 1.5f) const;
  /// An obstacle in the lab's obstacle colours.
  void draw_obstacle(const Obstacle& o) const;
  /// A labelled marker (start, goal): a filled circle of fixed screen size with a letter.
  void draw_marker(const Vec2& p, ImU32 color, const char* label) const;

 private:
  ImVec2 canvas_min_{0, 0}, canvas_max_{0, 0};  // the whole widget
  ImVec2 origin_{0, 0};                         // screen position of world_min_
  Vec2 world_min_{0, 0}, world_max_{1, 1};
  float scale_ = 1.0f;
  bool hovered_ = false;
};

}  // namespace csl::app
