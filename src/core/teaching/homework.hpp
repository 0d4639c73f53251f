#pragma once
// The homework companion: the course handout's thirteen problems P1-P13 by number, the lesson
// and preset that show each one, and a seeded exercise per problem that checks a student's
// answer and explains a wrong one.
//
// An exercise is a pure function of (problem, seed): the same numbers in the CLI, the browser
// and the tests (the lab's own RNG, values rounded to two decimals so that what the student
// reads is exactly what is computed with). Its answer is computed by the lab's core functions
// (the same ones the lessons draw with); tests/unit/homework_test.cpp checks it against
// formulas written again from the handout.
//
// Answers a student types:
//   number    a decimal number; also a multiple or fraction of pi ("pi/2", "3pi/4", "0.5*pi",
//             "2 pi"), a fraction of two numbers ("1/3"), a sum or difference of those ("2pi -
//             3.38"), with "rad" after it, or a decimal comma ("2,90"; not "6,127", which may
//             be a thousands separator)
//   integer   digits (a decimal that is a whole number is read as one)
//   notation  Q in the course's notation, as check_answer() in notation.hpp reads it
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace csl {

/// One problem of the handout and where the lab shows it.
struct HomeworkProblem {
  std::string id;          ///< "P1" ... "P13"
  std::string title;       ///< one line, in our words
  std::string lesson;      ///< the lesson that shows it (a lesson id of the app)
  std::string scene;       ///< a bundled scene the lesson opens with, or "" (the lesson's own)
  nlohmann::json params;   ///< lesson parameters to set (set_params), an object
  std::string task;        ///< what to try in the lesson, two or three sentences
};

/// P1 ... P13 in order.
const std::vector<HomeworkProblem>& homework_problems();
/// A problem by "P10", "p10" or "10"; nullptr if there is none.
const HomeworkProblem* find_homework_problem(const std::string& id);

/// Seeds run from 0 to 2^53 - 1, exact in JSON and JavaScript numbers.
inline constexpr std::uint64_t kMaxExerciseSeed = (std::uint64_t{1} << 53) - 1;

/// One exercise: what the student sees, and (for the checker only) its answer.
struct Exercise {
  std::string id;             ///< the problem, "P10"
  std::uint64_t seed = 0;
  std::string prompt;         ///< the question with its numbers
  nlohmann::json given;       ///< the numbers by the handout's names (P10: {q1, q2} ...)
  std::string answer_format;  ///< "number", "integer" or "notation"
  std::string format_hint;    ///< how to write it, e.g. "radians, e.g. 1.57 or pi/2 (within 0.005)"
  // format_hint's parts (set_format_hint), kept so that an assignment can state its own tolerance.
  std::string answer_form;    ///< "radians, e.g. 1.57 or pi/2"
  std::string within;         ///< the accepted tolerance as the hint says it ("0.005", "1%"); "" for none
  std::string hint_note;      ///< the rest of the hint ("both ends counted"); "" for none

  // The answer: not in to_json().
  double answer = 0.0;        ///< number and integer answers
  double tolerance = 0.0;     ///< accepted |typed - answer|
  std::string robot;          ///< notation answers: the robot's description (notation.hpp)
  std::string worked;         ///< the worked solution, shown once the student has answered
  /// Typical wrong answers and what each says about the student's reasoning.
  struct Trap {
    double value = 0.0;
    std::string why;
  };
  std::vector<Trap> traps;
};

/// The exercise of problem `id` (as find_homework_problem reads it) with `seed`. Throws
/// std::invalid_argument for an unknown problem or a seed past kMaxExerciseSeed.
Exercise make_exercise(const std::string& id, std::uint64_t seed);

/// Sets the hint's parts and format_hint from them: "FORM (within WITHIN; NOTE)", either part of
/// the brackets left out when empty, the brackets too when both are.
void set_format_hint(Exercise& exercise, std::string form, std::string within, std::string note = "");

/// {id, seed, prompt, given, answer_format, format_hint}: no answer in it.
nlohmann::json exercise_to_json(const Exercise& exercise);

struct ExerciseCheck {
  bool correct = false;
  bool readable = true;     ///< false: the answer was empty or could not be read (no attempt)
  nlohmann::json expected;  ///< the answer: a number, an integer, or Q in canonical notation
  std::string explanation;  ///< why it is right, or what went wrong, and the worked solution
  /// What a wrong try may be told without the answer (what went wrong, a typical mistake's
  /// reason); for a right or unreadable one the explanation's first line. The lab's card shows
  /// this, and the explanation once the student asks for the solution or answers right.
  std::string feedback;
  /// The wrong answer was one of the exercise's typical mistakes, whose reason the feedback gives:
  /// some all but give the answer ("the sign is wrong"), so it counts as the solution shown.
  bool typical_mistake = false;
};

/// Checks what a student typed. Never throws for the answer: an unreadable one is incorrect,
/// saying what could not be read.
ExerciseCheck check_exercise(const Exercise& exercise, const std::string& answer);

/// The exercise's own numbers in its problem's lesson, for "see it in the tool" once the student
/// has answered: {"params": {...}} for the lesson's set_params, with "scene" (schema v1) where the
/// numbers are a scene (P12's disk, P13's rectangle and box); null where the tool cannot take them
/// (P1-P7: the tool is a builder; P8 in three dimensions: the lesson's space is the plane).
nlohmann::json exercise_tool_setup(const Exercise& exercise);

/// The answer as a student reads it: Q in the course's notation, a whole number, or a number to
/// six significant digits, each with the tolerance that is accepted ("1.44 (within 0.01)",
/// "8 (within 1)"; a whole number's only from 1 up), never a double's last bits ("1.4400000000000002").
std::string exercise_answer_text(const Exercise& exercise);

/// {correct, expected, explanation, feedback}.
nlohmann::json exercise_check_to_json(const ExerciseCheck& check);

/// A number as a student may type it (see the file comment), or nullopt.
std::optional<double> parse_answer_number(const std::string& text);

}  // namespace csl
