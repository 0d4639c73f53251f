#pragma once
// A canvas showing a rectangle of a plane (the workspace, or a 2-D C-space) with y up: the
// mapping between world and screen, pan (right or middle drag) and zoom (wheel, about the
// cursor), the grid, and drawing helpers for the shapes lessons show.
#include <cstddef>
#include <string>
#include <vector>

#include "core/geometry/obstacles.hpp"
#include "imgui.h"

namespace csl::app {

class WorkspaceView {
 public:
  /// The user's zoom (1: the whole rectangle, "Fit") stays within these: the wheel and a pinch
  /// stop there, and a link or a saved camera outside them is refused.
  static constexpr double kMinZoom = 0.5;
  static constexpr double kMaxZoom = 200.0;
  /// Where the view looks: the world point at the canvas's centre and the zoom (1: Fit). What
  /// travels in snapshots and links (app/shell/camera.*), independent of the canvas's size.
  struct Camera {
    Vec2 center{0, 0};
    double zoom = 1.0;
  };

  /// Lays out the canvas in the current ImGui window at the cursor, filling `size` (logical
  /// pixels) and showing [world_min, world_max] as large as fits with equal scale on both axes
  /// (times the user's zoom). Handles pan and zoom. Call once a frame before the helpers.
  void begin(const char* id, ImVec2 size, const Vec2& world_min, const Vec2& world_max);
  /// Axes that are angles (S^1 coordinates): lines and labels at multiples of pi ("π/2").
  void set_angular(bool x, bool y) {
    angular_[0] = x;
    angular_[1] = y;
  }
  /// Back to the whole rectangle.
  void reset_view() {
    zoom_ = 1.0;
    pan_ = Vec2(0, 0);
  }
  /// Whether the view shows the whole rectangle, as it starts (no zoom, no pan).
  bool fitted() const { return zoom_ == 1.0 && pan_ == Vec2(0, 0); }
  /// The camera on [world_min, world_max], the rectangle the lesson shows in this view now. A
  /// rectangle other than the one last drawn (a new scene not drawn yet) is shown whole at its
  /// next begin(): its camera is the Fit one.
  Camera camera(const Vec2& world_min, const Vec2& world_max) const;
  /// Where the centre may be for that rectangle: within one width (height) of it on each side,
  /// so that some of it is always in sight at the least zoom. Pans stop there too.
  static void center_limits(const Vec2& world_min, const Vec2& world_max, Vec2& lo, Vec2& hi);
  /// Looks at `camera` in [world_min, world_max] (the lesson's rectangle for this view, which the
  /// next begin() then keeps). The caller checked it (zoom within the limits, centre within
  /// center_limits()).
  void set_camera(const Vec2& world_min, const Vec2& world_max, const Camera& camera);

  ImVec2 to_screen(const Vec2& p) const;
  Vec2 to_world(ImVec2 s) const;
  /// Logical pixels per world unit.
  float scale() const { return scale_; }
  ImVec2 canvas_min() const { return canvas_min_; }
  ImVec2 canvas_max() const { return canvas_max_; }
  bool hovered() const { return hovered_; }
  /// The labels of the last drawn grid's axis (0: x, 1: y), in order ("−π", "0", "0.5").
  const std::vector<std::string>& tick_labels(int axis) const { return tick_labels_[axis]; }
  /// The view is zoomed or panned, and shows its "Fit view (F)" button this frame.
  bool fit_button_shown() const { return fit_button_; }
  /// The mouse in world coordinates.
  Vec2 mouse_world() const { return to_world(ImGui::GetIO().MousePos); }
  /// World distance of `pixels` logical pixels (for hit tolerances).
  double pixels(float pixels) const { return static_cast<double>(pixels / scale_); }
  /// World distance within which a handle drawn `mouse_px` wide is grabbed: wider under a finger
  /// (input::reach), so that every handle is a 44 px touch target.
  double reach(float mouse_px) const;

  ImDrawList* draw_list() const { return ImGui::GetWindowDrawList(); }
  /// The background, grid and axis labels; `x_label`/`y_label` name the axes.
  void draw_grid(const char* x_label = "x", const char* y_label = "y") const;
  /// Clips drawing to the world rectangle's visible part (pair with pop_clip()).
  void push_clip() const;
  void pop_clip() const { draw_list()->PopClipRect(); }
  void draw_disk(const Vec2& center, double radius, ImU32 fill, ImU32 edge, float thickness = 1.5f) const;
  void draw_circle(const Vec2& center, double radius, ImU32 edge, float thickness = 1.5f) const;
  void draw_polygon(const Polygon& poly, ImU32 fill, ImU32 edge, float thickness = 1.5f) const;
  void draw_segment(const Vec2& a, const Vec2& b, ImU32 color, float thickness = 1.5f) const;
  /// An obstacle in the lab's obstacle colours (highlighted: the selection colour).
  void draw_obstacle(const Obstacle& o, bool highlighted = false) const;
  /// A labelled marker (start, goal): a filled circle of fixed screen size with a letter;
  /// `warn` draws a red ring (e.g. it lies inside an obstacle).
  void draw_marker(const Vec2& p, ImU32 color, const char* label, bool warn = false) const;
  /// Text at a world point, offset in pixels.
  void draw_label(const Vec2& p, const char* text, ImU32 color, ImVec2 offset = ImVec2(6, -18)) const;

 private:
  // One axis's grid: a line every `step`, labelled every `major_every` lines; an angular axis's
  // labels are multiples of pi / denominator.
  struct Ticks {
    double step = 1.0;
    int major_every = 5;
    bool angular = false;
    int denominator = 1;
  };
  Ticks ticks(int axis, double extent, double pixels_per_unit) const;
  /// "3π/4", "−π", "0": numerator * pi / denominator, reduced.
  static void angle_label(long long numerator, int denominator, char* out, std::size_t size);

  ImVec2 canvas_min_{0, 0}, canvas_max_{0, 0};  // the whole widget
  ImVec2 center_screen_{0, 0};                  // screen point of center_world_
  Vec2 center_world_{0, 0};
  Vec2 world_min_{0, 0}, world_max_{1, 1};
  float scale_ = 1.0f;
  double zoom_ = 1.0;
  Vec2 pan_{0, 0};  // world offset of the view's centre from the rectangle's centre
  bool hovered_ = false;
  bool panning_ = false;
  bool fit_button_ = false;  // the "Fit view" button is on the canvas this frame
  bool angular_[2] = {false, false};
  mutable std::vector<std::string> tick_labels_[2];  // what draw_grid() wrote (for the JS API)
};

}  // namespace csl::app
