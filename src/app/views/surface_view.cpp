#include "app/views/surface_view.hpp"

#include <algorithm>
#include <cmath>

#include "app/shell/theme.hpp"
#include "core/base/angles.hpp"

namespace csl::app {

void SurfaceView::begin(const char* id, ImVec2 size, double extent, float top) {
  const ImVec2 at = ImGui::GetCursorScreenPos();
  size.x = std::max(size.x, 40.0f);
  size.y = std::max(size.y, 40.0f);
  ImGui::InvisibleButton(id, size);
  hovered_ = ImGui::IsItemHovered();
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
    const ImVec2 d = ImGui::GetIO().MouseDelta;
    yaw_ = wrap_angle(yaw_ + 0.01 * static_cast<double>(d.x));  // one number per direction: links stay short
    pitch_ = std::clamp(pitch_ + 0.01 * static_cast<double>(d.y), -kMaxPitch, kMaxPitch);
  }
  top = std::clamp(top, 0.0f, 0.5f * size.y);
  centre_ = ImVec2(at.x + 0.5f * size.x, at.y + top + 0.5f * (size.y - top));
  scale_ = 0.5f * std::min(size.x, size.y - top) / static_cast<float>(extent);
  ImGui::GetWindowDrawList()->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), theme::kCanvasBg);
}

Vec3 SurfaceView::rotate(const Vec3& p) const {
  // Turn about z (yaw), then tilt about x (pitch): z ends up pointing (mostly) up the screen.
  const double cy = std::cos(yaw_), sy = std::sin(yaw_), cp = std::cos(pitch_), sp = std::sin(pitch_);
  const Vec3 a(cy * p.x() - sy * p.y(), sy * p.x() + cy * p.y(), p.z());
  return {a.x(), cp * a.y() - sp * a.z(), sp * a.y() + cp * a.z()};
}

ImVec2 SurfaceView::project(const Vec3& p, double* depth) const {
  const Vec3 r = rotate(p);
  if (depth) *depth = -r.y();  // the viewer looks along +y
  return ImVec2(centre_.x + scale_ * static_cast<float>(r.x()), centre_.y - scale_ * static_cast<float>(r.z()));
}

bool SurfaceView::facing(const Vec3& n) const { return rotate(n).y() < 0.0; }

SurfaceMesh::SurfaceMesh(const std::function<SurfacePoint(double, double)>& f, const std::vector<SurfacePatch>& patches) {
  faces.reserve(patches.size());
  for (const SurfacePatch& patch : patches) {
    Face face;
    const double us[4] = {patch.u0, patch.u1, patch.u1, patch.u0};
    const double vs[4] = {patch.va0, patch.va1, patch.vb1, patch.vb0};
    for (int k = 0; k < 4; ++k) face.corner[k] = f(us[k], vs[k]).p;
    face.normal = f(0.5 * (patch.u0 + patch.u1), 0.25 * (vs[0] + vs[1] + vs[2] + vs[3])).n;
    face.color = patch.color;
    faces.push_back(face);
  }
}

namespace {

// The quad's edges moved half a pixel outwards (its corners along the mitres): neighbours need
// not share corners (a strip cut at its own v values meets the next at T-junctions), and
// rasterised edge to edge they leave pinholes. Every edge moves, however thin the quad (moving
// corners away from the centre hardly moves a thin quad's long edges). A corner where an edge
// has no length (a tip) takes its neighbours' edges; mitres are capped at 2 px.
void grow_half_pixel(ImVec2 (&corner)[4]) {
  int index[4], n = 0;
  for (int k = 0; k < 4; ++k) {
    const ImVec2& p = corner[k];
    if (n > 0) {
      const ImVec2& last = corner[index[n - 1]];
      if (std::fabs(p.x - last.x) + std::fabs(p.y - last.y) < 1e-3f) continue;
    }
    index[n++] = k;
  }
  // The last one kept may duplicate the first: the corners after it then follow the first.
  const bool wraps = n > 1 && std::fabs(corner[index[0]].x - corner[index[n - 1]].x) +
                                      std::fabs(corner[index[0]].y - corner[index[n - 1]].y) < 1e-3f;
  const int last_kept = index[n - 1];
  if (wraps) --n;
  if (n < 3) return;
  float area = 0.0f;  // twice the signed area: which side is out
  for (int k = 0; k < n; ++k) {
    const ImVec2 &a = corner[index[k]], &b = corner[index[(k + 1) % n]];
    area += a.x * b.y - b.x * a.y;
  }
  if (area == 0.0f) return;
  const float side = area > 0.0f ? 1.0f : -1.0f;
  ImVec2 normal[4];  // outward unit normal of the edge from corner k to corner k + 1
  for (int k = 0; k < n; ++k) {
    const ImVec2 &a = corner[index[k]], &b = corner[index[(k + 1) % n]];
    const float dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    normal[k] = ImVec2(side * dy / len, -side * dx / len);
  }
  ImVec2 moved[4];
  for (int k = 0; k < n; ++k) {
    const ImVec2 &m = normal[(k + n - 1) % n], &l = normal[k];
    const float dot = m.x * l.x + m.y * l.y;
    // The mitre: both edges move 0.5; (m + l) / (1 + m.l) has length 1/cos(half the turn).
    float sx = m.x + l.x, sy = m.y + l.y, scale = 0.5f / std::max(1.0f + dot, 1e-3f);
    const float length = std::sqrt(sx * sx + sy * sy) * scale;
    if (length > 2.0f) scale *= 2.0f / length;
    moved[k] = ImVec2(corner[index[k]].x + sx * scale, corner[index[k]].y + sy * scale);
  }
  // Corners dropped as duplicates follow the corner they duplicate.
  ImVec2 out[4];
  for (int k = 0, j = 0; k < 4; ++k) {
    while (j + 1 < n && index[j + 1] <= k) ++j;
    out[k] = wraps && k >= last_kept ? moved[0] : moved[j];
  }
  for (int k = 0; k < 4; ++k) corner[k] = out[k];
}

}  // namespace

void SurfaceView::draw_surface(const std::function<SurfacePoint(double, double)>& f, int nu, int nv,
                               const std::function<ImU32(double, double)>& color) const {
  std::vector<SurfacePatch> patches;
  patches.reserve(static_cast<std::size_t>(nu * nv));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u0 = double(i) / nu, u1 = double(i + 1) / nu, v0 = double(j) / nv, v1 = double(j + 1) / nv;
      patches.push_back({u0, u1, v0, v0, v1, v1, color(0.5 * (u0 + u1), 0.5 * (v0 + v1))});
    }
  draw_mesh(SurfaceMesh(f, patches));
}

void SurfaceView::draw_mesh(const SurfaceMesh& mesh) const {
  struct Quad {
    ImVec2 corner[4];
    double depth;
    ImU32 fill;
  };
  std::vector<Quad> quads;
  quads.reserve(mesh.faces.size());
  const Vec3 light = Vec3(-0.4, -0.8, 0.5).normalized();  // in view coordinates
  for (const SurfaceMesh::Face& face : mesh.faces) {
    Quad q;
    q.depth = 0;
    for (int k = 0; k < 4; ++k) {
      double d;
      q.corner[k] = project(face.corner[k], &d);
      q.depth += d;
    }
    grow_half_pixel(q.corner);
    const Vec3 n = rotate(face.normal);
    // Lambert shading; faces turned away (seen through the hole) darker.
    const double lit = 0.45 + 0.55 * std::fabs(n.dot(light));
    const ImU32 c = face.color;
    const auto channel = [&](int shift) {
      return static_cast<unsigned>(std::clamp(lit * ((c >> shift) & 0xFF), 0.0, 255.0));
    };
    q.fill = theme::rgba(channel(0), channel(8), channel(16), (c >> 24) & 0xFF);
    quads.push_back(q);
  }
  std::sort(quads.begin(), quads.end(), [](const Quad& a, const Quad& b) { return a.depth < b.depth; });
  ImDrawList* dl = ImGui::GetWindowDrawList();
  // No anti-aliasing between quads (it would leave seams); the mesh is fine enough.
  const ImDrawListFlags saved = dl->Flags;
  dl->Flags &= ~ImDrawListFlags_AntiAliasedFill;
  for (const Quad& q : quads) dl->AddQuadFilled(q.corner[0], q.corner[1], q.corner[2], q.corner[3], q.fill);
  dl->Flags = saved;
}

void SurfaceView::draw_curve(const std::vector<SurfacePoint>& points, ImU32 color, float thickness) const {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const bool front = facing(points[i].n) && facing(points[i + 1].n);
    dl->AddLine(project(points[i].p), project(points[i + 1].p), front ? color : theme::with_alpha(color, 70),
                front ? thickness : 1.0f);
  }
}

SurfacePoint torus_point(double u, double v, double big, double small) {
  const double a = kTwoPi * u, b = kTwoPi * v;
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  return {Vec3((big + small * cb) * ca, (big + small * cb) * sa, small * sb), Vec3(cb * ca, cb * sa, sb)};
}

SurfacePoint sphere_point(double u, double v) {
  const double a = kTwoPi * u, b = kPi * v;
  const Vec3 p(std::sin(b) * std::cos(a), std::sin(b) * std::sin(a), std::cos(b));
  return {p, p};
}

}  // namespace csl::app
