#pragma once
// Grading an assignment (assignment.hpp) from a student's answers: the CLI's `cspacelab
// assignment grade` and, compiled to wasm, the page's assignment mode. Pure and deterministic:
// the same assignment, answers and learner give the same grade everywhere.
//
// Answers (JSON):
//   {"learner": "ID",                       optional: whose numbers the exercises are
//    "answers": [{"item": 0, "answer": "pi/2"},        an exercise: what the student typed
//                {"item": 1, "visited": true},         an explore item: the student went there
//                {"item": 2, "state": {...}}]}          a task: the lesson's state() that Check my lab recorded
// Each item at most once, with the field its kind takes; items without an answer are not
// attempted. An exercise's or task's answer may say how many times it was checked, "tries": an
// integer >= 1 (the page's assignment mode counts them); it is reported beside the item's own
// limit, not graded. Unknown fields are errors, as in the assignment.
//
// Per item: attempted, correct, points (all of the item's points when correct, else 0),
// expected (an exercise's answer; a task's condition in words), explanation. Totals as SCORM
// reports them: raw (the sum of points), min 0, max (the sum of the items' points), scaled =
// raw / max in [0, 1] (with max 0: 1 once completed, else 0); completed: every item attempted
// (an exercise answer that cannot be read, or an empty one, is not an attempt); passed:
// scaled >= the assignment's pass.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "core/teaching/assignment.hpp"

namespace csl {

struct AssignmentAnswer {
  std::size_t item = 0;
  std::string text;       ///< exercise
  bool visited = false;   ///< explore
  nlohmann::json state;   ///< task
  unsigned tries = 0;     ///< exercise, task: the checks counted; 0: not counted (none said)
};

struct AnswerSheet {
  std::optional<std::string> learner;
  std::vector<AssignmentAnswer> answers;
};

struct AnswerSheetParse {
  std::optional<AnswerSheet> sheet;  ///< set only if errors is empty
  std::vector<std::string> errors;   ///< every problem, "answers[3]: item: ..."
};

/// At most this many characters of a typed answer are read (the exercises read far fewer).
inline constexpr std::size_t kMaxAnswerText = 1000;

/// Reads answers for `assignment`: items in range and each once, the field each kind takes.
AnswerSheetParse parse_answer_sheet(const nlohmann::json& j, const Assignment& assignment);
/// The same from text (strict JSON, at most kMaxAssignmentBytes).
AnswerSheetParse parse_answer_sheet_text(const std::string& text, const Assignment& assignment);

struct ItemGrade {
  std::size_t item = 0;
  AssignmentItemKind kind = AssignmentItemKind::Exercise;
  bool attempted = false;
  bool correct = false;
  double points = 0;      ///< earned
  double max_points = 0;
  nlohmann::json expected;  ///< exercise: the answer; task: the condition in words; explore: null
  std::string explanation;
  std::optional<std::uint64_t> seed;  ///< exercise: the seed graded with
  unsigned tries = 0;                 ///< the answer's, 0 if it said none
};

struct AssignmentGrade {
  std::string learner;
  std::vector<ItemGrade> items;  ///< every item of the assignment, in order
  double raw = 0, min = 0, max = 0, scaled = 0;
  bool completed = false;
  bool passed = false;
};

/// Grades `sheet` against `assignment` for `learner` (the id the exercises' seeds come from).
AssignmentGrade grade_assignment(const Assignment& assignment, const AnswerSheet& sheet, const std::string& learner);

/// {"learner", "items": [{item, kind, title, attempted, correct, points, max_points, expected,
/// explanation, seed?, tries? (the answer's), tries_allowed? (the item's)}], "score": {raw, min, max, scaled}, "completed", "passed", "pass"}.
nlohmann::json assignment_grade_to_json(const Assignment& assignment, const AssignmentGrade& grade);

}  // namespace csl
