#pragma once
// A 3-D C-space as a block of voxels, seen with SurfaceView's turn and projection (a drag turns
// it, the wheel zooms, and the camera link key carries both): the boundary faces between
// blocked and free cells of a coarse CSpaceVolume, shaded and painter-sorted, cut by a plane
// across the third axis (theta, or theta1) that the lesson fills with the exact slice there.
// The half of the block beyond the plane (as the viewer sees it) is drawn faint, so the plane's
// slice is never hidden; a strip at the view's right edge scrubs the plane.
//
// Points are given in the block's unit coordinates u in [0, 1]^3 (the lesson maps its
// configurations there); u.z is the cut axis, drawn vertically.
#include <vector>

#include "app/views/surface_view.hpp"
#include "core/teaching/cspace_volume.hpp"

namespace csl::app {

class VolumeView : public SurfaceView {
 public:
  VolumeView() { zooms_ = true; }
  /// The cells to draw; `half` is the block's half size in view units (x, y, z).
  void set_volume(const CSpaceVolume& volume, const Vec3& half);
  /// The block's faces (after set_volume), for the API's counts.
  std::size_t faces() const { return faces_.size(); }

  /// Lays out the view (size in logical pixels) with its scrub strip on the right. A drag in
  /// the view turns it, the wheel zooms, arrow keys turn it while the mouse is over it; a drag
  /// in the strip, or Page Up / Page Down over the view, moves `cut` (in [0, 1]). True if the
  /// cut moved.
  bool begin(const char* id, ImVec2 size, double& cut);

  /// View coordinates of a unit point.
  Vec3 point(const Vec3& u) const;
  /// The block's faces beyond the cut plane (opaque, dimmed by the plane), `draw_plane` (what
  /// lies on the plane), then the faces on the viewer's side of it (faint).
  template <class F>
  void draw_block(double cut, const F& draw_plane) const {
    const bool from_above = facing(Vec3(0, 0, 1));
    draw_half(cut, from_above);  // beyond the plane
    draw_plane_frame(cut);
    draw_plane();
    draw_half(cut, !from_above);
  }
  /// A convex polygon in the cut plane (unit x, y at height cut), filled.
  void fill_in_plane(const std::vector<Vec2>& unit_xy, double cut, ImU32 color) const;
  /// The segment from a to a + d (unit coordinates), clipped to the block; along a glued axis
  /// (glued[axis]) the part that leaves through one face comes back through its twin.
  void draw_segment(const Vec3& a, const Vec3& d, const bool glued[3], ImU32 color, float thickness) const;
  /// A point (a dot with an outline, and a label beside it if any).
  void draw_point(const Vec3& u, ImU32 color, float radius, const char* label = nullptr) const;
  /// The block's twelve edges, and the names of its axes at their ends.
  void draw_frame(const char* x_name, const char* y_name, const char* z_name) const;
  /// The strip's rectangle on screen (for status().layout and tests).
  ImVec2 strip_min() const { return strip_min_; }
  ImVec2 strip_max() const { return strip_max_; }

  static constexpr float kStripWidth = 30.0f;

 private:
  struct Face {
    Vec3 corner[4];
    Vec3 normal;
    int layer;  // the cell's index along z
  };
  void draw_half(double cut, bool below) const;
  void draw_plane_frame(double cut) const;

  std::vector<Face> faces_;
  int nz_ = 1;
  Vec3 half_{1, 1, 1};
  ImVec2 strip_min_{0, 0}, strip_max_{0, 0};
};

}  // namespace csl::app
