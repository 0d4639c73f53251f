#pragma once
// One student's work on an assignment (assignment.hpp) as the page's assignment mode keeps it:
// the answers recorded so far, the item on screen, whether it was submitted; graded by
// assignment_grade.hpp (nothing here decides what is right), reported as the JSON the page's
// assignment_state answers and the LMS layer reports (SCORM's score, interactions, suspend
// data), and saved to and resumed from a small "suspend" object.
//
// Tries: every check of an exercise or task that could be graded counts one try (an exercise's
// answer the lab cannot read does not, nor the answer recorded already checked again), whether
// or not the item limits them ("tries" in assignment.hpp): an instructor sees how often a right
// answer was found. Once an item's tries are used up its answer is final.
//
// Suspend (what SCORM 1.2's cmi.suspend_data holds, so at most kMaxSuspendChars characters):
//   {"v": 1, "c": CURRENT, "s": SUBMITTED (0 or 1), "a": [[ITEM, ANSWER, TRIES?], ...]}
// ANSWER by the item's kind: an exercise's typed text; an explore item's 1 (visited); a task's
// state as far as its check reads it (task_state_excerpt). TRIES: the tries counted, if any (a
// suspend object from before tries were counted has none: its answers count none). An answer that would make it longer
// than that is refused when it is recorded (never cut later: a resume gives back exactly what was
// graded).
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "core/teaching/assignment_grade.hpp"

namespace csl {

/// SCORM 1.2's suspend_data holds 4096 characters; the suspend JSON stays below this.
inline constexpr std::size_t kMaxSuspendChars = 4000;

struct AssignmentSession {
  Assignment assignment;
  std::string learner;
  std::vector<std::optional<AssignmentAnswer>> answers;  ///< by item: what was recorded last
  std::size_t current = 0;                               ///< the item on screen
  bool submitted = false;                                ///< answers frozen, review shown
};

/// A session with nothing answered, at item 0. Throws std::invalid_argument for a learner id
/// that learner_id_problem() refuses.
AssignmentSession start_assignment_session(Assignment assignment, std::string learner);

/// Records an answer to item `index` (replacing an earlier one), counting a try as the top of
/// this file says. Throws std::invalid_argument, changing nothing, if the session was submitted,
/// the index is out of range, the item is of another kind, its tries are used up (unless the
/// answer is the one recorded), an exercise's text is longer than kMaxAnswerText or cannot be
/// read while a readable answer is recorded (it would take a graded answer off the record), or
/// the suspend object would grow past kMaxSuspendChars.
void record_exercise_answer(AssignmentSession& s, std::size_t index, const std::string& text);
void record_visit(AssignmentSession& s, std::size_t index);
/// `state`: the lesson's state() as the lab has it now; what is kept of it is its excerpt.
void record_task_state(AssignmentSession& s, std::size_t index, const nlohmann::json& state);

/// The values `condition` reads from `state` and nothing else (each pointer's value if it is a
/// scalar; an empty array or object in place of a larger one, which no comparison accepts
/// either): the condition gives the same result on it, and it fits in suspend data.
nlohmann::json task_state_excerpt(const StateCondition& condition, const nlohmann::json& state);

/// The answers recorded, with the learner: what grade_assignment takes.
AnswerSheet session_answer_sheet(const AssignmentSession& s);
AssignmentGrade grade_session(const AssignmentSession& s);

/// "open" (nothing recorded), "viewed" (an explore item visited), "answered" (recorded but no
/// attempt: an exercise answer the lab cannot read), "correct", "incorrect".
const char* item_status(const AssignmentSession& s, const ItemGrade& g);

/// The suspend object (see the top of this file).
nlohmann::json session_suspend(const AssignmentSession& s);
/// Puts a suspend object's answers, item and submission into `s` (a fresh session of the same
/// assignment). Every problem is one line in the result ("resume: a[2]: item 4 is an explore
/// item, answered with 1"); `s` changes only if there is none.
std::vector<std::string> resume_session(AssignmentSession& s, const nlohmann::json& suspend);

/// The tries item `index` has left: nullopt if it has no limit; 0 for an exercise or task once
/// the session was submitted (every answer final).
std::optional<unsigned> tries_left(const AssignmentSession& s, std::size_t index);

/// What the page's assignment_state answers (docs/web.md): {title, description, learner, pass,
/// current, submitted, items: [... each with tries, tries_allowed, tries_left, tries_text], grade: {raw, min, max, scaled, completed, passed},
/// interactions: [...], answers (as `cspacelab assignment grade --answers` reads them), suspend}. Correct answers, worked solutions
/// and the interactions' correct_response only once submitted.
nlohmann::json assignment_session_json(const AssignmentSession& s);

}  // namespace csl
