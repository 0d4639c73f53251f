#pragma once
// A small 3-D view for surfaces of the lesson (the torus T^2, the sphere S^2): parametric
// surfaces as shaded quads sorted back to front, curves on them, rotated by dragging.
// Orthographic projection; enough for pictures that teach, no GPU depth buffer needed.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "imgui.h"

namespace csl::app {

using Vec3 = Eigen::Vector3d;

/// A point of a surface with its unit normal.
struct SurfacePoint {
  Vec3 p;
  Vec3 n;
};

/// A quadrilateral piece of a surface in its (u, v) parameters, with its colour: corners
/// (u0, va0), (u1, va1), (u1, vb1), (u0, vb0), so its two v edges may slant (a boundary that
/// runs across the piece).
struct SurfacePatch {
  double u0, u1, va0, va1, vb0, vb1;
  ImU32 color;
};

/// Patches placed on a surface once (corners and the normal at the centre, in 3-D), so that a
/// frame only turns and projects them: a surface cut at a C-obstacle's edges has thousands.
struct SurfaceMesh {
  SurfaceMesh() = default;
  SurfaceMesh(const std::function<SurfacePoint(double u, double v)>& f, const std::vector<SurfacePatch>& patches);
  struct Face {
    Vec3 corner[4];
    Vec3 normal;
    ImU32 color;
  };
  std::vector<Face> faces;
};

class SurfaceView {
 public:
  /// Lays out the canvas at the cursor (size in logical pixels); a left drag turns the view.
  /// The drawing keeps clear of a band `top` pixels high at the top (the view's caption).
  void begin(const char* id, ImVec2 size, double extent, float top = 0.0f);
  /// The view's turn, as it starts and within what a drag reaches: yaw about the vertical axis,
  /// kept in [-pi, pi) (it wraps), pitch the tilt towards the viewer, within +-kMaxPitch.
  static constexpr double kDefaultYaw = 0.6;
  static constexpr double kDefaultPitch = 0.9;
  static constexpr double kMaxPitch = 1.5;
  void set_angles(double yaw, double pitch) {
    yaw_ = yaw;
    pitch_ = pitch;
  }
  double yaw() const { return yaw_; }
  double pitch() const { return pitch_; }
  /// How far a view that zooms (zooms(): the volume view's wheel) is zoomed in, 1 as it starts,
  /// within [kMinZoom, kMaxZoom]; a view that does not zoom stays at 1 (the camera link's third
  /// number is refused for it).
  static constexpr double kMinZoom = 0.5;
  static constexpr double kMaxZoom = 4.0;
  bool zooms() const { return zooms_; }
  double zoom() const { return zoom_; }
  void set_zoom(double zoom) {
    if (zooms_) zoom_ = zoom;
  }

  /// Screen position of a 3-D point; depth > 0 is nearer the viewer.
  ImVec2 project(const Vec3& p, double* depth = nullptr) const;
  /// Whether a surface normal faces the viewer.
  bool facing(const Vec3& n) const;

  /// The surface f(u, v), u and v in [0, 1), as nu x nv shaded quads coloured by
  /// color(u, v) (at the quad's centre), far ones first.
  void draw_surface(const std::function<SurfacePoint(double u, double v)>& f, int nu, int nv,
                    const std::function<ImU32(double u, double v)>& color) const;
  /// A mesh's faces, shaded, far ones first.
  void draw_mesh(const SurfaceMesh& mesh) const;
  /// A curve on a surface: solid where the surface faces the viewer, faint behind.
  void draw_curve(const std::vector<SurfacePoint>& points, ImU32 color, float thickness) const;
  bool hovered() const { return hovered_; }

 protected:
  /// View coordinates of a point: x to the right, z up the screen, y away from the viewer
  /// (the volume view, app/views/volume_view.*, draws with the same turn and projection).
  Vec3 rotate(const Vec3& p) const;
  /// Set by a view that zooms (its constructor).
  bool zooms_ = false;
  double zoom_ = 1.0;

 private:
  ImVec2 centre_{0, 0};
  float scale_ = 1.0f;
  double yaw_ = kDefaultYaw, pitch_ = kDefaultPitch;
  bool hovered_ = false;
};

/// The torus of radii (R, r): u turns around the hole (theta1), v around the tube (theta2).
SurfacePoint torus_point(double u, double v, double big = 1.0, double small = 0.42);
/// The unit sphere: u around the axis, v from pole to pole.
SurfacePoint sphere_point(double u, double v);

}  // namespace csl::app
