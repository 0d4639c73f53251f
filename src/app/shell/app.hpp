#pragma once
// The lab's shell: the lesson menu, the side panel with the shared playback controls, the
// lesson's views, the event log, notices, and the JS API that drives all of it.
#include <nlohmann/json.hpp>

#include <map>
#include <memory>
#include <string>

#include "app/shell/assignment_panel.hpp"
#include "app/shell/context.hpp"
#include "app/shell/homework_panel.hpp"
#include "app/shell/lesson.hpp"
#include "app/shell/platform.hpp"
#include "app/shell/scene_name.hpp"

namespace csl::app {

/// The lesson's stepper, or one with nothing to step (at step 0, done) for a lesson without.
Stepper& stepping(Lesson& lesson);
/// Whether the lesson shows the playback controls (and the event log).
bool shows_controls(const Lesson& lesson);

class App {
 public:
  explicit App(const Platform& platform);
  /// Builds one frame of UI (between ImGui::NewFrame and ImGui::Render).
  void frame();
  /// Switches lessons (created on first use, kept afterwards so nothing is lost); false if unknown.
  bool select_lesson(const std::string& id);
  Lesson& lesson() { return *lesson_; }
  const std::string& lesson_id() const { return lesson_id_; }

 private:
  void register_api();
  // Advances long work (Lesson::work) for a slice of this frame.
  void work();
  // status().busy: the first lesson with long work going on, or null.
  nlohmann::json busy_json() const;
  // The layout (app_layout.cpp): the wide one (lesson bar, side panel, views, log) or, on a
  // narrow or short screen, the compact one (a lesson menu, View and Controls tabs, a playback
  // strip over the views, a log that folds).
  void wide_frame();
  void compact_frame();
  void top_bar();
  void compact_bar();
  void playback_strip();
  bool strip_wide() const;  // the compact layout's tabs, strip and tools on one row
  void compact_log();
  nlohmann::json layout_json() const;
  void playback_controls();
  void shortcuts();
  void notice();
  // Shows a homework problem: its lesson, with the problem's scene and parameters.
  void open_problem(const HomeworkProblem& problem, bool preset);
  // Shows `lesson` with {scene?, params} (an exercise's numbers) applied to it.
  void show_in_lesson(const std::string& lesson, const nlohmann::json& setup);
  // An assignment's item in the lab (AssignmentPanel::Show): the lesson, with the setup if
  // `preset` as far as the instructor's locks allow; "" or why not all of it.
  std::string show_item(const std::string& lesson, const nlohmann::json& setup, bool preset, bool view);
  // Lesson `id`'s state() as the API answers it (hidden answers out, scene_name in); throws
  // ApiError if it is not open or still working.
  nlohmann::json lesson_state_of(const std::string& id) const;
  // What the instructor fixed (app_instructor.cpp): the API's restrict, the
  // scene and parameters each lesson is held to, the checks before an edit.
  void register_instructor_api();
  // What is fixed and hidden, for restrict's answer and status().restrictions.
  nlohmann::json restrictions_json() const;
  // The lesson `id`, made if it is not open yet (and pinned, while something is locked).
  Lesson& instance(const std::string& id);
  // Remembers `lesson`'s scene and the parameters locked now as what it is held to.
  void pin(const std::string& id, const Lesson& lesson);
  // `snapshot` {scene?, params?} with what a lock holds for lesson `id` put in (restore, reset).
  nlohmann::json pinned(const std::string& id, nlohmann::json snapshot) const;
  // Throws ApiError if a lock refuses setting `params` (an object) on the lesson on screen.
  void check_params_allowed(const Lesson& lesson, const nlohmann::json& params) const;
  // Undoes this frame's changes of locked parameters made by the student's input (a drag, a
  // key) that no widget stopped, with a notice; `before`: params() at the frame's start.
  void hold_locked_params(const nlohmann::json& before);
  // The panel's line saying what the instructor fixed and hid here, if anything.
  void instructor_note();
  // Brings every open lesson's scene name up to date with its content (scene_name.hpp).
  void name_scenes();
  // A scene from elsewhere went into lesson `id`: it is what its name refers to from now on.
  void scene_loaded(const std::string& id);
  // The log of lesson `id` says it was restored from `from` ("the link"), where and how (once a
  // replay over frames has ended: finish_notes()).
  void note_restored(const std::string& id, const std::string& from);
  void finish_notes();
  // The lesson's state() with its scene's name ("scene_name"), as the API answers it.
  nlohmann::json lesson_state(const nlohmann::json& args) const;

  const Platform& platform_;
  LabContext ctx_;
  std::map<std::string, std::unique_ptr<Lesson>> instances_;
  Lesson* lesson_ = nullptr;
  std::string lesson_id_;
  enum class Tab { View, Controls };
  Tab tab_ = Tab::View;   // the compact layout's tab
  bool log_open_ = false;  // the compact layout's log, unfolded
  nlohmann::json layout_;  // status().layout: the last frame's
  std::pair<ImVec2, ImVec2> notice_box_;  // where the notice was drawn (zero: none), for layout_json
  // While something is locked: each lesson's scene (JSON, or null) and parameters as the lock
  // found them (or as the lesson began, opened later): what a restore or a reset gets.
  std::map<std::string, nlohmann::json> pins_;
  // What the app keeps for each open lesson besides the lesson itself, by its id.
  struct LessonExtras {
    SceneName scene_name;       // its scene's name, true to what it holds
    std::string log_note;       // the first line of its log (EventLog::set_note)
    std::string restored_from;  // a restore's replay still runs: where from, for the note at its end
  };
  std::map<std::string, LessonExtras> extras_;
  HomeworkPanel homework_{[this](const HomeworkProblem& p, bool preset) { open_problem(p, preset); },
                          [this](const std::string& lesson, const nlohmann::json& setup) {
                            show_in_lesson(lesson, setup);
                            // The numbers are in the tool: show it, or the panel where the lesson
                            // shows what the problem asks about (P13's forces table on a phone).
                            const bool panel = lesson_->numbers_shown(ctx_);
                            if (ctx_.compact) tab_ = panel ? Tab::Controls : Tab::View;
                          }};
  AssignmentPanel assignment_{
      [this](const std::string& lesson, const nlohmann::json& setup, bool preset, bool view) {
        return show_item(lesson, setup, preset, view);
      },
      [this](const std::string& lesson) { return lesson_state_of(lesson); }};
};

}  // namespace csl::app
