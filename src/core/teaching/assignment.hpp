#pragma once
// Assignment files: an instructor's set of exercises, lab states to explore and tasks checked
// from the lab's state, graded by assignment_grade.hpp (the CLI's `cspacelab assignment`, and
// the page, compiled to wasm, with the same code). `cspacelab help assignment` is the reference
// for authors; this is the same contract.
//
//   {"format": "cspacelab-assignment", "version": 1,
//    "title": "Week 3: configuration spaces",        required, 1 to 200 characters
//    "description": "...",                            optional, at most 4000 characters
//    "pass": 0.6,                                     optional: the scaled score that passes, in
//                                                     [0, 1]; default kDefaultPass (0.6)
//    "seed_key": "week3-2026",                        optional, 1 to 200 characters: what the
//                                                     per-learner seeds derive from; default the
//                                                     title (keep it when you edit the title, so
//                                                     that students keep their numbers)
//    "items": [ITEM, ...]}                            1 to kMaxAssignmentItems
//
// ITEM, by "kind" (every item: optional "title", 1 to 200 characters; "points", a number in
// [0, 1000]):
//   {"kind": "exercise", "problem": "P10", "seed": 7 | "learner", "points": 2, "tolerance": 0.01,
//    "tries": 3}
//       A homework exercise (homework.hpp). "seed": an integer in [0, 2^53 - 1] (everyone gets the
//       same numbers) or "learner" (each learner gets their own: learner_seed()); default
//       "learner". "tolerance": accepted |typed - answer|, a finite number >= 0, only for
//       problems with a numeric answer (P8-P13); default the exercise's own. "tries": how many
//       times the student may check an answer, an integer in [1, kMaxItemTries]; default any
//       number (every check is counted either way: assignment_session.hpp). Title default: the
//       problem's ("P10: ..."). Points default 1.
//   {"kind": "explore", "title": "...", "prompt": "...", "lesson": "step-prm",
//    "scene": {...}, "params": {...}, "points": 0}
//       A lab state to look at: the lesson (an id of lesson_catalogue.hpp), optionally a scene
//       (schema v1, inline, checked by the scene parser and against the lesson's robots) and
//       parameters (checked against the lesson's specs). Credit is for visiting: answered with
//       {"visited": true}, it earns all its points. Title required; prompt 1 to 2000
//       characters, required. Points default 0.
//   {"kind": "task", "title": "...", "prompt": "...", "lesson": "step-prm", "scene": {...},
//    "params": {...}, "points": 1, "check": CONDITION, "tries": 5}
//       A task checked from the lesson's state() when the student checks the lab ("Check my
//       lab" records that state): CONDITION as in state_condition.hpp. Title and prompt
//       required. Points default 1. "tries" as for an exercise. An answer hidden by the
//       instructor (hide=, restrictions.hpp) is not in state(): a check on its field fails.
// Unknown fields anywhere are errors (a typo is not silently ignored). A scene names no
// bundled scene: the core does not know the app's bundled scenes; paste the scene's JSON.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/teaching/homework.hpp"
#include "core/teaching/state_condition.hpp"

namespace csl {

inline constexpr const char* kAssignmentFormat = "cspacelab-assignment";
inline constexpr int kAssignmentVersion = 1;
inline constexpr std::size_t kMaxAssignmentItems = 100;
inline constexpr std::size_t kMaxAssignmentTitle = 200;
inline constexpr std::size_t kMaxAssignmentPrompt = 2000;
inline constexpr std::size_t kMaxAssignmentDescription = 4000;
inline constexpr double kMaxItemPoints = 1000;
inline constexpr double kDefaultPass = 0.6;
/// An item's "tries": more than this is no limit a student would notice.
inline constexpr unsigned kMaxItemTries = 100;
/// Bytes of an assignment or answers file: 100 items with inline scenes fit many times over.
inline constexpr std::size_t kMaxAssignmentBytes = std::size_t{16} << 20;
/// A learner id's length: SCORM 2004's cmi.learner_id holds up to 4000 characters.
inline constexpr std::size_t kMaxLearnerId = 4000;

enum class AssignmentItemKind { Exercise, Explore, Task };
/// "exercise", "explore", "task".
const char* assignment_item_kind_name(AssignmentItemKind kind);

struct AssignmentItem {
  AssignmentItemKind kind = AssignmentItemKind::Exercise;
  std::string title;
  double points = 1;
  // exercise
  std::string problem;                ///< "P10" (canonical)
  std::optional<std::uint64_t> seed;  ///< nullopt: per learner
  std::optional<double> tolerance;    ///< nullopt: the exercise's own
  // exercise, task
  std::optional<unsigned> tries;      ///< the checks allowed; nullopt: any number
  // explore, task
  std::string prompt;
  std::string lesson;                          ///< a lesson id of the catalogue
  nlohmann::json scene;                        ///< null, or the scene normalised (schema v1)
  nlohmann::json params = nlohmann::json::object();
  StateCondition check;                        ///< task
};

struct Assignment {
  std::string title;
  std::string description;
  std::string seed_key;  ///< as given, or the title
  double pass = kDefaultPass;
  std::vector<AssignmentItem> items;

  double max_points() const;
};

struct AssignmentParse {
  std::optional<Assignment> assignment;  ///< set only if errors is empty
  /// Every problem found, each one line naming where: "items[2] (\"Find a path\"): points: a
  /// number in [0, 1000], got -1".
  std::vector<std::string> errors;
};

/// Reads and validates an assignment; collects every error rather than stopping at the first.
AssignmentParse parse_assignment(const nlohmann::json& j);
/// The same from text (strict JSON, at most kMaxAssignmentBytes; a syntax error is the one error).
AssignmentParse parse_assignment_text(const std::string& text);

/// Why `learner` cannot be a learner id (not at most kMaxLearnerId bytes), or "".
std::string learner_id_problem(const std::string& learner);

/// The seed of item `index` for `learner`: FNV-1a (64-bit) over the seed key, the item's index
/// and problem and the learner id (each length-prefixed, so no two splits of the same bytes
/// agree), mixed by splitmix64's finaliser and cut to 53 bits: in [0, kMaxExerciseSeed]. A
/// learner id "" (no LMS, no --learner) is a learner like any other: everyone without one gets
/// the same numbers.
std::uint64_t learner_seed(const Assignment& a, std::size_t index, const std::string& learner);

/// The exercise of item `index` (an exercise item) for `learner`: its fixed seed or the
/// learner's, the tolerance override applied (and said in format_hint).
Exercise assignment_exercise(const Assignment& a, std::size_t index, const std::string& learner);

/// The assignment normalised (defaults filled in, scenes normalised): parse_assignment reads it
/// back to the same.
nlohmann::json assignment_to_json(const Assignment& a);

/// What a student's page shows for `learner`: {"title", "description", "pass", "max_points",
/// "learner", "items": [...]}: each exercise with its seed, prompt, given, answer_format and
/// format_hint (no answer), each explore and task item with its lesson, scene, params and
/// prompt (a task also its check, as JSON and in words: the student is told what counts).
nlohmann::json assignment_student_view(const Assignment& a, const std::string& learner);

}  // namespace csl
