#pragma once
// The lab's shell: the lesson menu, the side panel with the shared playback controls, the
// lesson's views, the event log, notices, and the JS API that drives all of it.
#include <nlohmann/json.hpp>

#include <map>
#include <memory>
#include <string>

#include "app/shell/context.hpp"
#include "app/shell/homework_panel.hpp"
#include "app/shell/lesson.hpp"
#include "app/shell/platform.hpp"

namespace csl::app {

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
  void top_bar();
  void playback_controls();
  void shortcuts();
  void notice();
  // Shows a homework problem: its lesson, with the problem's scene and parameters.
  void open_problem(const HomeworkProblem& problem, bool preset);
  // Shows `lesson` with {scene?, params} (an exercise's numbers) applied to it.
  void show_in_lesson(const std::string& lesson, const nlohmann::json& setup);

  const Platform& platform_;
  LabContext ctx_;
  std::map<std::string, std::unique_ptr<Lesson>> instances_;
  Lesson* lesson_ = nullptr;
  std::string lesson_id_;
  HomeworkPanel homework_{[this](const HomeworkProblem& p, bool preset) { open_problem(p, preset); },
                          [this](const std::string& lesson, const nlohmann::json& setup) { show_in_lesson(lesson, setup); }};
};

}  // namespace csl::app
