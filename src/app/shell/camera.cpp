#include "app/shell/camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <vector>

#include "app/shell/js_api.hpp"
#include "app/views/surface_view.hpp"
#include "app/views/workspace_view.hpp"
#include "core/base/angles.hpp"
#include "core/base/text.hpp"

namespace csl::app {

using json = nlohmann::json;

namespace {

// Refusals through one printf-like call: the wasm module is near its size budget, and a message
// built by std::string concatenation costs code at every place it is built.
[[noreturn]] void refuse(const char* format, ...) {
  char text[400];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  throw ApiError(std::string("camera: ") + text);
}

// x to `decimals` decimals, and inside [lo, hi] (rounding must not carry a value a pan or a drag
// stopped at a limit past it: the link would then be refused). n / 10^d is the double nearest
// the decimal, so the JSON prints it short ("0.31235", not "0.31235000000000002").
double round_within(double x, int decimals, double lo, double hi) {
  const double p = std::pow(10.0, decimals);
  if (!(std::fabs(x) * p < 9e15)) return x;  // past 2^53: the double is the decimal already
  double r = std::round(x * p) / p;
  if (r < lo) r = std::ceil(lo * p) / p;
  if (r > hi) r = std::floor(hi * p) / p;
  return r;
}

// Decimals that resolve 1/10000 of `extent` at `zoom`: a hundredth of a pixel on a canvas
// 100 px wide at the least, a fraction of one on the largest screens.
int decimals_for(double extent, double zoom) {
  return std::clamp(static_cast<int>(-std::floor(std::log10(extent / (zoom * 1e4)))), 0, 15);
}

// Zooms to 6 significant digits (1.2^4 = 2.0736000000000003 is written 2.0736).
double six_digits(double v) {
  const int d = 5 - static_cast<int>(std::floor(std::log10(v)));
  return std::round(v * std::pow(10.0, d)) / std::pow(10.0, d);
}

json numbers(std::initializer_list<double> values) {
  json out = json::array();
  for (double v : values) out.push_back(v);
  return out;
}

}  // namespace

json cameras_json(Lesson& lesson, bool all) {
  json out = json::object();
  for (const LessonView& v : lesson.views_kept()) {
    if (v.plane) {
      const WorkspaceView::Camera c = v.plane->camera(v.min, v.max);
      if (!all && c.zoom == 1.0 && c.center == 0.5 * (v.min + v.max)) continue;
      const Vec2 extent = v.max - v.min;
      const int d = decimals_for(std::max(extent.x(), extent.y()), c.zoom);
      Vec2 lo, hi;
      WorkspaceView::center_limits(v.min, v.max, lo, hi);
      out[v.name] = numbers({round_within(c.center.x(), d, lo.x(), hi.x()), round_within(c.center.y(), d, lo.y(), hi.y()),
                             six_digits(c.zoom)});
    } else if (v.surface) {
      const double yaw = v.surface->yaw(), pitch = v.surface->pitch(), zoom = v.surface->zoom();
      if (!all && yaw == SurfaceView::kDefaultYaw && pitch == SurfaceView::kDefaultPitch && zoom == 1.0) continue;
      out[v.name] = numbers({round_within(yaw, 4, -kPi, kPi), round_within(pitch, 4, -SurfaceView::kMaxPitch, SurfaceView::kMaxPitch)});
      // The zoom only where it is not 1: a turned view's link stays as it was before views zoomed.
      if (zoom != 1.0) out[v.name].push_back(six_digits(zoom));
    }
  }
  return out;
}

void set_cameras(Lesson& lesson, const json& cameras) {
  if (!cameras.is_object()) refuse("an object of views ({\"workspace\": [x, y, zoom], \"torus\": [yaw, pitch]})");
  const std::vector<LessonView> views = lesson.views_kept();
  struct Change {
    const LessonView* view;
    double n[3];
  };
  std::vector<Change> changes;
  for (auto it = cameras.begin(); it != cameras.end(); ++it) {
    const std::string key = printable(it.key(), 40);
    const char* name = key.c_str();
    const LessonView* view = nullptr;
    std::string known;
    for (const LessonView& v : views) {
      if (it.key() == v.name) view = &v;
      known += (known.empty() ? "" : ", ") + std::string(v.name);
    }
    if (!view) refuse("this lesson has no view \"%s\" (its views: %s)", name, known.empty() ? "none" : known.c_str());
    const json& j = *it;
    // A plane: x, y, zoom; a 3-D view: yaw, pitch, and its zoom if it zooms (1 when left out).
    const bool zooms = !view->plane && view->surface->zooms();
    const std::size_t count = view->plane ? 3 : zooms && j.is_array() && j.size() == 3 ? 3 : 2;
    bool ok = j.is_array() && j.size() == count;
    Change c{view, {0, 0, 1}};
    for (std::size_t i = 0; ok && i < count; ++i) {
      ok = j[i].is_number() && std::isfinite(j[i].get<double>());
      if (ok) c.n[i] = j[i].get<double>();
    }
    if (!ok)
      refuse(view->plane ? "%s is a plane: [x, y, zoom], finite numbers"
             : zooms     ? "%s is a 3-D view: [yaw, pitch] in radians and an optional zoom, finite numbers"
                         : "%s is a 3-D view: [yaw, pitch] in radians, finite numbers",
             name);
    if (view->plane) {
      if (c.n[2] < WorkspaceView::kMinZoom || c.n[2] > WorkspaceView::kMaxZoom)
        refuse("%s's zoom %g is outside [%g, %g] (1: the whole view)", name, c.n[2], WorkspaceView::kMinZoom, WorkspaceView::kMaxZoom);
      Vec2 lo, hi;
      WorkspaceView::center_limits(view->min, view->max, lo, hi);
      for (int axis = 0; axis < 2; ++axis)
        if (c.n[axis] < lo[axis] || c.n[axis] > hi[axis])
          refuse("%s's centre %s %g is outside [%g, %g] (at most the view's %s beside it)", name, axis ? "y" : "x", c.n[axis],
                 lo[axis], hi[axis], axis ? "height" : "width");
    } else {
      if (std::fabs(c.n[0]) > kPi) refuse("%s's yaw %g is outside [-pi, pi]", name, c.n[0]);
      if (std::fabs(c.n[1]) > SurfaceView::kMaxPitch)
        refuse("%s's pitch %g is outside [%g, %g]", name, c.n[1], -SurfaceView::kMaxPitch, SurfaceView::kMaxPitch);
      if (c.n[2] < SurfaceView::kMinZoom || c.n[2] > SurfaceView::kMaxZoom)
        refuse("%s's zoom %g is outside [%g, %g] (1: the whole block)", name, c.n[2], SurfaceView::kMinZoom,
               SurfaceView::kMaxZoom);
    }
    changes.push_back(c);
  }
  for (const Change& c : changes) {
    if (c.view->plane) {
      c.view->plane->set_camera(c.view->min, c.view->max, {Vec2(c.n[0], c.n[1]), c.n[2]});
    } else {
      c.view->surface->set_angles(wrap_angle(c.n[0]), c.n[1]);
      c.view->surface->set_zoom(c.n[2]);
    }
  }
}

std::string cameras_text(const json& cameras) {
  std::string out;
  for (auto it = cameras.begin(); it != cameras.end(); ++it) {
    char part[80];
    if (it->size() == 3) std::snprintf(part, sizeof part, "the %s zoomed %.3gx", it.key().c_str(), (*it)[2].get<double>());
    else std::snprintf(part, sizeof part, "the %s turned", it.key().c_str());
    out += (out.empty() ? "" : ", ") + std::string(part);
  }
  return out;
}

}  // namespace csl::app
