#pragma once
// The checked questions of the lesson "C-spaces in 3-D" (issue 25: P1, P2 and P5 from notation to
// a picture, with exercises): what a student answers from the block the lesson draws for a
// polygon robot (SE(2) = R^2 x S^1) or a 3-link arm (T^3). Every answer is computed here from the
// scene (its robot's space, which coordinates wrap, the short way between two configurations) or
// from the free fraction the lesson counted, never written into the question; the app only shows
// prompts and choices and reports the verdict (ExerciseCheck, as the homework's exercises).
//
//   name       Q in the course's notation (notation.hpp's check_answer)
//   dimension  how many numbers fix a configuration
//   glued      which pairs of the block's faces are glued (one per angle coordinate)
//   seam       of two configurations B and C, which one A reaches the short way through a glued face
//   free       the percentage of Q that is free, read off the panel (within half a point)
#include <string>
#include <vector>

#include "core/scene/scene.hpp"
#include "core/teaching/homework.hpp"

namespace csl {

struct VolumeQuestion {
  std::string id;             ///< "name", "dimension", "glued", "seam", "free"
  std::string prompt;         ///< the question, with its configurations for "seam"
  std::string answer_format;  ///< "notation", "integer", "choice" or "number"
  /// "choice": the keys an answer may be and what each says ({"all", "all three pairs"}).
  std::vector<std::pair<std::string, std::string>> choices;
  std::string format_hint;    ///< how to write a typed answer
};

/// The question ids in the order the lesson asks them.
const std::vector<std::string>& volume_question_ids();

/// The question `id` for `scene` (a polygon robot or a 3-link arm). Throws std::invalid_argument
/// for an unknown id or another robot.
VolumeQuestion volume_question(const std::string& id, const Scene& scene);

/// The configurations the "seam" question names, A, B and C: A is the scene's start with its
/// angle (theta, or theta1) at 2.8; B has it at -2.9, C at 0.5 (the other coordinates A's).
std::vector<Config> seam_question_configs(const Scene& scene);

/// Checks `answer` to question `id` in `scene`; `free_fraction` is the share of Q the lesson
/// counted free (its fine volume), used by "free" only. Never throws for the answer: an empty or
/// unreadable one is incorrect with readable = false.
ExerciseCheck check_volume_question(const std::string& id, const Scene& scene, double free_fraction,
                                    const std::string& answer);

}  // namespace csl
