#include "app/workspace_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/fonts.hpp"
#include "app/theme.hpp"

namespace csl::app {

namespace {
constexpr float kMargin = 36.0f;  // room for the axis labels
}

bool WorkspaceView::begin(const char* id, ImVec2 size, const Vec2& world_min, const Vec2& world_max) {
  world_min_ = world_min;
  world_max_ = world_max;
  canvas_min_ = ImGui::GetCursorScreenPos();
  size.x = std::max(size.x, 64.0f);
  size.y = std::max(size.y, 64.0f);
  canvas_max_ = ImVec2(canvas_min_.x + size.x, canvas_min_.y + size.y);
  ImGui::InvisibleButton(id, size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  hovered_ = ImGui::IsItemHovered();

  const Vec2 extent = world_max_ - world_min_;
  const float avail_w = size.x - 2 * kMargin, avail_h = size.y - 2 * kMargin;
  scale_ = std::max(1.0f, std::min(avail_w / static_cast<float>(extent.x()),
                                   avail_h / static_cast<float>(extent.y())));
  const float used_w = scale_ * static_cast<float>(extent.x());
  const float used_h = scale_ * static_cast<float>(extent.y());
  // Bottom-left corner of the world rectangle, centred in the canvas; snapped to whole pixels
  // so that 1-pixel grid lines stay sharp.
  origin_ = ImVec2(std::round(canvas_min_.x + 0.5f * (size.x - used_w)),
                   std::round(canvas_min_.y + 0.5f * (size.y + used_h)));
  return hovered_;
}

ImVec2 WorkspaceView::to_screen(const Vec2& p) const {
  return ImVec2(origin_.x + scale_ * static_cast<float>(p.x() - world_min_.x()),
                origin_.y - scale_ * static_cast<float>(p.y() - world_min_.y()));
}

Vec2 WorkspaceView::to_world(ImVec2 s) const {
  return {world_min_.x() + static_cast<double>((s.x - origin_.x) / scale_),
          world_min_.y() + static_cast<double>((origin_.y - s.y) / scale_)};
}

void WorkspaceView::draw_grid() const {
  ImDrawList* dl = draw_list();
  const ImVec2 lo = to_screen(world_min_), hi = to_screen(world_max_);
  dl->AddRectFilled(ImVec2(lo.x, hi.y), ImVec2(hi.x, lo.y), theme::kCanvasBg);
  dl->PushClipRect(canvas_min_, canvas_max_, true);

  // Grid spacing: a power of ten (or half of one) that gives lines at least ~24 px apart.
  const double extent = std::max(world_max_.x() - world_min_.x(), world_max_.y() - world_min_.y());
  double step = std::pow(10.0, std::floor(std::log10(extent)));
  while (step * static_cast<double>(scale_) > 240.0) step /= 2.0;
  while (step * static_cast<double>(scale_) > 48.0) step /= 5.0;
  const double major = step * 5.0;
  for (int axis = 0; axis < 2; ++axis) {
    const double a0 = world_min_[axis], a1 = world_max_[axis];
    for (double v = std::ceil(a0 / step) * step; v <= a1 + 1e-9; v += step) {
      const bool is_major = std::fabs(v / major - std::round(v / major)) < 1e-6;
      Vec2 p = world_min_, q = world_max_;
      p[axis] = q[axis] = v;
      dl->AddLine(to_screen(p), to_screen(q), is_major ? theme::kGridMajor : theme::kGridMinor, 1.0f);
      if (!is_major) continue;
      char text[32];
      std::snprintf(text, sizeof text, "%g", std::fabs(v) < 1e-12 ? 0.0 : v);
      ImFont* font = fonts().small;
      const float fs = font->FontSize * ImGui::GetIO().FontGlobalScale;
      const ImVec2 ts = font->CalcTextSizeA(fs, 1e9f, 0.0f, text);
      const ImVec2 at = to_screen(p);
      const ImVec2 pos = axis == 0 ? ImVec2(at.x - 0.5f * ts.x, lo.y + 6.0f)
                                   : ImVec2(lo.x - ts.x - 6.0f, at.y - 0.5f * ts.y);
      dl->AddText(font, fs, pos, theme::kLabel, text);
    }
  }
  dl->PopClipRect();
  dl->AddRect(ImVec2(lo.x, hi.y), ImVec2(hi.x + 1, lo.y + 1), theme::kFrame, 0.0f, 0, 1.0f);
}

void WorkspaceView::draw_disk(const Vec2& center, double radius, ImU32 fill, ImU32 edge,
                              float thickness) const {
  const ImVec2 c = to_screen(center);
  const float r = scale_ * static_cast<float>(radius);
  // Enough segments that the outline looks round at any zoom.
  const int segments = std::clamp(static_cast<int>(r * 0.75f), 24, 256);
  ImDrawList* dl = draw_list();
  dl->AddCircleFilled(c, r, fill, segments);
  dl->AddCircle(c, r, edge, segments, thickness);
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
        dl->PrimWriteIdx(static_cast<ImDrawIdx>(dl->_VtxCurrentIdx));
        dl->PrimWriteVtx(pts[k], uv, fill);
      }
  }
  dl->AddPolyline(pts.Data, pts.Size, edge, ImDrawFlags_Closed, thickness);
}

void WorkspaceView::draw_obstacle(const Obstacle& o) const {
  if (const auto* d = std::get_if<Disk>(&o)) {
    draw_disk(d->center, d->radius, theme::kObstacleFill, theme::kObstacleEdge);
  } else if (const auto* g = std::get_if<PolygonObstacle>(&o)) {
    draw_polygon(g->vertices, theme::kObstacleFill, theme::kObstacleEdge);
  } else {
    const Wall& w = std::get<Wall>(o);
    draw_list()->AddLine(to_screen(w.a), to_screen(w.b), theme::kObstacleEdge, 3.0f);
  }
}

void WorkspaceView::draw_marker(const Vec2& p, ImU32 color, const char* label) const {
  const ImVec2 c = to_screen(p);
  ImDrawList* dl = draw_list();
  dl->AddCircleFilled(c, 9.0f, color, 24);
  dl->AddCircle(c, 9.0f, theme::kBlack, 24, 1.5f);
  ImFont* font = fonts().small;
  const float fs = font->FontSize * ImGui::GetIO().FontGlobalScale;
  const ImVec2 ts = font->CalcTextSizeA(fs, 1e9f, 0.0f, label);
  dl->AddText(font, fs, ImVec2(c.x - 0.5f * ts.x, c.y - 0.5f * ts.y), theme::rgba(255, 255, 255), label);
}

}  // namespace csl::app
