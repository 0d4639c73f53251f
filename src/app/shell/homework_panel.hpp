#pragma once
// The homework companion in the lab: the "Homework" map (P1-P13 by number, each opening the
// lesson that shows it), the first-visit welcome, and the card at the top of the side panel with
// the problem's task and its checked exercise (predict, then reveal), and the visit's score.
// The exercises themselves are core's (core/teaching/homework.hpp): the CLI gives the same ones.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <string>

#include "app/shell/js_api.hpp"
#include "core/teaching/homework.hpp"

namespace csl::app {

class HomeworkPanel {
 public:
  /// `open` shows a problem's lesson, with its preset if asked (the app switches lessons); it
  /// throws ApiError if the lesson refuses the preset.
  /// `show` puts an exercise's own numbers into its lesson (exercise_tool_setup()); it throws
  /// ApiError if the lesson refuses them.
  HomeworkPanel(std::function<void(const HomeworkProblem&, bool preset)> open,
                std::function<void(const std::string& lesson, const nlohmann::json&)> show);

  /// homework, open_problem, exercise, check_answer, show_solution, show_exercise, close_problem,
  /// homework_state.
  void register_api(JsApi& api);
  /// The top bar's "Homework" button and its map; `tall`: as ui::bar_button.
  void menu_button(bool tall);
  /// Above the lesson's panel: the welcome on a first visit, and the open problem's card while
  /// its lesson is on screen.
  void card(const std::string& lesson_id);

  /// Opens problem `id` with an exercise of `seed` (none: a new seed); `preset`: the lesson gets
  /// the problem's scene and parameters (not when a reload brings back saved work). Throws ApiError.
  void open(const std::string& id, std::optional<std::uint64_t> seed, bool preset = true);

 private:
  struct Score {
    int tried = 0, right = 0;  // readable answers checked; exercises (seeds) answered right
  };
  void problem_body(const HomeworkProblem& problem);
  void set_exercise(const std::string& id, std::uint64_t seed);
  nlohmann::json check(const std::string& answer);
  /// Whether the current exercise's solution was asked for (this visit); show_solution asks.
  bool solution_shown() const;
  /// After a readable wrong try whose solution was not shown: the card offers it.
  bool solution_offered() const;
  nlohmann::json show_solution();
  /// The answered exercise's numbers in its lesson, or its robot's C-space in the 3-D lesson.
  /// Throw ApiError when there is nothing to show (or the lesson refuses it).
  nlohmann::json show_in_tool();
  nlohmann::json show_in_3d();
  nlohmann::json state_json() const;
  static std::uint64_t fresh_seed();

  std::function<void(const HomeworkProblem&, bool)> open_;
  std::function<void(const std::string&, const nlohmann::json&)> show_;
  std::set<std::pair<std::string, std::uint64_t>> solved_;  // (problem, seed) answered right
  std::set<std::pair<std::string, std::uint64_t>> shown_;   // (problem, seed) whose solution the student asked for
  std::string problem_;  // the open problem's id, "" for none
  std::optional<Exercise> exercise_;
  std::optional<ExerciseCheck> checked_;
  std::string checked_answer_;
  char answer_[256] = "";
  bool focus_answer_ = false;
  // Frames left in which the card scrolls the panel to a new check's result and the buttons
  // under it (two: the panel's "more below" row may take its height the frame after).
  int reveal_result_ = 0;
  bool map_open_ = false;
  bool want_map_ = false;  // the welcome asked for the map
  std::string error_;  // why the last problem or numbers could not be shown, "" if they were
  std::map<std::string, Score> scores_;
};

}  // namespace csl::app
