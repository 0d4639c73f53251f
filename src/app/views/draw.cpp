#include "app/views/draw.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "app/shell/theme.hpp"
#include "core/base/angles.hpp"

namespace csl::app {

void draw_robot(const WorkspaceView& view, const Robot& robot, const Config& q, ImU32 color, float thickness) {
  ImDrawList* dl = view.draw_list();
  if (const auto* arm = std::get_if<ArmRobot>(&robot)) {
    // Its links, the base black, each joint between links a dot, the tip a ring.
    Vec2 joints[ArmRobot::kMaxLinks + 1];
    arm_joints(*arm, q, joints);
    const int n = arm->links();
    for (int i = 0; i < n; ++i) dl->AddLine(view.to_screen(joints[i]), view.to_screen(joints[i + 1]), color, thickness);
    dl->AddCircleFilled(view.to_screen(joints[0]), thickness + 2.0f, theme::kInk, 16);
    for (int i = 1; i < n; ++i) dl->AddCircleFilled(view.to_screen(joints[i]), thickness + 1.0f, color, 16);
    dl->AddCircle(view.to_screen(joints[n]), thickness, color, 12, 1.5f);
  } else if (const auto* poly = std::get_if<PolygonRobot>(&robot)) {
    Polygon world;
    polygon_pose(*poly, q, world);
    view.draw_polygon(world, theme::with_alpha(color, 70), color, thickness * 0.6f);
    dl->AddCircleFilled(view.to_screen(Vec2(q[0], q[1])), 3.0f, color, 12);
  } else {
    dl->AddCircleFilled(view.to_screen(Vec2(q[0], q[1])), thickness + 2.0f, color, 16);
  }
}

void draw_chart_segment(const WorkspaceView& view, const Space& space, const Config& a, const Config& delta,
                        ImU32 color, float thickness) {
  ImDrawList* dl = view.draw_list();
  const bool wraps = space.coordinate(0).angular || space.coordinate(1).angular;
  const Vec2 p(a[0], a[1]), d(delta[0], delta[1]);
  if (!wraps) {
    dl->AddLine(view.to_screen(p), view.to_screen(p + d), color, thickness);
    return;
  }
  // Walk the segment across the square [-pi, pi)^2, cutting it where a coordinate wraps.
  Vec2 from = p;
  double left = 1.0;  // fraction of delta still to draw
  for (int piece = 0; piece < 4 && left > 1e-12; ++piece) {
    double cut = left;  // fraction of delta until the next seam
    for (int axis = 0; axis < 2; ++axis) {
      if (!space.coordinate(axis).angular || d[axis] == 0.0) continue;
      const double bound = d[axis] > 0 ? kPi : -kPi;
      const double f = (bound - from[axis]) / d[axis];
      if (f >= 0.0 && f < cut) cut = f;
    }
    const Vec2 to = from + cut * d;
    dl->AddLine(view.to_screen(from), view.to_screen(to), color, thickness);
    left -= cut;
    from = to;
    for (int axis = 0; axis < 2; ++axis)
      if (space.coordinate(axis).angular && left > 1e-12) {
        if (from[axis] >= kPi - 1e-12 && d[axis] > 0) from[axis] -= kTwoPi;
        if (from[axis] <= -kPi + 1e-12 && d[axis] < 0) from[axis] += kTwoPi;
      }
  }
}

namespace {

// Thin quads and squares written straight into the draw list: a roadmap has tens of thousands
// of edges, and ImGui's general AddLine/AddCircle cost several times the vertices and time.
// Quads are not anti-aliased; at about a pixel wide and half transparent they need not be.
class Batch {
 public:
  explicit Batch(ImDrawList* dl) : dl_(dl), uv_(ImGui::GetFontTexUvWhitePixel()) {}
  void segment(ImVec2 a, ImVec2 b, ImU32 col, float width) {
    float dx = b.x - a.x, dy = b.y - a.y;
    const float len2 = dx * dx + dy * dy;
    if (len2 <= 0.0f) return;
    const float k = 0.5f * width / std::sqrt(len2);
    dx *= k;
    dy *= k;
    quad(ImVec2(a.x - dy, a.y + dx), ImVec2(b.x - dy, b.y + dx), ImVec2(b.x + dy, b.y - dx), ImVec2(a.x + dy, a.y - dx),
         col);
  }
  void square(ImVec2 c, float half, ImU32 col) {
    quad(ImVec2(c.x - half, c.y - half), ImVec2(c.x + half, c.y - half), ImVec2(c.x + half, c.y + half),
         ImVec2(c.x - half, c.y + half), col);
  }

 private:
  void quad(ImVec2 a, ImVec2 b, ImVec2 c, ImVec2 d, ImU32 col) {
    dl_->PrimReserve(6, 4);
    const ImDrawIdx i = dl_->_VtxCurrentIdx;
    dl_->PrimWriteIdx(i);
    dl_->PrimWriteIdx(i + 1);
    dl_->PrimWriteIdx(i + 2);
    dl_->PrimWriteIdx(i);
    dl_->PrimWriteIdx(i + 2);
    dl_->PrimWriteIdx(i + 3);
    dl_->PrimWriteVtx(a, uv_, col);
    dl_->PrimWriteVtx(b, uv_, col);
    dl_->PrimWriteVtx(c, uv_, col);
    dl_->PrimWriteVtx(d, uv_, col);
  }
  ImDrawList* dl_;
  ImVec2 uv_;
};

}  // namespace

void draw_roadmap(const WorkspaceView& view, const Space& space, const Roadmap& roadmap,
                  const std::vector<int>& labels, const std::vector<unsigned char>* checked) {
  const auto& v = roadmap.vertices;
  ImDrawList* dl = view.draw_list();
  Batch batch(dl);
  const bool wraps = space.coordinate(0).angular || space.coordinate(1).angular;
  // Dense roadmaps get fainter edges, so that structure (and the path) stays readable.
  const auto alpha = static_cast<unsigned>(
      std::clamp(150.0 * std::sqrt(2000.0 / std::max<double>(1.0, static_cast<double>(roadmap.edges.size()))), 45.0, 150.0));
  // Past kMaxDrawnEdges, one edge in `every` (edges come vertex by vertex, so that thins the
  // picture evenly): 577000 edges (20000 samples, k = 50) took 700 ms a frame to draw in the
  // headless browser's software WebGL, and hold 2.3 million vertices on any GPU.
  std::size_t alive = 0;
  for (const RoadmapEdge& e : roadmap.edges) alive += e.alive ? 1 : 0;
  const std::size_t every = (alive + kMaxDrawnEdges - 1) / kMaxDrawnEdges;
  std::size_t seen = 0;
  const ImVec2 lo = view.canvas_min(), hi = view.canvas_max();
  for (std::size_t i = 0; i < roadmap.edges.size(); ++i) {
    const RoadmapEdge& e = roadmap.edges[i];
    if (!e.alive) continue;
    if (every > 1 && seen++ % every != 0) continue;
    const Config& a = v[static_cast<std::size_t>(e.a)];
    const int c = labels.empty() ? 0 : labels[static_cast<std::size_t>(e.a)];
    const bool trusted = checked && i < checked->size() && (*checked)[i] == 0;
    if (wraps) {
      // Seam-crossing edges are cut into pieces; the general path handles them (an unchecked
      // edge fainter: dashes would need the pieces' lengths).
      draw_chart_segment(view, space, a, space.difference(a, v[static_cast<std::size_t>(e.b)]),
                         theme::component_color(c, trusted ? alpha / 3 : alpha), 1.0f);
    } else if (trusted) {
      const Config& b = v[static_cast<std::size_t>(e.b)];
      const ImVec2 sa = view.to_screen(Vec2(a[0], a[1])), sb = view.to_screen(Vec2(b[0], b[1]));
      if ((sa.x < lo.x && sb.x < lo.x) || (sa.x > hi.x && sb.x > hi.x) || (sa.y < lo.y && sb.y < lo.y) ||
          (sa.y > hi.y && sb.y > hi.y))
        continue;
      // Never checked: dashed, 5 px on and 4 off, so that it reads as "not known to be free".
      const float dx = sb.x - sa.x, dy = sb.y - sa.y, len = std::sqrt(dx * dx + dy * dy);
      const int dashes = std::min(200, static_cast<int>(len / 9.0f) + 1);
      for (int d = 0; d < dashes; ++d) {
        const float t0 = static_cast<float>(d) * 9.0f / std::max(len, 1.0f);
        const float t1 = std::min(1.0f, t0 + 5.0f / std::max(len, 1.0f));
        if (t0 >= 1.0f) break;
        batch.segment(ImVec2(sa.x + dx * t0, sa.y + dy * t0), ImVec2(sa.x + dx * t1, sa.y + dy * t1),
                      theme::component_color(c, alpha), 1.2f);
      }
    } else {
      const Config& b = v[static_cast<std::size_t>(e.b)];
      const ImVec2 sa = view.to_screen(Vec2(a[0], a[1])), sb = view.to_screen(Vec2(b[0], b[1]));
      // Zoomed in: an edge wholly to one side of the canvas is not drawn.
      if ((sa.x < lo.x && sb.x < lo.x) || (sa.x > hi.x && sb.x > hi.x) || (sa.y < lo.y && sb.y < lo.y) ||
          (sa.y > hi.y && sb.y > hi.y))
        continue;
      batch.segment(sa, sb, theme::component_color(c, alpha), 1.2f);
    }
  }
  // Vertices as squares with a dark rim, large enough to find and count while the roadmap is
  // small (6 px across up to 400 vertices), smaller as it fills the view (a 20000-vertex
  // roadmap of 6 px squares hides its own edges); never below 4 px (they were 3.6 px, no rim).
  const double n = static_cast<double>(v.size());
  const float half = n <= 400 ? 3.0f : n <= 3000 ? 2.5f : 2.0f;
  for (std::size_t i = 2; i < v.size(); ++i) {
    const int c = labels.empty() ? 0 : labels[i];
    const ImVec2 at = view.to_screen(Vec2(v[i][0], v[i][1]));
    // (Past 3000 vertices no rim: twice the quads for a rim too small to see.)
    if (n <= 3000) batch.square(at, half + 1.0f, theme::with_alpha(theme::kInk, 200));
    batch.square(at, half, theme::component_color(c));
  }
  if (every > 1) {
    char text[96];
    std::snprintf(text, sizeof text, "showing 1 in %zu of %zu edges (too many to draw)", every, alive);
    // At the bottom left of what is visible (the caller's clip rectangle: the world's part).
    const ImVec2 clip_lo = dl->GetClipRectMin(), clip_hi = dl->GetClipRectMax();
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 at(clip_lo.x + 8.0f, clip_hi.y - size.y - 8.0f);
    dl->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + size.x + 4, at.y + size.y + 2), theme::with_alpha(theme::kLabelBox, 230), 3.0f);
    dl->AddText(at, theme::kLabel, text);
  }
}

void RoadmapLayer::draw(const WorkspaceView& view, const Space& space, const Roadmap& roadmap,
                        const std::vector<int>& labels, long long version, const std::vector<unsigned char>* checked) {
  ImDrawList* dl = view.draw_list();
  const ImVec2 origin = view.to_screen(Vec2(0, 0)), unit = view.to_screen(Vec2(1, 1));
  const bool same = version == version_ && origin.x == origin_.x && origin.y == origin_.y && unit.x == unit_.x &&
                    unit.y == unit_.y;
  if (!same) {
    // Draw afresh, then keep what was added to the draw list.
    const int vtx_start = dl->VtxBuffer.Size, idx_start = dl->IdxBuffer.Size;
    const unsigned base = dl->_VtxCurrentIdx;
    draw_roadmap(view, space, roadmap, labels, checked);
    vertices_.resize(dl->VtxBuffer.Size - vtx_start);
    std::memcpy(vertices_.Data, dl->VtxBuffer.Data + vtx_start, sizeof(ImDrawVert) * static_cast<std::size_t>(vertices_.Size));
    indices_.resize(dl->IdxBuffer.Size - idx_start);
    for (int i = 0; i < indices_.Size; ++i) indices_[i] = dl->IdxBuffer[idx_start + i] - base;
    version_ = version;
    origin_ = origin;
    unit_ = unit;
    return;
  }
  dl->PrimReserve(indices_.Size, vertices_.Size);
  std::memcpy(dl->_VtxWritePtr, vertices_.Data, sizeof(ImDrawVert) * static_cast<std::size_t>(vertices_.Size));
  const ImDrawIdx base = dl->_VtxCurrentIdx;
  for (int i = 0; i < indices_.Size; ++i) dl->_IdxWritePtr[i] = base + indices_[i];
  dl->_VtxWritePtr += vertices_.Size;
  dl->_IdxWritePtr += indices_.Size;
  dl->_VtxCurrentIdx += static_cast<unsigned>(vertices_.Size);
}

void draw_rejected_samples(const WorkspaceView& view, const std::vector<Config>& rejected) {
  ImDrawList* dl = view.draw_list();
  for (const Config& q : rejected) {
    const ImVec2 c = view.to_screen(Vec2(q[0], q[1]));
    dl->AddLine(ImVec2(c.x - 3, c.y - 3), ImVec2(c.x + 3, c.y + 3), theme::kHit, 1.5f);
    dl->AddLine(ImVec2(c.x - 3, c.y + 3), ImVec2(c.x + 3, c.y - 3), theme::kHit, 1.5f);
  }
}

void draw_path(const WorkspaceView& view, const Space& space, const Roadmap& roadmap, const std::vector<int>& path) {
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      const Config& a = roadmap.vertices[static_cast<std::size_t>(path[i])];
      const Config& b = roadmap.vertices[static_cast<std::size_t>(path[i + 1])];
      draw_chart_segment(view, space, a, space.difference(a, b), pass == 0 ? theme::kPathOutline : theme::kPath,
                         pass == 0 ? 6.0f : 3.5f);
    }
}

}  // namespace csl::app
