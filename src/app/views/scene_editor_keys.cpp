// The scene editor by keyboard alone: a focus among the editable things (start, goal, each
// obstacle and its handles) drawn as a ring, arrows that move it, + and - that resize it, and
// Enter that places a new obstacle in the middle of the view. Everything a drag does, a key
// does too, with the same refusals; a press (or a held burst of repeats) is one undo step.
#include <algorithm>
#include <cmath>
#include <string>

#include "app/shell/theme.hpp"
#include "app/views/scene_editor.hpp"
#include "core/base/angles.hpp"
#include "core/base/overloaded.hpp"
#include "imgui_internal.h"  // the navigation request the arrows must not also feed

namespace csl::app {
namespace {

// A step is about this fraction of the view's visible width: a press moves things far enough to
// see, fifty presses cross the view. Shift makes it ten times finer.
constexpr double kStepsAcross = 50.0;
constexpr double kFine = 0.1;
// What Enter places, in steps: a disk's radius, half a wall, half a square's side.
constexpr double kNewSize = 5.0;
// + and - scale a polygon about its centroid by this.
constexpr double kScaleBy = 0.1;

bool pressed(ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), true); }

// x rounded down to 1, 2 or 5 times a power of ten: keyed moves keep coordinates readable
// (0.5, 0.52, 0.54 rather than 0.5, 0.5263, ...).
double nice_floor(double x) {
  if (!(x > 0) || !std::isfinite(x)) return 0.0;
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  const double m = x / p;
  constexpr double kSlack = 1e-9;  // log10 and pow round: 0.02 may come out as 1.9999999 p
  return (m >= 5.0 - kSlack ? 5.0 : m >= 2.0 - kSlack ? 2.0 : 1.0) * p;
}

// The keyboard's step in `view`: from what it shows now, so a zoomed-in view moves finely.
double key_step(const WorkspaceView& view) {
  if (view.scale() <= 0.0f) return 0.0;
  const double width = static_cast<double>(view.canvas_max().x - view.canvas_min().x) / static_cast<double>(view.scale());
  return nice_floor(width / kStepsAcross);
}

Vec2 centroid(const std::vector<Vec2>& vertices) {
  Vec2 sum(0, 0);
  for (const Vec2& v : vertices) sum += v;
  return sum / static_cast<double>(vertices.size());
}

int handle_count(const Obstacle& o) {
  return std::visit(Overloaded{[](const Disk&) { return 0; },  // its size: + and -
                               [](const PolygonObstacle& g) { return static_cast<int>(g.vertices.size()); },
                               [](const Wall&) { return 2; }},
                    o);
}

Vec2 handle_point(const Obstacle& o, int handle) {
  return std::visit(Overloaded{[&](const Disk& d) { return d.center; },
                               [&](const PolygonObstacle& g) { return g.vertices[static_cast<std::size_t>(handle)]; },
                               [&](const Wall& w) { return handle == 0 ? w.a : w.b; }},
                    o);
}

// The arrows moved what has the focus: ImGui's keyboard navigation, which read the same arrows
// when the frame began, must not also walk its cursor through the panel (and scroll it).
void keep_arrows_from_nav() {
  ImGuiContext& g = *ImGui::GetCurrentContext();
  if (g.NavMoveSubmitted) ImGui::NavMoveRequestCancel();
  if (g.NavInitRequestFromMove) {  // a move with no item focused asks for the first one
    g.NavInitRequest = g.NavInitRequestFromMove = false;
    g.NavInitResultId = 0;
  }
}

// The focus ring: dark outside, yellow inside, so it shows on the white canvas and on a dark
// obstacle alike, and is told from the selection (blue) and the warnings (orange).
void ring_circle(ImDrawList* dl, ImVec2 c, float r) {
  dl->AddCircle(c, r, theme::kBlack, 48, 5.0f);
  dl->AddCircle(c, r, theme::kYellow, 48, 2.5f);
}

void ring_rect(ImDrawList* dl, ImVec2 a, ImVec2 b) {
  dl->AddRect(a, b, theme::kBlack, 6.0f, 0, 5.0f);
  dl->AddRect(a, b, theme::kYellow, 6.0f, 0, 2.5f);
}

// Under the ring: what the keys do to it (the ? window lists them all).
void ring_caption(ImDrawList* dl, ImVec2 at, const char* text) {
  const ImVec2 size = ImGui::CalcTextSize(text);
  dl->AddRectFilled(ImVec2(at.x - 3, at.y - 1), ImVec2(at.x + size.x + 3, at.y + size.y + 1),
                    theme::kLabelBox, 3.0f);
  dl->AddText(at, theme::kLabel, text);
}

}  // namespace

SceneEditor::Focus SceneEditor::focus() const {
  if (focus_ == Focus::Obstacle && selected_ < 0) return Focus::None;  // deleted, undone, deselected
  return focus_;
}

void SceneEditor::cycle_focus(const Scene& scene, const Options& options, int by) {
  // The order of the cycle: start, goal (when the keyboard can move them), then the obstacles.
  const bool ends = options.endpoints_are_points || options.angle_view;
  const int first_obstacle = ends ? 2 : 0;
  const int count = first_obstacle + static_cast<int>(scene.obstacles.size());
  if (count == 0) {
    return;
  }
  int at = -1;
  switch (focus()) {
    case Focus::Start: at = ends ? 0 : -1; break;
    case Focus::Goal: at = ends ? 1 : -1; break;
    case Focus::Obstacle: at = first_obstacle + selected_; break;
    case Focus::None: break;
  }
  at = at < 0 ? (by > 0 ? 0 : count - 1) : ((at + by) % count + count) % count;
  focus_handle_ = -1;
  if (at < first_obstacle) {
    focus_ = at == 0 ? Focus::Start : Focus::Goal;
    selected_ = -1;  // Delete must not remove an obstacle the ring has left
  } else {
    focus_ = Focus::Obstacle;
    selected_ = at - first_obstacle;
  }
}

void SceneEditor::cycle_handle(const Scene& scene, int by) {
  if (focus() != Focus::Obstacle) return;
  const int count = handle_count(scene.obstacles[static_cast<std::size_t>(selected_)]);
  // -1 (the whole obstacle), 0, ..., count - 1, round.
  focus_handle_ = ((focus_handle_ + 1 + by) % (count + 1) + count + 1) % (count + 1) - 1;
}

bool SceneEditor::move_focused(Scene& scene, LabContext& ctx, const Options& options, const Vec2& by) {
  const Focus f = focus();
  if (f == Focus::Start || f == Focus::Goal) {
    Config& q = f == Focus::Start ? scene.start : scene.goal;
    Config moved = q;
    if (options.endpoints_are_points) {
      // Inside the workspace (the point robot's configuration space), as a drag keeps them.
      moved[0] = std::clamp(q[0] + by.x(), scene.workspace_min.x(), scene.workspace_max.x());
      moved[1] = std::clamp(q[1] + by.y(), scene.workspace_min.y(), scene.workspace_max.y());
    } else {
      moved[0] = wrap_angle(q[0] + by.x());  // round the torus, as the square's edges meet
      moved[1] = wrap_angle(q[1] + by.y());
    }
    if (moved == q) return false;
    q = moved;
    return true;
  }
  if (f != Focus::Obstacle) return false;
  Obstacle& o = scene.obstacles[static_cast<std::size_t>(selected_)];
  Obstacle moved = o;
  if (focus_handle_ < 0) {
    translate(moved, by);
  } else if (auto* g = std::get_if<PolygonObstacle>(&moved)) {
    g->vertices[static_cast<std::size_t>(focus_handle_)] += by;
    if (*polygon_problem(g->vertices)) {
      ctx.notify("That vertex position would make the polygon cross itself.", 2.0);
      return false;
    }
  } else if (auto* w = std::get_if<Wall>(&moved)) {
    (focus_handle_ == 0 ? w->a : w->b) += by;
  }
  if (const std::string problem = obstacle_problem(moved, "moved obstacle"); !problem.empty()) {
    ctx.notify("Refused: " + problem, 3.0);
    return false;
  }
  o = std::move(moved);
  return true;
}

bool SceneEditor::resize_focused(Scene& scene, LabContext& ctx, double step, int sign) {
  const Focus f = focus();
  if (f == Focus::Start || f == Focus::Goal) {
    ctx.notify("Start and goal have no size: the arrows move them.", 2.0);
    return false;
  }
  if (f != Focus::Obstacle) return false;
  Obstacle& o = scene.obstacles[static_cast<std::size_t>(selected_)];
  Obstacle resized = o;
  const char* refusal = nullptr;
  std::visit(Overloaded{[&](Disk& d) {
                          d.radius += sign * step;
                          if (d.radius <= 0.0) refusal = "Refused: a disk's radius must stay above zero.";
                        },
                        [&](PolygonObstacle& g) {
                          const Vec2 c = centroid(g.vertices);
                          const double k = 1.0 + sign * kScaleBy;
                          for (Vec2& v : g.vertices) v = c + k * (v - c);
                        },
                        [&](Wall& w) {
                          // Both ends along the wall, half a step each: the length changes by a step.
                          const double len = length(w.b - w.a);
                          if (len + sign * step <= 0.0) {
                            refusal = "Refused: a wall's length must stay above zero.";
                            return;
                          }
                          const Vec2 along = (w.b - w.a) / len * (0.5 * sign * step);
                          w.a -= along;
                          w.b += along;
                        }},
             resized);
  if (refusal) {
    ctx.notify(refusal, 2.0);
    return false;
  }
  if (const std::string problem = obstacle_problem(resized, "resized obstacle"); !problem.empty()) {
    ctx.notify("Refused: " + problem, 3.0);
    return false;
  }
  o = std::move(resized);
  return true;
}

bool SceneEditor::place(WorkspaceView& view, Scene& scene, LabContext& ctx) {
  const double s = key_step(view);
  if (s <= 0.0) return false;
  // The middle of what the view shows, kept inside the workspace (a zoomed or panned view may
  // show its outside).
  const ImVec2 mid(0.5f * (view.canvas_min().x + view.canvas_max().x), 0.5f * (view.canvas_min().y + view.canvas_max().y));
  Vec2 c = view.to_world(mid);
  c = Vec2(std::clamp(c.x(), scene.workspace_min.x(), scene.workspace_max.x()),
           std::clamp(c.y(), scene.workspace_min.y(), scene.workspace_max.y()));
  const double h = kNewSize * s;
  Obstacle o = Disk{c, h};
  if (tool_ == Tool::Wall) o = Wall{c - Vec2(h, 0), c + Vec2(h, 0)};
  if (tool_ == Tool::Polygon)  // a square; H and the arrows move its vertices
    o = PolygonObstacle{{c + Vec2(-h, -h), c + Vec2(h, -h), c + Vec2(h, h), c + Vec2(-h, h)}};
  if (!add_obstacle(scene, std::move(o), ctx)) return false;
  focus_ = Focus::Obstacle;  // add_obstacle selected it: the arrows move it now
  focus_handle_ = -1;
  return true;
}

bool SceneEditor::handle_edit_keys(WorkspaceView& view, Scene& scene, LabContext& ctx, const Options& options,
                                   bool enter_places) {
  const ImGuiIO& io = ImGui::GetIO();
  // A burst ends when every key is up: its repeats were one undo step, as one drag is.
  if (key_burst_ && std::none_of(std::begin(io.KeysDown), std::end(io.KeysDown), [](bool d) { return d; }))
    key_burst_ = false;
  if (io.WantTextInput || io.KeyCtrl || io.KeyAlt || drag_ != Drag::None) return false;
  // What the focus held may be gone: an obstacle deleted or undone, the arm's square hidden.
  if (focus() == Focus::None) focus_ = Focus::None;
  if ((focus_ == Focus::Start || focus_ == Focus::Goal) && !options.endpoints_are_points && !options.angle_view)
    focus_ = Focus::None;
  if (focus_ != Focus::Obstacle || focus_handle_ >= handle_count(scene.obstacles[static_cast<std::size_t>(selected_)]))
    focus_handle_ = -1;
  const Scene before = scene;
  bool changed = false;

  // Letters come as typed characters (the layout's N, not a key position), as the tools' do.
  for (ImWchar c : io.InputQueueCharacters) {
    switch (c) {
      case 'n': cycle_focus(scene, options, +1); break;
      case 'N': cycle_focus(scene, options, -1); break;
      case 'h': cycle_handle(scene, +1); break;
      case 'H': cycle_handle(scene, -1); break;
      // = and _ are + and - without (or with) Shift on many layouts: either pair works.
      case '+': case '=': changed |= resize_focused(scene, ctx, key_step(view), +1); break;
      case '-': case '_': changed |= resize_focused(scene, ctx, key_step(view), -1); break;
      default: break;
    }
  }

  // (Not repeated: a held Enter places one obstacle, not a stack of them. Not either when it
  // closed a polygon drawn with the mouse this frame: `enter_places` is false then.)
  if (enter_places && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) && tool_ != Tool::Select &&
      polygon_.empty())
    changed |= place(view, scene, ctx);

  Vec2 arrows(0, 0);
  if (pressed(ImGuiKey_LeftArrow)) arrows.x() -= 1;
  if (pressed(ImGuiKey_RightArrow)) arrows.x() += 1;
  if (pressed(ImGuiKey_UpArrow)) arrows.y() += 1;  // the world's y is up
  if (pressed(ImGuiKey_DownArrow)) arrows.y() -= 1;
  if (arrows != Vec2::Zero()) {
    // Nothing focused but an obstacle selected (by the mouse): the arrows take it.
    if (focus() == Focus::None && selected_ >= 0) focus_ = Focus::Obstacle;
    const bool ends = focus() == Focus::Start || focus() == Focus::Goal;
    const WorkspaceView& in = ends && options.angle_view ? *options.angle_view : view;
    const double s = key_step(in) * (io.KeyShift ? kFine : 1.0);
    if (focus() != Focus::None && s > 0.0) {
      changed |= move_focused(scene, ctx, options, arrows * s);
      keep_arrows_from_nav();
    }
  }
  if (changed && !key_burst_) {
    record(before);  // the first change of the burst: its one undo step
    key_burst_ = true;
  }
  return changed;
}

void SceneEditor::draw_focus(const WorkspaceView& view, const Scene& scene) const {
  if (focus() != Focus::Obstacle) return;
  ImDrawList* dl = view.draw_list();
  const Obstacle& o = scene.obstacles[static_cast<std::size_t>(selected_)];
  constexpr float kPad = 8.0f;
  ImVec2 below;  // where the caption goes
  if (const auto* d = std::get_if<Disk>(&o)) {
    const ImVec2 c = view.to_screen(d->center);
    const float r = static_cast<float>(d->radius) * view.scale() + kPad;
    ring_circle(dl, c, r);  // (a disk has no handles: its size is + and -)
    below = ImVec2(c.x - r, c.y + r + 4);
  } else {
    ImVec2 lo(1e9f, 1e9f), hi(-1e9f, -1e9f);
    const auto grow = [&](const Vec2& p) {
      const ImVec2 s = view.to_screen(p);
      lo = ImVec2(std::min(lo.x, s.x), std::min(lo.y, s.y));
      hi = ImVec2(std::max(hi.x, s.x), std::max(hi.y, s.y));
    };
    if (const auto* g = std::get_if<PolygonObstacle>(&o)) {
      for (const Vec2& v : g->vertices) grow(v);
    } else {
      grow(std::get<Wall>(o).a);
      grow(std::get<Wall>(o).b);
    }
    lo = ImVec2(lo.x - kPad, lo.y - kPad);
    hi = ImVec2(hi.x + kPad, hi.y + kPad);
    if (focus_handle_ < 0) ring_rect(dl, lo, hi);
    below = ImVec2(lo.x, hi.y + 4);
  }
  if (focus_handle_ >= 0 && focus_handle_ < handle_count(o)) {
    // A handle has the focus: the ring is on it, the obstacle keeps its selection look.
    const ImVec2 h = view.to_screen(handle_point(o, focus_handle_));
    ring_circle(dl, h, 10.0f);
    below = ImVec2(h.x - 10, h.y + 14);
    ring_caption(dl, below, "arrows move this handle, H the next");
    return;
  }
  ring_caption(dl, below, handle_count(o) > 0 ? "arrows move, +/- size, H its handles" : "arrows move, +/- size");
}

void SceneEditor::draw_endpoint_focus(const WorkspaceView& view, const Scene& scene) const {
  const Focus f = focus();
  if (f != Focus::Start && f != Focus::Goal) return;
  const Config& q = f == Focus::Start ? scene.start : scene.goal;
  const ImVec2 c = view.to_screen(Vec2(q[0], q[1]));
  ImDrawList* dl = view.draw_list();
  dl->PushClipRect(view.canvas_min(), view.canvas_max(), true);
  ring_circle(dl, c, 18.0f);
  ring_caption(dl, ImVec2(c.x - 18, c.y + 22), f == Focus::Start ? "start: arrows move it" : "goal: arrows move it");
  dl->PopClipRect();
}

}  // namespace csl::app
