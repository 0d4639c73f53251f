#pragma once
// Editing a scene with the mouse on a WorkspaceView: create disks (drag), polygons (click the
// vertices, double-click or Enter to close), walls (drag); select, move, resize (a disk's rim,
// a polygon's vertices, a wall's ends), delete; drag start and goal; undo and redo.
// Keys: V select, D disk, P polygon, W wall, Delete, Esc, Ctrl+Z, Ctrl+Y, F fit view, ? help.
// A context menu (scene_editor_menu.cpp) on a right-click, or a long press by touch: delete,
// duplicate or select the obstacle there, add a disk or square, move start or goal there.
// And all of it by keyboard alone (scene_editor_keys.cpp): N / Shift+N focus the next / previous
// thing (start, goal, each obstacle), H / Shift+H a handle of it (a vertex, a wall's end), the
// arrows move what has the focus, + / - resize it, Enter places a disk, wall or polygon.
// Edits that would make the scene invalid (a polygon with < 3 vertices or crossing edges, too
// many obstacles) are refused with a message and change nothing.
#include <optional>
#include <vector>

#include "app/shell/context.hpp"
#include "app/views/workspace_view.hpp"
#include "core/scene/scene.hpp"

namespace csl::app {

class SceneEditor {
 public:
  enum class Tool { Select, Disk, Polygon, Wall };

  struct Options {
    bool endpoints_are_points = true;  ///< start/goal are workspace points (point/polygon robot)
    bool editable = true;              ///< false: view only (no tools)
    /// Where start and goal are points when they are not points of the edited view: an arm's
    /// C-space square, whose coordinates are angles (the keyboard moves them there, wrapping
    /// round). Null: the keyboard moves them only if endpoints_are_points.
    const WorkspaceView* angle_view = nullptr;
  };

  /// Handles the mouse and keys over `view` (after view.begin() and after the scene is drawn)
  /// and draws the editing overlays. Returns true if `scene` changed this frame, including
  /// each frame of a drag (so views can follow live); each drag is one undo step.
  bool edit(WorkspaceView& view, Scene& scene, LabContext& ctx, const Options& options);
  /// The tool buttons and undo/redo, for the side panel. Returns true if `scene` changed
  /// (Undo, Redo or Delete): the lesson must rebuild what it derives from the scene.
  bool toolbar(Scene& scene, LabContext& ctx);
  /// The four tool buttons, `height` high, for the compact layout's strip over the views (they
  /// change no scene): on a row of their own sharing the width, or `inline_` after the items
  /// before them, each as wide as its label.
  void tool_buttons(float height, bool inline_);
  /// The keyboard help as a window, when asked for (? key or the toolbar's button).
  void help_window();
  /// The keyboard focus ring on start or goal, if one has it, in `view` where they are drawn as
  /// points: edit() draws it in its own view; a lesson whose start and goal are angles
  /// (Options::angle_view) calls this after drawing them there.
  void draw_endpoint_focus(const WorkspaceView& view, const Scene& scene) const;

  Tool tool() const { return tool_; }
  void set_tool(Tool t);
  /// The selected obstacle, or -1.
  int selected() const { return selected_; }
  /// Whether a drag (of an obstacle, handle or endpoint) is in progress, or an editing key is
  /// held: views that replay at a drag's release replay when the key is let go.
  bool dragging() const { return drag_ != Drag::None || key_burst_; }

  /// Records `scene` as it is before an edit made elsewhere (e.g. through the API): undoable.
  void record(const Scene& before);
  bool undo(Scene& scene);
  bool redo(Scene& scene);
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  /// Ends the history: the scene is a new one (any drag in progress is dropped).
  void clear_history();
  /// Replaces `scene` by `next`, a scene from elsewhere (the API, a file): one undo step. A drag
  /// in progress ends first, as its own undo step: it must not go on in the new scene.
  void replace(Scene& scene, const Scene& next);

 private:
  enum class Drag { None, Obstacle, DiskRim, Vertex, WallEnd, Start, Goal, NewDisk, NewWall };
  // What the keyboard edits: start, goal, or the selected obstacle (selected_), whole or one of
  // its handles (focus_handle_: a polygon's vertex, a wall's end; -1 the whole obstacle).
  enum class Focus { None, Start, Goal, Obstacle };
  bool handle_keys(Scene& scene, LabContext& ctx);
  // scene_editor_menu.cpp: the context menu (right-click, long press).
  bool context_menu(WorkspaceView& view, Scene& scene, LabContext& ctx, const Options& options);
  // What opens the context menu: a right-click that did not pan; a long press (which it
  // records, once per press). locked_edit() asks them too, to say why nothing opens.
  bool menu_right_click(const WorkspaceView& view) const;
  bool menu_long_press(const WorkspaceView& view);
  // edit() while the instructor fixed the scene: no change; a press or key that would edit
  // shows the notice saying why.
  bool locked_edit(WorkspaceView& view, const Scene& scene, LabContext& ctx, const Options& options);
  // scene_editor_keys.cpp: editing by keyboard alone.
  bool handle_edit_keys(WorkspaceView& view, Scene& scene, LabContext& ctx, const Options& options, bool enter_places);
  void cycle_focus(const Scene& scene, const Options& options, int by);
  void cycle_handle(const Scene& scene, int by);
  bool move_focused(Scene& scene, LabContext& ctx, const Options& options, const Vec2& by);
  bool resize_focused(Scene& scene, LabContext& ctx, double step, int sign);
  bool place(WorkspaceView& view, Scene& scene, LabContext& ctx);
  void keep_focus_through(const Scene& now);  // after undo or redo
  void draw_focus(const WorkspaceView& view, const Scene& scene) const;
  Focus focus() const;
  bool begin_drag(WorkspaceView& view, Scene& scene, const Options& options);
  // The topmost obstacle at world point p (inside it, or within `tolerance` of a wall), or -1:
  // what a press there grabs, and what the context menu opened there is about.
  static int obstacle_under(const Scene& scene, const Vec2& p, double tolerance);
  bool continue_drag(WorkspaceView& view, Scene& scene, LabContext& ctx);
  bool finish_polygon(Scene& scene, LabContext& ctx);
  void draw_overlays(WorkspaceView& view, const Scene& scene) const;
  bool add_obstacle(Scene& scene, Obstacle o, LabContext& ctx);
  // Undo, redo and a new scene end a drag first: it holds an index into the scene it began in.
  void end_drag(Scene& scene);  // as if released: a move becomes one undo step
  void drop_drag();             // forgets it, keeping the scene as it is

  Tool tool_ = Tool::Select;
  int selected_ = -1;
  Drag drag_ = Drag::None;
  int target_ = -1;            // the obstacle being dragged (the selection may change meanwhile)
  int handle_ = -1;            // vertex or wall end being dragged
  int last_frame_ = -1;        // the ImGui frame of the last edit(): a drag spans consecutive ones
  Vec2 grab_{0, 0};            // where the drag started (world)
  std::optional<Scene> before_drag_;
  std::vector<Vec2> polygon_;  // vertices of the polygon being built
  std::vector<Scene> undo_, redo_;
  bool show_help_ = false;
  Focus focus_ = Focus::None;
  int focus_handle_ = -1;
  bool key_burst_ = false;  // an edit key is held: its repeats join the press's undo step
  Vec2 menu_at_{0, 0};        // where the context menu was opened (world)
  int menu_target_ = -1;      // the obstacle it was opened on, or -1
  bool long_pressed_ = false;  // this press already opened the menu (until the finger lifts)
  int press_frames_ = 0;       // frames the left button (a finger) has been down
};

}  // namespace csl::app
