#include "app/views/scene_editor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/shell/instructor.hpp"
#include "app/shell/theme.hpp"
#include "app/shell/ui.hpp"
#include "app/shell/web_bridge.hpp"
#include "core/base/overloaded.hpp"
#include <nlohmann/json.hpp>

namespace csl::app {
namespace {

constexpr std::size_t kUndoDepth = 200;
constexpr float kGrabPixels = 8.0f;  // how close the mouse must be to a handle

bool key_pressed(ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false); }

// Whether world point p hits obstacle o (inside it, or within `tolerance` of a wall).
bool hits(const Obstacle& o, const Vec2& p, double tolerance) {
  return std::visit(Overloaded{[&](const Disk& d) { return length(p - d.center) <= d.radius + tolerance; },
                               [&](const PolygonObstacle& g) { return point_polygon_distance(p, g.vertices) <= tolerance; },
                               [&](const Wall& w) { return point_segment_distance(p, w.a, w.b) <= tolerance; }},
                    o);
}

Vec2 endpoint(const Config& q) { return Vec2(q[0], q[1]); }

}  // namespace

void SceneEditor::set_tool(Tool t) {
  tool_ = t;
  polygon_.clear();
  if (t != Tool::Select) selected_ = -1;
}

void SceneEditor::record(const Scene& before) {
  undo_.push_back(before);
  if (undo_.size() > kUndoDepth) undo_.erase(undo_.begin());
  redo_.clear();
}

bool SceneEditor::undo(Scene& scene) {
  end_drag(scene);  // a drag in progress becomes its own step, and this undoes it
  if (undo_.empty()) return false;
  redo_.push_back(scene);
  scene = undo_.back();
  undo_.pop_back();
  keep_focus_through(scene);
  return true;
}

bool SceneEditor::redo(Scene& scene) {
  end_drag(scene);
  if (redo_.empty()) return false;
  undo_.push_back(scene);
  scene = redo_.back();
  redo_.pop_back();
  keep_focus_through(scene);
  return true;
}

void SceneEditor::keep_focus_through(const Scene& now) {
  // The mouse's selection ends with an undo or redo; the keyboard's focus stays where it was
  // (one who undoes a press goes on with the same thing) while the obstacle is still there.
  const bool keep = focus_ == Focus::Obstacle && selected_ >= 0 && selected_ < static_cast<int>(now.obstacles.size());
  if (!keep) selected_ = -1;
}

void SceneEditor::clear_history() {
  undo_.clear();
  redo_.clear();
  selected_ = -1;
  drop_drag();  // the scene is a new one: nothing to commit
}

void SceneEditor::replace(Scene& scene, const Scene& next) {
  end_drag(scene);
  record(scene);
  scene = next;
  selected_ = -1;
}

void SceneEditor::end_drag(Scene& scene) {
  // A move or resize is one undo step; a new disk's or wall's preview is dropped.
  if (before_drag_ && drag_ != Drag::NewDisk && drag_ != Drag::NewWall &&
      !same_scene(*before_drag_, scene))
    record(*before_drag_);
  drop_drag();
}

void SceneEditor::drop_drag() {
  before_drag_.reset();
  drag_ = Drag::None;
  target_ = -1;
  handle_ = -1;
  key_burst_ = false;  // a key still held makes its next change a new undo step
}

bool SceneEditor::add_obstacle(Scene& scene, Obstacle o, LabContext& ctx) {
  if (scene.obstacles.size() >= kMaxObstacles) {
    ctx.notify("The scene already has the maximum of 1000 obstacles.");
    return false;
  }
  if (const std::string problem = obstacle_problem(o, "new obstacle"); !problem.empty()) {
    ctx.notify("Refused: " + problem);
    return false;
  }
  record(scene);
  scene.obstacles.push_back(std::move(o));
  selected_ = static_cast<int>(scene.obstacles.size()) - 1;
  return true;
}

bool SceneEditor::finish_polygon(Scene& scene, LabContext& ctx) {
  if (polygon_.size() < 3) {
    ctx.notify("A polygon needs at least 3 vertices: click more, or Esc to cancel.");
    return false;
  }
  PolygonObstacle poly{polygon_};
  if (const char* problem = polygon_problem(poly.vertices); *problem) {
    // Keep the vertices: the user can undo the last one (Backspace) instead of starting over.
    ctx.notify(std::string("Refused: ") + problem + ". Backspace removes the last vertex.");
    return false;
  }
  const bool added = add_obstacle(scene, std::move(poly), ctx);
  if (added) polygon_.clear();
  return added;
}

bool SceneEditor::handle_keys(Scene& scene, LabContext& ctx) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return false;
  bool changed = false;
  if (io.KeyCtrl && key_pressed(ImGuiKey_Z)) {
    changed = io.KeyShift ? redo(scene) : undo(scene);
    if (!changed) ctx.notify(io.KeyShift ? "Nothing to redo." : "Nothing to undo.", 2.0);
  } else if (io.KeyCtrl && key_pressed(ImGuiKey_Y)) {
    changed = redo(scene);
    if (!changed) ctx.notify("Nothing to redo.", 2.0);
  }
  if (key_pressed(ImGuiKey_Escape)) {
    if (drag_ != Drag::None) {
      // Esc in the middle of a drag puts everything back as it was before the press.
      if (before_drag_) {
        changed = true;
        scene = *before_drag_;
      }
      drop_drag();
    } else if (!polygon_.empty()) {
      polygon_.clear();
    } else {
      selected_ = -1;
      focus_ = Focus::None;
    }
  }
  // (Enter with no polygon begun places one by keyboard: handle_edit_keys.)
  if (key_pressed(ImGuiKey_Enter) && tool_ == Tool::Polygon && !polygon_.empty()) changed |= finish_polygon(scene, ctx);
  if (key_pressed(ImGuiKey_Delete) || key_pressed(ImGuiKey_Backspace)) {
    if (!polygon_.empty()) {
      polygon_.pop_back();
    } else if (selected_ >= 0 && selected_ < static_cast<int>(scene.obstacles.size()) && drag_ == Drag::None) {
      record(scene);
      scene.obstacles.erase(scene.obstacles.begin() + selected_);
      selected_ = -1;
      changed = true;
    }
  }
  // Letters come as typed characters, so shortcuts follow the keyboard's layout.
  if (!io.KeyCtrl && !io.KeyAlt)
    for (ImWchar c : io.InputQueueCharacters) {
      switch (c) {
        case 'v': case 'V': set_tool(Tool::Select); break;
        case 'd': case 'D': set_tool(Tool::Disk); break;
        case 'p': case 'P': set_tool(Tool::Polygon); break;
        case 'w': case 'W': set_tool(Tool::Wall); break;
        case '?': show_help_ = !show_help_; break;
        default: break;
      }
    }
  return changed;
}

int SceneEditor::obstacle_under(const Scene& scene, const Vec2& p, double tolerance) {
  for (int i = static_cast<int>(scene.obstacles.size()) - 1; i >= 0; --i)
    if (hits(scene.obstacles[static_cast<std::size_t>(i)], p, tolerance)) return i;
  return -1;
}

bool SceneEditor::begin_drag(WorkspaceView& view, Scene& scene, const Options& options) {
  const Vec2 m = view.mouse_world();
  const double grab = view.reach(kGrabPixels);
  grab_ = m;
  before_drag_ = scene;
  // Endpoints first: they sit on top of everything.
  if (options.endpoints_are_points) {
    if (length(endpoint(scene.goal) - m) <= view.reach(11.0f)) return drag_ = Drag::Goal, true;
    if (length(endpoint(scene.start) - m) <= view.reach(11.0f)) return drag_ = Drag::Start, true;
  }
  if (tool_ == Tool::Disk) return drag_ = Drag::NewDisk, true;
  if (tool_ == Tool::Wall) return drag_ = Drag::NewWall, true;
  if (tool_ == Tool::Polygon) {
    before_drag_.reset();
    return false;  // clicks, not drags: handled in edit()
  }
  // Select tool: the selected obstacle's handles, then any obstacle (topmost first).
  if (selected_ >= 0 && selected_ < static_cast<int>(scene.obstacles.size())) {
    const Obstacle& o = scene.obstacles[static_cast<std::size_t>(selected_)];
    if (const auto* d = std::get_if<Disk>(&o)) {
      // (The inner half is always the body: a finger's reach would make a small disk all rim.)
      const double from_centre = length(m - d->center);
      if (std::fabs(from_centre - d->radius) <= grab && from_centre >= 0.5 * d->radius)
        return target_ = selected_, drag_ = Drag::DiskRim, true;
    } else if (const auto* g = std::get_if<PolygonObstacle>(&o)) {
      for (std::size_t i = 0; i < g->vertices.size(); ++i)
        if (length(g->vertices[i] - m) <= grab)
          return target_ = selected_, handle_ = static_cast<int>(i), drag_ = Drag::Vertex, true;
    } else if (const auto* w = std::get_if<Wall>(&o)) {
      if (length(w->a - m) <= grab) return target_ = selected_, handle_ = 0, drag_ = Drag::WallEnd, true;
      if (length(w->b - m) <= grab) return target_ = selected_, handle_ = 1, drag_ = Drag::WallEnd, true;
    }
  }
  if (const int i = obstacle_under(scene, m, view.pixels(4.0f)); i >= 0) {
    selected_ = target_ = i;
    return drag_ = Drag::Obstacle, true;
  }
  selected_ = -1;
  before_drag_.reset();
  return false;
}

bool SceneEditor::continue_drag(WorkspaceView& view, Scene& scene, LabContext& ctx) {
  const Vec2 m = view.mouse_world();
  const bool down = ImGui::IsMouseDown(ImGuiMouseButton_Left);
  // What is dragged moves by the mouse's offset from the press, from where it was at the press:
  // a press that does not move changes nothing (no jump to the cursor, no replay), and bringing
  // the mouse back to where it was pressed puts the scene back exactly, bit for bit (offsets
  // added frame after frame would drift by rounding).
  if (!before_drag_) {  // begin_drag() sets it for every drag it starts; never drag blind
    drop_drag();
    return false;
  }
  const Vec2 offset = m - grab_;
  const Scene& was = *before_drag_;
  bool changed = false;
  switch (drag_) {
    case Drag::Start:
    case Drag::Goal: {
      Config& q = drag_ == Drag::Start ? scene.start : scene.goal;
      const Config& q0 = drag_ == Drag::Start ? was.start : was.goal;
      // Positions stay inside the workspace (the point robot's configuration space).
      const double x = std::clamp(q0[0] + offset.x(), scene.workspace_min.x(), scene.workspace_max.x());
      const double y = std::clamp(q0[1] + offset.y(), scene.workspace_min.y(), scene.workspace_max.y());
      changed = x != q[0] || y != q[1];
      q[0] = x;
      q[1] = y;
      break;
    }
    case Drag::Obstacle: {
      Obstacle& o = scene.obstacles[static_cast<std::size_t>(target_)];
      Obstacle moved = was.obstacles[static_cast<std::size_t>(target_)];
      if (offset != Vec2::Zero()) translate(moved, offset);
      changed = obstacle_to_json(moved) != obstacle_to_json(o);
      o = std::move(moved);
      break;
    }
    case Drag::DiskRim: {
      Disk& d = std::get<Disk>(scene.obstacles[static_cast<std::size_t>(target_)]);
      const double r0 = std::get<Disk>(was.obstacles[static_cast<std::size_t>(target_)]).radius;
      // The rim follows the mouse's change of distance from the centre (the press may be a few
      // pixels off the rim).
      const double r = offset == Vec2::Zero()
                           ? r0
                           : std::max(view.pixels(2.0f), r0 + (length(m - d.center) - length(grab_ - d.center)));
      changed = r != d.radius;
      d.radius = r;
      break;
    }
    case Drag::Vertex: {
      auto& verts = std::get<PolygonObstacle>(scene.obstacles[static_cast<std::size_t>(target_)]).vertices;
      const auto i = static_cast<std::size_t>(handle_);
      const Vec2 old = verts[i];
      verts[i] = std::get<PolygonObstacle>(was.obstacles[static_cast<std::size_t>(target_)]).vertices[i] + offset;
      // A move that would make the polygon cross itself is not taken.
      if (*polygon_problem(verts)) {
        verts[i] = old;
        if (ctx.notice.empty() || ImGui::GetTime() > ctx.notice_until)
          ctx.notify("That vertex position would make the polygon cross itself.", 2.0);
      } else {
        changed = verts[i] != old;
      }
      break;
    }
    case Drag::WallEnd: {
      Wall& w = std::get<Wall>(scene.obstacles[static_cast<std::size_t>(target_)]);
      const Wall& w0 = std::get<Wall>(was.obstacles[static_cast<std::size_t>(target_)]);
      const Vec2 end = (handle_ == 0 ? w0.a : w0.b) + offset;
      Vec2& at = handle_ == 0 ? w.a : w.b;
      changed = end != at;
      at = end;
      break;
    }
    case Drag::NewDisk:
    case Drag::NewWall: {
      // Previews only: committed on release.
      if (!down) {
        const double size = length(m - grab_);
        if (size < view.pixels(3.0f)) {
          ctx.notify(drag_ == Drag::NewDisk ? "Drag (do not just click) to give the disk a radius."
                                            : "Drag to draw a wall from one end to the other.",
                     3.0);
        } else {
          Scene before = scene;
          if (drag_ == Drag::NewDisk ? add_obstacle(scene, Disk{grab_, size}, ctx)
                                     : add_obstacle(scene, Wall{grab_, m}, ctx))
            changed = true;
        }
        before_drag_.reset();  // add_obstacle recorded its own undo step
      }
      break;
    }
    case Drag::None:
      break;
  }
  if (!down) end_drag(scene);  // one undo step per drag, if it changed anything
  return changed;
}

bool SceneEditor::edit(WorkspaceView& view, Scene& scene, LabContext& ctx, const Options& options) {
  if (!options.editable) return false;
  // A drag lives in consecutive frames of its view. If the view was off screen (another lesson
  // or tab), the drag ended there: it must not jump to wherever the mouse is on return.
  const int frame = ImGui::GetFrameCount();
  if ((drag_ != Drag::None || key_burst_) && last_frame_ < frame - 1) end_drag(scene);
  last_frame_ = frame;
  if (instructor::scene_locked()) return locked_edit(view, scene, ctx, options);
  bool changed = false;
  // Keys work wherever the mouse is (the lesson on screen owns them); text fields keep theirs.
  const bool polygon_begun = !polygon_.empty();  // then Enter closes it, and places nothing
  changed |= handle_keys(scene, ctx);
  if (selected_ >= static_cast<int>(scene.obstacles.size())) selected_ = -1;
  // No mouse needed: what has the keyboard focus moves by the arrows (scene_editor_keys.cpp).
  changed |= handle_edit_keys(view, scene, ctx, options, !polygon_begun);

  if (drag_ == Drag::None && view.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    focus_ = Focus::None;  // the mouse takes over; the arrows take its selection if pressed
    focus_handle_ = -1;
    if (!begin_drag(view, scene, options) && tool_ == Tool::Polygon) {
      const Vec2 m = view.mouse_world();
      // Double-click, or a click on the first vertex, closes the polygon.
      const bool on_first = polygon_.size() >= 3 && length(polygon_.front() - m) <= view.reach(kGrabPixels);
      if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) || on_first) {
        // The double-click's first click added a vertex at the same place: drop it.
        if (!on_first && !polygon_.empty() && length(polygon_.back() - m) <= view.reach(kGrabPixels))
          polygon_.pop_back();
        changed |= finish_polygon(scene, ctx);
      } else {
        polygon_.push_back(m);
      }
    }
  }
  if (drag_ != Drag::None) changed |= continue_drag(view, scene, ctx);
  changed |= context_menu(view, scene, ctx, options);

  // Cursor shapes say what a press would do.
  if (view.hovered()) {
    if (drag_ == Drag::Obstacle || drag_ == Drag::Start || drag_ == Drag::Goal)
      ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeAll);
    else if (tool_ != Tool::Select)
      ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
  }
  draw_overlays(view, scene);
  if (options.endpoints_are_points) draw_endpoint_focus(view, scene);
  return changed;
}

bool SceneEditor::locked_edit(WorkspaceView& view, const Scene& scene, LabContext& ctx, const Options& options) {
  // Nothing changes. What would have edited says why instead: a press on start, goal or an
  // obstacle, the editing keys. The keyboard's focus (N, H) still walks the scene, to read it.
  if (drag_ != Drag::None) drop_drag();
  polygon_.clear();
  tool_ = Tool::Select;
  key_burst_ = false;
  bool tried = false;
  // The context menu (a right-click that did not pan, a long press) is the editor's too.
  if (menu_right_click(view) || menu_long_press(view)) tried = true;
  if (view.hovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const Vec2 m = view.mouse_world();
    if (options.endpoints_are_points)
      tried = length(endpoint(scene.goal) - m) <= view.reach(11.0f) || length(endpoint(scene.start) - m) <= view.reach(11.0f);
    for (const Obstacle& o : scene.obstacles) tried = tried || hits(o, m, view.pixels(4.0f));
    focus_ = Focus::None;
    selected_ = -1;
  }
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantTextInput) {
    if (io.KeyCtrl && (key_pressed(ImGuiKey_Z) || key_pressed(ImGuiKey_Y))) tried = true;
    if (!io.KeyCtrl && !io.KeyAlt) {
      for (ImWchar c : io.InputQueueCharacters) {
        switch (c) {
          case 'n': cycle_focus(scene, options, +1); break;
          case 'N': cycle_focus(scene, options, -1); break;
          case 'h': cycle_handle(scene, +1); break;
          case 'H': cycle_handle(scene, -1); break;
          case '?': show_help_ = !show_help_; break;
          case 'd': case 'D': case 'p': case 'P': case 'w': case 'W':
          case '+': case '=': case '-': case '_': tried = true; break;
          default: break;
        }
      }
      const bool arrows = key_pressed(ImGuiKey_LeftArrow) || key_pressed(ImGuiKey_RightArrow) ||
                          key_pressed(ImGuiKey_UpArrow) || key_pressed(ImGuiKey_DownArrow);
      if (arrows && focus() != Focus::None) tried = true;
      if ((key_pressed(ImGuiKey_Delete) || key_pressed(ImGuiKey_Backspace)) && selected_ >= 0) tried = true;
      if (key_pressed(ImGuiKey_Escape)) {
        selected_ = -1;
        focus_ = Focus::None;
      }
    }
  }
  if (tried) ctx.notify(instructor::scene_refusal(), 4.0);
  if (selected_ >= static_cast<int>(scene.obstacles.size())) selected_ = -1;
  draw_overlays(view, scene);
  if (options.endpoints_are_points) draw_endpoint_focus(view, scene);
  return false;
}

void SceneEditor::draw_overlays(WorkspaceView& view, const Scene& scene) const {
  ImDrawList* dl = view.draw_list();
  dl->PushClipRect(view.canvas_min(), view.canvas_max(), true);
  const Vec2 m = view.mouse_world();
  if (selected_ >= 0 && selected_ < static_cast<int>(scene.obstacles.size())) {
    const Obstacle& o = scene.obstacles[static_cast<std::size_t>(selected_)];
    view.draw_obstacle(o, true);
    auto handle = [&](const Vec2& p) {
      const ImVec2 s = view.to_screen(p);
      dl->AddRectFilled(ImVec2(s.x - 4, s.y - 4), ImVec2(s.x + 4, s.y + 4), theme::kCanvasBg);
      dl->AddRect(ImVec2(s.x - 4, s.y - 4), ImVec2(s.x + 4, s.y + 4), theme::kSelectedEdge, 0.0f, 0, 1.5f);
    };
    std::visit(Overloaded{[&](const Disk& d) {
                            handle(d.center + Vec2(d.radius, 0));
                            char text[48];
                            std::snprintf(text, sizeof text, "r = %.3f", d.radius);
                            view.draw_label(d.center + Vec2(d.radius, 0), text, theme::kSelectedEdge, ImVec2(8, -8));
                          },
                          [&](const PolygonObstacle& g) {
                            for (const Vec2& v : g.vertices) handle(v);
                          },
                          [&](const Wall& w) {
                            handle(w.a);
                            handle(w.b);
                          }},
               o);
  }
  if (drag_ == Drag::NewDisk) {
    const double r = length(m - grab_);
    view.draw_disk(grab_, r, theme::with_alpha(theme::kPreview, 48), theme::kPreview, 2.0f);
    char text[48];
    std::snprintf(text, sizeof text, "r = %.3f", r);
    view.draw_label(m, text, theme::kPreview);
  }
  if (drag_ == Drag::NewWall) view.draw_segment(grab_, m, theme::kPreview, 3.0f);
  if (!polygon_.empty()) {
    for (std::size_t i = 0; i + 1 < polygon_.size(); ++i) view.draw_segment(polygon_[i], polygon_[i + 1], theme::kPreview, 2.0f);
    view.draw_segment(polygon_.back(), m, theme::with_alpha(theme::kPreview, 120), 1.5f);
    for (const Vec2& v : polygon_) dl->AddCircleFilled(view.to_screen(v), 4.0f, theme::kPreview);
    if (polygon_.size() >= 3) dl->AddCircle(view.to_screen(polygon_.front()), kGrabPixels, theme::kPreview, 16, 1.5f);
  }
  draw_focus(view, scene);  // over the selection look: the keyboard's ring
  dl->PopClipRect();
}

bool SceneEditor::toolbar(Scene& scene, LabContext&) {
  bool changed = false;
  struct Item {
    Tool tool;
    const char* label;
    const char* tip;
  };
  static const Item kItems[] = {
      {Tool::Select, "Select", "V: select, move, resize, delete obstacles; drag start and goal (or N and the arrows)"},
      {Tool::Disk, "Disk", "D: drag from the centre to the rim (or Enter: one in the middle of the view)"},
      {Tool::Polygon, "Polygon", "P: click the vertices; double-click, Enter or the first vertex closes (Enter first: a square)"},
      {Tool::Wall, "Wall", "W: drag from one end to the other, zero thickness (or Enter: one in the middle)"},
  };
  // Fixed by the instructor: the tools are shown, disabled, and the line under them says why.
  const bool locked = instructor::scene_locked();
  ImGui::BeginDisabled(locked);
  for (const Item& item : kItems) {
    if (&item != kItems) ui::flow(ui::button_width(item.label));
    const bool active = tool_ == item.tool;
    if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button(item.label)) set_tool(item.tool);
    if (active) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", locked ? instructor::kFixed : item.tip);
  }
  ImGui::BeginDisabled(!can_undo());
  if (ImGui::Button("Undo")) changed = undo(scene);
  ImGui::EndDisabled();
  ui::flow(ui::button_width("Redo"));
  ImGui::BeginDisabled(!can_redo());
  if (ImGui::Button("Redo")) changed = redo(scene);
  ImGui::EndDisabled();
  ui::flow(ui::button_width("Delete"));
  ImGui::BeginDisabled(selected_ < 0);
  if (ImGui::Button("Delete") && selected_ >= 0 && selected_ < static_cast<int>(scene.obstacles.size()) &&
      drag_ == Drag::None) {
    record(scene);
    scene.obstacles.erase(scene.obstacles.begin() + selected_);
    selected_ = -1;
    changed = true;
  }
  ImGui::EndDisabled();
  ImGui::EndDisabled();  // locked
  ui::flow(ui::button_width("Keys (?)"));
  if (ImGui::Button("Keys (?)")) show_help_ = !show_help_;
  if (locked) instructor::dim_line(instructor::scene_refusal());
  return changed;
}

void SceneEditor::help_window() {
  if (!show_help_) return;
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  // Sized to its table: a fixed width cut the descriptions off.
  if (ImGui::Begin("Keyboard and mouse", &show_help_, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize)) {
    static const char* const kRows[][2] = {
        {"V / D / P / W", "tool: select / disk / polygon / wall"},
        {"drag (Select)", "move an obstacle, start or goal; its handles resize"},
        {"drag (Disk, Wall)", "draw one"},
        {"click (Polygon)", "add a vertex; double-click or Enter closes"},
        {"Enter (Disk, Wall)", "place one in the middle of the view, focused"},
        {"Enter (Polygon)", "close it; with no vertex yet, place a square (vertices: H)"},
        {"N / Shift+N", "keyboard focus on the next / previous thing: start, goal, obstacles"},
        {"H / Shift+H", "focus the focused obstacle's next / previous vertex or wall end"},
        {"arrows", "move what has the focus by a step (1/50 of the view); Shift: 1/10 step"},
        {"+ / - (= / _)", "grow / shrink the focused obstacle"},
        {"Backspace", "remove the last polygon vertex, or the selection"},
        {"Delete", "delete the selected obstacle"},
        {"Esc", "cancel a drag or the polygon, or deselect (and unfocus)"},
        {"Tab / Shift+Tab", "leave the lab for the page (no key trap)"},
        {"Ctrl+Z / Ctrl+Y", "undo / redo (Ctrl+Shift+Z redoes too)"},
        {"wheel / right drag", "zoom about the cursor / pan"},
        {"F", "fit the view"},
        {"Space / . / ,", "play or pause / step / step back"},
        {"?", "this help"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
      for (const auto& row : kRows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row[0]);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row[1]);
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

void SceneEditor::tool_buttons(float height, bool inline_) {
  static const struct {
    Tool tool;
    const char* label;
    const char* control;
  } kTools[] = {{Tool::Select, "Select", "tool:select"},
                {Tool::Disk, "Disk", "tool:disk"},
                {Tool::Polygon, "Polygon", "tool:polygon"},
                {Tool::Wall, "Wall", "tool:wall"}};
  const float share = (ImGui::GetContentRegionAvail().x - 3 * ImGui::GetStyle().ItemSpacing.x) / 4;
  for (const auto& t : kTools) {
    const float w = inline_ ? ui::button_width(t.label) + 12.0f : share;
    if (inline_) ui::flow(w);  // (after the items before, while it fits)
    else if (&t != kTools) ImGui::SameLine();
    const bool active = tool_ == t.tool;
    if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    ImGui::BeginDisabled(instructor::scene_locked());
    if (ImGui::Button(t.label, ImVec2(w, height))) set_tool(t.tool);
    ImGui::EndDisabled();
    if (active) ImGui::PopStyleColor();
    web::record_control(t.control);
  }
}

}  // namespace csl::app
