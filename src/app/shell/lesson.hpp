#pragma once
// Lessons: each is one source file holding a Lesson subclass, registered by one line at the end
// of that file:
//     CSL_REGISTER_LESSON(StepPrmLesson, "step-prm", "Step PRM", "Planning");
// The registry builds the lesson menu, sorted by category and name. Lesson files are compiled
// straight into the app (not a static library, whose linker would drop the registrations).
#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/shell/context.hpp"
#include "app/shell/param_fields.hpp"
#include "app/shell/stepper.hpp"
#include "core/scene/scene.hpp"

namespace csl::app {

class SceneEditor;
class SurfaceView;
class WorkspaceView;

/// One of a lesson's views whose camera travels in snapshots and links (app/shell/camera.*):
/// a plane (`plane`, with the rectangle the lesson shows in it now) or a 3-D surface.
struct LessonView {
  const char* name;  ///< as status().layout.views names it: "workspace", "cspace", "torus"
  WorkspaceView* plane = nullptr;
  Vec2 min{0, 0}, max{1, 1};
  SurfaceView* surface = nullptr;
};

class Lesson {
 public:
  virtual ~Lesson() = default;

  /// The controls of the side panel, once a frame.
  virtual void panel(LabContext& ctx) = 0;
  /// The lesson's views, filling `size` (logical pixels), once a frame.
  virtual void views(LabContext& ctx, ImVec2 size) = 0;
  /// Called once a frame before panel/views: advance animations, replay after edits.
  virtual void update(LabContext&) {}
  /// The lesson comes on screen (the app cleared the event log): log where it stands again.
  virtual void on_show() {}

  /// The scene the lesson works on (get_scene/set_scene, undo), or nullptr.
  virtual Scene* scene() { return nullptr; }
  /// Replaces the scene (validated by the caller) as one undoable edit; false if the lesson
  /// cannot take it (e.g. a robot type it does not show), with the reason in `why`.
  virtual bool accept_scene(const Scene&, std::string& why) {
    why = "this lesson has no scene";
    return false;
  }
  virtual bool undo() { return false; }
  virtual bool redo() { return false; }

  /// The lesson's state for the JS API (args may ask for more, e.g. {"roadmap": true}).
  virtual nlohmann::json state(const nlohmann::json& args) const = 0;
  /// Sets parameters from the JS API; throws ApiError naming a bad one, changing nothing.
  virtual void set_params(const nlohmann::json& params) = 0;
  /// The parameters set_params() takes, as they are now (for share links and autosave).
  virtual nlohmann::json params() const = 0;
  /// Keys of params() that are part of the scene as well (the collision lesson's p and q are its
  /// start and goal): a scene fixed by the instructor (lock=scene) fixes them too.
  virtual std::vector<std::string> scene_params() const { return {}; }
  /// The parameters that have a ParamSpec (or a set of choices), for the page's native controls
  /// (the API's param_specs); a key of params() not listed gets its kind from its value.
  virtual std::vector<ParamField> param_fields() const { return {}; }
  /// What the lesson shows now, in sentences, for the page's text description (a screen reader
  /// has nothing else of the canvas): by default its scene's (lesson_text.cpp); a lesson adds
  /// what its main view shows.
  virtual std::string describe() const;

  /// The algorithm the lesson steps (the shared playback controls, keys and API drive it), or
  /// nullptr for a lesson with nothing to step.
  virtual Stepper* stepper() { return nullptr; }
  /// The views whose zoom and pan (a 3-D view: its turn) a snapshot keeps, each once (a view
  /// the API knows by two names, as Step PRM's workspace that is its C-space, under the first).
  virtual std::vector<LessonView> views_kept() { return {}; }
  /// The scene editor of the view on screen, or nullptr: the compact layout puts its tool
  /// buttons over the views (the side panel, where they are, is another tab there).
  virtual SceneEditor* editor() { return nullptr; }
  /// A homework problem's numbers went into the lesson ("Show these numbers in the tool"): true
  /// when what the problem asks about is then read on the side panel, not in the views (the
  /// compact layout stays on its Controls tab, and the lesson brings that part on screen).
  virtual bool numbers_shown(LabContext&) { return false; }
  const Stepper* stepper() const { return const_cast<Lesson*>(this)->stepper(); }
};

struct LessonInfo {
  std::string id;        ///< used in URLs and the API, e.g. "step-prm"
  std::string name;      ///< shown in the menu
  std::string category;  ///< menu section
  std::function<std::unique_ptr<Lesson>()> create;
};

/// Every registered lesson, sorted by category, then name.
const std::vector<LessonInfo>& lessons();
const LessonInfo* find_lesson(const std::string& id);

/// Registers a lesson at static-initialisation time; use CSL_REGISTER_LESSON.
struct LessonRegistration {
  LessonRegistration(const char* id, const char* name, const char* category,
                     std::function<std::unique_ptr<Lesson>()> create);
};

#define CSL_REGISTER_LESSON(Type, id, name, category)                         \
  static const ::csl::app::LessonRegistration csl_lesson_registration_##Type( \
      id, name, category, [] { return std::unique_ptr<::csl::app::Lesson>(new Type()); })

}  // namespace csl::app
