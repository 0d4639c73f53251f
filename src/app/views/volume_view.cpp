#include "app/views/volume_view.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "app/shell/theme.hpp"
#include "core/base/angles.hpp"

namespace csl::app {

void VolumeView::set_volume(const CSpaceVolume& v, const Vec3& half) {
  faces_.clear();
  half_ = half;
  nz_ = std::max(v.nz, 1);
  const auto blocked = [&](int i, int j, int k) {
    // Outside the block counts as free: a C-obstacle that reaches a face is closed there (its
    // twin across a glued face shows where it goes on).
    if (i < 0 || j < 0 || k < 0 || i >= v.nx || j >= v.ny || k >= v.nz) return false;
    return v.cells[static_cast<std::size_t>((k * v.ny + j) * v.nx + i)] == 0;
  };
  const Vec3 cell(2.0 * half.x() / v.nx, 2.0 * half.y() / v.ny, 2.0 * half.z() / v.nz);
  const auto corner = [&](int i, int j, int k) {
    return Vec3(-half.x() + i * cell.x(), -half.y() + j * cell.y(), -half.z() + k * cell.z());
  };
  // The six neighbours, each with the corners (in cell offsets) of the face towards it.
  static const int kDir[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const int kQuad[6][4][3] = {
      {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}, {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}};
  for (int k = 0; k < v.nz; ++k)
    for (int j = 0; j < v.ny; ++j)
      for (int i = 0; i < v.nx; ++i) {
        if (!blocked(i, j, k)) continue;
        for (int d = 0; d < 6; ++d) {
          if (blocked(i + kDir[d][0], j + kDir[d][1], k + kDir[d][2])) continue;
          Face f;
          for (int c = 0; c < 4; ++c) f.corner[c] = corner(i + kQuad[d][c][0], j + kQuad[d][c][1], k + kQuad[d][c][2]);
          f.normal = Vec3(kDir[d][0], kDir[d][1], kDir[d][2]);
          f.layer = k;
          faces_.push_back(f);
        }
      }
}

bool VolumeView::begin(const char* id, ImVec2 size, double& cut) {
  const double before = cut;
  const ImVec2 at = ImGui::GetCursorScreenPos();
  size.x = std::max(size.x, kStripWidth + 40.0f);
  size.y = std::max(size.y, 40.0f);
  // The block's half diagonal fits the shorter side at zoom 1, whatever the turn, under the
  // caption's line (on a phone the caption crossed the block's top corner).
  SurfaceView::begin(id, ImVec2(size.x - kStripWidth, size.y), half_.norm() * 1.05 / zoom_,
                     ImGui::GetTextLineHeightWithSpacing());
  const ImGuiIO& io = ImGui::GetIO();
  if (hovered()) {
    if (io.MouseWheel != 0.0f) zoom_ = std::clamp(zoom_ * std::pow(1.2, static_cast<double>(io.MouseWheel)), kMinZoom, kMaxZoom);
    const auto key = [](ImGuiKey k) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(k), true); };
    double turn = yaw(), tilt = pitch();
    if (key(ImGuiKey_LeftArrow)) turn -= 0.1;
    if (key(ImGuiKey_RightArrow)) turn += 0.1;
    if (key(ImGuiKey_UpArrow)) tilt -= 0.1;
    if (key(ImGuiKey_DownArrow)) tilt += 0.1;
    set_angles(wrap_angle(turn), std::clamp(tilt, -kMaxPitch, kMaxPitch));
    if (key(ImGuiKey_PageUp)) cut += 1.0 / nz_;
    if (key(ImGuiKey_PageDown)) cut -= 1.0 / nz_;
  }
  // The strip: the cut axis from bottom (0) to top (1); a press or a drag puts the plane there.
  ImGui::SetCursorScreenPos(ImVec2(at.x + size.x - kStripWidth, at.y));
  ImGui::InvisibleButton("##cut-strip", ImVec2(kStripWidth, size.y));
  strip_min_ = ImGui::GetItemRectMin();
  strip_max_ = ImGui::GetItemRectMax();
  const float pad = 12.0f, top = strip_min_.y + pad, bottom = strip_max_.y - pad;
  if (ImGui::IsItemActive()) cut = static_cast<double>((bottom - io.MousePos.y) / (bottom - top));
  cut = std::clamp(cut, 0.0, 1.0);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float mid = 0.5f * (strip_min_.x + strip_max_.x);
  dl->AddRectFilled(strip_min_, strip_max_, theme::kCanvasBg);
  dl->AddLine(ImVec2(mid, top), ImVec2(mid, bottom), theme::kFrame, 3.0f);
  const float y = bottom - static_cast<float>(cut) * (bottom - top);
  dl->AddRectFilled(ImVec2(strip_min_.x + 4, y - 4), ImVec2(strip_max_.x - 4, y + 4), theme::kSelectedEdge, 3.0f);
  ImGui::SetCursorScreenPos(ImVec2(at.x, at.y + size.y));
  ImGui::Dummy(ImVec2(0, 0));
  return cut != before;
}

Vec3 VolumeView::point(const Vec3& u) const {
  return Vec3((2.0 * u.x() - 1.0) * half_.x(), (2.0 * u.y() - 1.0) * half_.y(), (2.0 * u.z() - 1.0) * half_.z());
}

void VolumeView::draw_half(double cut, bool below) const {
  SurfaceMesh mesh;
  const double split = cut * nz_;
  // The half the plane hides from the viewer is drawn opaque; the one in front of it faint.
  const bool front = below != facing(Vec3(0, 0, 1));
  const ImU32 color = front ? theme::with_alpha(theme::kCObstacle, 40) : theme::with_alpha(theme::kCObstacle, 255);
  for (const Face& f : faces_) {
    // Faces turned away are hidden behind the solid's own (or, at the cut, by the plane): not
    // drawn, which halves the work and keeps the faint half from piling up into grey.
    if ((f.layer + 0.5 < split) != below || !facing(f.normal)) continue;
    SurfaceMesh::Face m;
    for (int c = 0; c < 4; ++c) m.corner[c] = f.corner[c];
    m.normal = f.normal;
    m.color = color;
    mesh.faces.push_back(m);
  }
  draw_mesh(mesh);
}

void VolumeView::draw_plane_frame(double cut) const {
  std::vector<Vec2> square{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  fill_in_plane(square, cut, theme::with_alpha(theme::kCanvasBg, 150));  // dims what lies beyond
  ImDrawList* dl = ImGui::GetWindowDrawList();
  for (int c = 0; c < 4; ++c) {
    const Vec2 a = square[static_cast<std::size_t>(c)], b = square[static_cast<std::size_t>((c + 1) % 4)];
    dl->AddLine(project(point(Vec3(a.x(), a.y(), cut))), project(point(Vec3(b.x(), b.y(), cut))), theme::kSelectedEdge, 2.0f);
  }
}

void VolumeView::fill_in_plane(const std::vector<Vec2>& unit_xy, double cut, ImU32 color) const {
  if (unit_xy.size() < 3) return;
  std::vector<ImVec2> screen;
  screen.reserve(unit_xy.size());
  for (const Vec2& p : unit_xy) screen.push_back(project(point(Vec3(p.x(), p.y(), cut))));
  ImGui::GetWindowDrawList()->AddConvexPolyFilled(screen.data(), static_cast<int>(screen.size()), color);
}

namespace {
// Clips the segment p + t d, t in [0, 1], to the unit cube: false if nothing is left.
bool clip_unit(const Vec3& p, const Vec3& d, double& t0, double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  for (int a = 0; a < 3; ++a) {
    if (std::fabs(d[a]) < 1e-15) {
      if (p[a] < -1e-12 || p[a] > 1 + 1e-12) return false;
      continue;
    }
    double lo = (0.0 - p[a]) / d[a], hi = (1.0 - p[a]) / d[a];
    if (lo > hi) std::swap(lo, hi);
    t0 = std::max(t0, lo);
    t1 = std::min(t1, hi);
  }
  return t1 > t0;
}
}  // namespace

void VolumeView::draw_segment(const Vec3& a, const Vec3& d, const bool glued[3], ImU32 color, float thickness) const {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  // Each copy of the segment shifted by a whole turn along glued axes: the pieces inside the
  // block are where it leaves through a face and comes back through the twin.
  int range[3][2];
  for (int k = 0; k < 3; ++k) {
    range[k][0] = glued[k] ? -1 : 0;
    range[k][1] = glued[k] ? 1 : 0;
  }
  for (int sx = range[0][0]; sx <= range[0][1]; ++sx)
    for (int sy = range[1][0]; sy <= range[1][1]; ++sy)
      for (int sz = range[2][0]; sz <= range[2][1]; ++sz) {
        const Vec3 p = a + Vec3(sx, sy, sz);
        double t0, t1;
        if (!clip_unit(p, d, t0, t1)) continue;
        dl->AddLine(project(point(p + t0 * d)), project(point(p + t1 * d)), color, thickness);
      }
}

void VolumeView::draw_point(const Vec3& u, ImU32 color, float radius, const char* label) const {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 s = project(point(u));
  dl->AddCircleFilled(s, radius, color, 16);
  dl->AddCircle(s, radius, theme::kCanvasBg, 16, 2.0f);
  if (label) dl->AddText(ImVec2(s.x + radius + 2, s.y - radius - 10), theme::kLabel, label);
}

void VolumeView::draw_frame(const char* x_name, const char* y_name, const char* z_name) const {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  for (int e = 0; e < 12; ++e) {
    // Edge e runs along axis e / 4 with the other two coordinates the bits of e % 4.
    const int axis = e / 4, bits = e % 4;
    Vec3 a, b;
    for (int k = 0, bit = 0; k < 3; ++k) {
      if (k == axis) {
        a[k] = 0;
        b[k] = 1;
      } else {
        a[k] = b[k] = (bits >> bit++) & 1;
      }
    }
    dl->AddLine(project(point(a)), project(point(b)), theme::kFrame, 1.0f);
  }
  const auto label = [&](const Vec3& u, const char* text) {
    const ImVec2 s = project(point(u));
    dl->AddText(ImVec2(s.x + 3, s.y - 8), theme::kLabel, text);
  };
  label(Vec3(1.08, 0, 0), x_name);
  label(Vec3(0, 1.08, 0), y_name);
  // The vertical axis's name beside the leftmost of the four vertical edges, outside the block
  // (at the top of the edge through the origin it sat inside the block from most angles).
  ImVec2 mid(FLT_MAX, 0);
  for (int bits = 0; bits < 4; ++bits) {
    const ImVec2 m = project(point(Vec3(bits & 1, bits >> 1, 0.5)));
    if (m.x < mid.x) mid = m;
  }
  dl->AddText(ImVec2(mid.x - ImGui::CalcTextSize(z_name).x - 6, mid.y - 8), theme::kLabel, z_name);
}

}  // namespace csl::app
