#include "app/views/workspace_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "app/shell/fonts.hpp"
#include "app/shell/input_mode.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/web_bridge.hpp"
#include "core/base/angles.hpp"
#include "core/base/overloaded.hpp"

namespace csl::app {

namespace {
constexpr float kMargin = 36.0f;  // room for the axis labels
float ui_button_width(const char* label) {  // of a SmallButton
  return ImGui::CalcTextSize(label).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}
}

void WorkspaceView::begin(const char* id, ImVec2 size, const Vec2& world_min, const Vec2& world_max) {
  // A scene of another size (an import, a link): the whole of it, not the old zoom on it.
  if (world_min != world_min_ || world_max != world_max_) reset_view();
  world_min_ = world_min;
  world_max_ = world_max;
  canvas_min_ = ImGui::GetCursorScreenPos();
  size.x = std::max(size.x, 64.0f);
  size.y = std::max(size.y, 64.0f);
  canvas_max_ = ImVec2(canvas_min_.x + size.x, canvas_min_.y + size.y);
  if (zoom_ != 1.0 || pan_ != Vec2(0, 0)) {
    // Zoomed or panned: a button back to the whole picture, at the canvas's top right, in a child
    // window of its own. A child is drawn after its parent's draw list: zoomed in, the world
    // rectangle's background and the scene drawn after begin() cover the whole canvas, and hid a
    // button drawn in it (a link opened zoomed showed no way back). The mouse over the child is
    // not over the canvas, so the press is the button's and an editor under it sees none.
    const char* label = "Fit view (F)";
    const ImVec2 button(ui_button_width(label), ImGui::GetTextLineHeight());
    ImGui::SetCursorScreenPos(ImVec2(canvas_max_.x - button.x - 6.0f, canvas_min_.y + 4.0f));
    ImGui::PushID(id);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::BeginChild("##fit", button, false,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBackground);
    if (ImGui::SmallButton(label)) reset_view();
    web::record_control((std::string("fit") + id).c_str());  // "fit##prm-workspace": for tests
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the whole scene again (F)");
    ImGui::EndChild();
    ImGui::PopStyleVar();
    ImGui::PopID();
    fit_button_ = true;
    ImGui::SetCursorScreenPos(canvas_min_);
  } else {
    fit_button_ = false;
  }
  ImGui::InvisibleButton(id, size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  hovered_ = ImGui::IsItemHovered();

  const Vec2 extent = world_max_ - world_min_;
  const float avail_w = size.x - 2 * kMargin, avail_h = size.y - 2 * kMargin;
  // In double: a float of avail / extent overflowed to infinity for tiny workspaces. The
  // schema keeps sides >= 0.001 (and a scale far inside float's range); this is the last guard.
  const double fit_d = std::min(static_cast<double>(avail_w) / std::max(extent.x(), 1e-300),
                                static_cast<double>(avail_h) / std::max(extent.y(), 1e-300));
  const float fit = static_cast<float>(std::clamp(std::isfinite(fit_d) ? fit_d : 1.0, 1.0, 1e12));
  const ImGuiIO& io = ImGui::GetIO();
  // Zoom about the cursor: the world point under it stays put.
  if (hovered_ && io.MouseWheel != 0.0f) {
    const Vec2 before = mouse_world();
    zoom_ = std::clamp(zoom_ * std::pow(1.2, static_cast<double>(io.MouseWheel)), kMinZoom, kMaxZoom);
    scale_ = fit * static_cast<float>(zoom_);
    center_world_ = 0.5 * (world_min_ + world_max_) + pan_;
    center_screen_ = ImVec2(canvas_min_.x + 0.5f * size.x, canvas_min_.y + 0.5f * size.y);
    pan_ += before - mouse_world();
  }
  // Two fingers: zoom about their midpoint as they spread, and pan as it moves.
  const input::Pinch& pinch = input::pinch();
  if (pinch.active && pinch.center.x >= canvas_min_.x && pinch.center.x < canvas_max_.x &&
      pinch.center.y >= canvas_min_.y && pinch.center.y < canvas_max_.y) {
    const Vec2 before = to_world(pinch.center);
    zoom_ = std::clamp(zoom_ * static_cast<double>(pinch.scale), kMinZoom, kMaxZoom);
    scale_ = fit * static_cast<float>(zoom_);
    center_world_ = 0.5 * (world_min_ + world_max_) + pan_;
    center_screen_ = ImVec2(canvas_min_.x + 0.5f * size.x, canvas_min_.y + 0.5f * size.y);
    pan_ += before - to_world(pinch.center);
    pan_ -= Vec2(static_cast<double>(pinch.pan.x), -static_cast<double>(pinch.pan.y)) / static_cast<double>(scale_);
  }
  // Pan with the right or middle button.
  if (hovered_ && (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)))
    panning_ = true;
  if (panning_) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle))
      pan_ -= Vec2(static_cast<double>(io.MouseDelta.x), -static_cast<double>(io.MouseDelta.y)) /
              static_cast<double>(scale_);
    else
      panning_ = false;
  }
  // Not out of sight: a camera a link can hold (camera.cpp refuses the same limits).
  Vec2 lo, hi;
  center_limits(world_min_, world_max_, lo, hi);
  const Vec2 mid = 0.5 * (world_min_ + world_max_);
  for (int axis = 0; axis < 2; ++axis) {  // (pan_ untouched inside: no rounding creeps in a frame at a time)
    if (mid[axis] + pan_[axis] < lo[axis]) pan_[axis] = lo[axis] - mid[axis];
    if (mid[axis] + pan_[axis] > hi[axis]) pan_[axis] = hi[axis] - mid[axis];
  }
  scale_ = fit * static_cast<float>(zoom_);
  center_world_ = mid + pan_;
  // Snapped to whole pixels so that 1-pixel grid lines stay sharp.
  center_screen_ = ImVec2(std::round(canvas_min_.x + 0.5f * size.x), std::round(canvas_min_.y + 0.5f * size.y));
}

WorkspaceView::Camera WorkspaceView::camera(const Vec2& world_min, const Vec2& world_max) const {
  const Vec2 mid = 0.5 * (world_min + world_max);
  if (world_min != world_min_ || world_max != world_max_) return {mid, 1.0};
  return {mid + pan_, zoom_};
}

void WorkspaceView::center_limits(const Vec2& world_min, const Vec2& world_max, Vec2& lo, Vec2& hi) {
  const Vec2 extent = world_max - world_min;
  lo = world_min - extent;
  hi = world_max + extent;
}

void WorkspaceView::set_camera(const Vec2& world_min, const Vec2& world_max, const Camera& camera) {
  world_min_ = world_min;  // so that begin() keeps the camera rather than fit a "new" rectangle
  world_max_ = world_max;
  zoom_ = camera.zoom;
  pan_ = camera.center - 0.5 * (world_min + world_max);
  panning_ = false;
}

double WorkspaceView::reach(float mouse_px) const { return pixels(input::reach(mouse_px)); }

ImVec2 WorkspaceView::to_screen(const Vec2& p) const {
  return ImVec2(center_screen_.x + scale_ * static_cast<float>(p.x() - center_world_.x()),
                center_screen_.y - scale_ * static_cast<float>(p.y() - center_world_.y()));
}

Vec2 WorkspaceView::to_world(ImVec2 s) const {
  return {center_world_.x() + static_cast<double>((s.x - center_screen_.x) / scale_),
          center_world_.y() + static_cast<double>((center_screen_.y - s.y) / scale_)};
}

void WorkspaceView::push_clip() const {
  const ImVec2 lo = to_screen(world_min_), hi = to_screen(world_max_);
  const ImVec2 a(std::max(lo.x, canvas_min_.x), std::max(hi.y, canvas_min_.y));
  const ImVec2 b(std::min(hi.x + 1, canvas_max_.x), std::min(lo.y + 1, canvas_max_.y));
  draw_list()->PushClipRect(a, b, true);
}

WorkspaceView::Ticks WorkspaceView::ticks(int axis, double extent, double pixels_per_unit) const {
  Ticks t;
  if (angular_[axis]) {
    // Multiples of pi: labels at pi/d (d = 1, 2, 4, 12, 24, 48: 180, 90, 45, 15, 7.5, 3.75
    // degrees), the finest at least ~56 px apart (pi itself when none is), and lines between
    // them at least 12 px apart.
    t.angular = true;
    t.denominator = 1;
    for (int d : {1, 2, 4, 12, 24, 48})
      if (kPi / d * pixels_per_unit >= 56.0) t.denominator = d;
    const double major = kPi / t.denominator;
    t.major_every = 1;
    for (int m : {2, 3, 4, 6})
      if (major / m * pixels_per_unit >= 12.0) t.major_every = m;
    t.step = major / t.major_every;
    return t;
  }
  // A power of ten (or half of one) that gives lines at least ~24 px apart; labels every fifth.
  double step = std::pow(10.0, std::floor(std::log10(extent)));
  for (int i = 0; i < 64 && step * pixels_per_unit > 240.0; ++i) step /= 2.0;
  for (int i = 0; i < 64 && step * pixels_per_unit > 48.0; ++i) step /= 5.0;
  for (int i = 0; i < 64 && step * pixels_per_unit < 12.0; ++i) step *= 2.0;
  t.step = step;
  t.major_every = 5;
  return t;
}

void WorkspaceView::angle_label(long long numerator, int denominator, char* out, std::size_t size) {
  if (numerator == 0) {
    std::snprintf(out, size, "0");
    return;
  }
  long long a = std::llabs(numerator), b = denominator;
  while (b != 0) {  // gcd
    const long long r = a % b;
    a = b;
    b = r;
  }
  const long long num = numerator / a, den = denominator / a;
  const char* sign = num < 0 ? "\xE2\x88\x92" : "";  // a minus sign, as the lessons write one
  const long long m = std::llabs(num);
  const std::string coefficient = m == 1 ? "" : std::to_string(m);
  if (den == 1) std::snprintf(out, size, "%s%s\xCF\x80", sign, coefficient.c_str());
  else std::snprintf(out, size, "%s%s\xCF\x80/%lld", sign, coefficient.c_str(), den);
}

void WorkspaceView::draw_grid(const char* x_label, const char* y_label) const {
  ImDrawList* dl = draw_list();
  dl->PushClipRect(canvas_min_, canvas_max_, true);
  const ImVec2 lo = to_screen(world_min_), hi = to_screen(world_max_);
  dl->AddRectFilled(ImVec2(lo.x, hi.y), ImVec2(hi.x, lo.y), theme::kCanvasBg);

  const double extent = std::max(world_max_.x() - world_min_.x(), world_max_.y() - world_min_.y());
  const double pixels_per_unit = static_cast<double>(scale_);
  if (!(extent > 0.0) || !std::isfinite(extent) || !(pixels_per_unit > 0.0) || !std::isfinite(pixels_per_unit)) {
    dl->PopClipRect();
    return;
  }
  const double most_lines = 2.0 + static_cast<double>(std::max(canvas_max_.x - canvas_min_.x, canvas_max_.y - canvas_min_.y)) / 6.0;
  // The part of the world rectangle on the canvas: zoomed in, lines outside it are not counted
  // (or a 1 x 1 workspace at zoom 10 would have more lines than the cap, and none drawn).
  const Vec2 seen_a = to_world(canvas_min_), seen_b = to_world(canvas_max_);
  for (int axis = 0; axis < 2; ++axis) {
    tick_labels_[axis].clear();
    const Ticks t = ticks(axis, extent, pixels_per_unit);
    const double a0 = std::max(world_min_[axis], std::min(seen_a[axis], seen_b[axis]));
    const double a1 = std::min(world_max_[axis], std::max(seen_a[axis], seen_b[axis]));
    if (!(a0 <= a1)) continue;
    // Lines are counted, not stepped to an end: at most one per 6 pixels of the canvas, whatever
    // the scene's size or the float scale does (a step below the rounding of its values stepped
    // forever, and a 1e-15 wide workspace drew ~1e8 lines into the draw list).
    const double first = std::ceil(a0 / t.step - 1e-9);
    const double count = std::floor((a1 - first * t.step) / t.step + 1e-9) + 1.0;  // lines in [a0, a1]
    if (!(count >= 1.0) || count > most_lines) continue;
    for (int k = 0; k < static_cast<int>(count); ++k) {
      const double index = first + k;  // the line's multiple of the step
      const double v = index * t.step;
      const bool is_major = std::fmod(std::fabs(index), static_cast<double>(t.major_every)) < 0.5;
      Vec2 p = world_min_, q = world_max_;
      p[axis] = q[axis] = v;
      dl->AddLine(to_screen(p), to_screen(q), is_major ? theme::kGridMajor : theme::kGridMinor, 1.0f);
      if (!is_major) continue;
      char text[32];
      if (t.angular) {
        angle_label(static_cast<long long>(std::llround(index / t.major_every)), t.denominator, text, sizeof text);
      } else {
        std::snprintf(text, sizeof text, "%g", std::fabs(v) < 1e-12 * extent ? 0.0 : v);
      }
      tick_labels_[axis].emplace_back(text);
      ImFont* font = fonts().small;
      const float fs = font->FontSize * ImGui::GetIO().FontGlobalScale;
      const ImVec2 ts = font->CalcTextSizeA(fs, 1e9f, 0.0f, text);
      const ImVec2 at = to_screen(p);
      const ImVec2 pos = axis == 0 ? ImVec2(at.x - 0.5f * ts.x, lo.y + 6.0f)
                                   : ImVec2(lo.x - ts.x - 6.0f, at.y - 0.5f * ts.y);
      dl->AddText(font, fs, pos, theme::kLabel, text);
    }
  }
  dl->AddRect(ImVec2(lo.x, hi.y), ImVec2(hi.x + 1, lo.y + 1), theme::kFrame, 0.0f, 0, 1.0f);
  // Axis names beside the frame.
  ImFont* font = fonts().small;
  const float fs = font->FontSize * ImGui::GetIO().FontGlobalScale;
  // The x axis's name right of the frame; where the canvas ends too soon for it (a square view
  // filling its width), under the frame's right end, below the tick numbers.
  const ImVec2 xs = font->CalcTextSizeA(fs, 1e9f, 0.0f, x_label);
  const ImVec2 x_at = hi.x + 6.0f + xs.x <= canvas_max_.x ? ImVec2(hi.x + 6.0f, lo.y - 0.5f * fs)
                                                          : ImVec2(hi.x - xs.x, lo.y + 8.0f + fs);
  dl->AddText(font, fs, x_at, theme::kLabel, x_label);
  const ImVec2 ys = font->CalcTextSizeA(fs, 1e9f, 0.0f, y_label);
  dl->AddText(font, fs, ImVec2(lo.x - 0.5f * ys.x, hi.y - ys.y - 4.0f), theme::kLabel, y_label);
  dl->PopClipRect();
}

void WorkspaceView::draw_disk(const Vec2& center, double radius, ImU32 fill, ImU32 edge,
                              float thickness) const {
  const ImVec2 c = to_screen(center);
  const float r = scale_ * static_cast<float>(radius);
  // Enough segments that the outline looks round at any zoom.
  const int segments = std::clamp(static_cast<int>(r * 0.75f), 24, 256);
  ImDrawList* dl = draw_list();
  if (fill & IM_COL32_A_MASK) dl->AddCircleFilled(c, r, fill, segments);
  if (edge & IM_COL32_A_MASK) dl->AddCircle(c, r, edge, segments, thickness);
}

void WorkspaceView::draw_polygon(const Polygon& poly, ImU32 fill, ImU32 edge, float thickness) const {
  ImDrawList* dl = draw_list();
  ImVector<ImVec2> pts;
  pts.reserve(static_cast<int>(poly.size()));
  for (const Vec2& v : poly) pts.push_back(to_screen(v));
  if (polygon_is_convex(poly)) {
    dl->AddConvexPolyFilled(pts.Data, pts.Size, fill);
  } else {
    // ImGui fills convex shapes only: fill the ear-clipping triangles without anti-aliasing
    // (anti-aliased fringes would show seams between them); the outline smooths the border.
    const std::vector<Triangle> tris = triangulate(poly);
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
    dl->PrimReserve(static_cast<int>(3 * tris.size()), static_cast<int>(3 * tris.size()));
    for (const Triangle& t : tris)
      for (int k : t) {
        dl->PrimWriteIdx(dl->_VtxCurrentIdx);
        dl->PrimWriteVtx(pts[k], uv, fill);
      }
  }
  dl->AddPolyline(pts.Data, pts.Size, edge, ImDrawFlags_Closed, thickness);
}

void WorkspaceView::draw_obstacle(const Obstacle& o, bool highlighted) const {
  const ImU32 fill = highlighted ? theme::kSelectedFill : theme::kObstacleFill;
  const ImU32 edge = highlighted ? theme::kSelectedEdge : theme::kObstacleEdge;
  std::visit(Overloaded{[&](const Disk& d) { draw_disk(d.center, d.radius, fill, edge, highlighted ? 2.5f : 1.5f); },
                        [&](const PolygonObstacle& g) { draw_polygon(g.vertices, fill, edge, highlighted ? 2.5f : 1.5f); },
                        [&](const Wall& w) { draw_segment(w.a, w.b, edge, highlighted ? 4.0f : 3.0f); }},
             o);
}

void WorkspaceView::draw_circle(const Vec2& center, double radius, ImU32 edge, float thickness) const {
  const float r = scale_ * static_cast<float>(radius);
  draw_list()->AddCircle(to_screen(center), r, edge, std::clamp(static_cast<int>(r * 0.75f), 24, 256), thickness);
}

void WorkspaceView::draw_segment(const Vec2& a, const Vec2& b, ImU32 color, float thickness) const {
  draw_list()->AddLine(to_screen(a), to_screen(b), color, thickness);
}

void WorkspaceView::draw_label(const Vec2& p, const char* text, ImU32 color, ImVec2 offset) const {
  const ImVec2 s = to_screen(p);
  draw_list()->AddText(ImVec2(s.x + offset.x, s.y + offset.y), color, text);
}

void WorkspaceView::draw_marker(const Vec2& p, ImU32 color, const char* label, bool warn) const {
  const ImVec2 c = to_screen(p);
  ImDrawList* dl = draw_list();
  if (warn) dl->AddCircle(c, 14.0f, theme::kWarning, 32, 3.0f);
  dl->AddCircleFilled(c, 9.0f, color, 24);
  dl->AddCircle(c, 9.0f, theme::kInk, 24, 1.5f);
  ImFont* font = fonts().small;
  const float fs = font->FontSize * ImGui::GetIO().FontGlobalScale;
  const ImVec2 ts = font->CalcTextSizeA(fs, 1e9f, 0.0f, label);
  // Black or white, whichever reads at 4.5:1 on the fill (white on the green start was 3.4:1).
  dl->AddText(font, fs, ImVec2(c.x - 0.5f * ts.x, c.y - 0.5f * ts.y), theme::text_on(color), label);
}

}  // namespace csl::app
