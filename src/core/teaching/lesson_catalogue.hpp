#pragma once
// The lab's lessons as the core knows them: each lesson's id and name, the parameters a link may
// set (exactly the keys of the app's Lesson::params(), with how each is written) and the robots
// whose scenes it takes. The app registers its lessons itself (src/app/lessons); this list is
// what the CLI's `link` command checks a link against, and what the restrictions of a link
// (restrictions.hpp: lock=PARAM) name. tests/e2e/lock-hide.test.mjs compares it with the app's
// lessons, their param_specs and the scenes they take, so the two cannot drift apart unseen.
//
// The lists are static data (string views and initializer lists, no code to build them): they
// are in the wasm, whose budget is tight.
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/params.hpp"
#include "core/scene/scene.hpp"

namespace csl {

/// How a parameter's value is written in JSON (and so in a link: web/lab-url.js parseValue).
enum class LessonParamKind {
  Integer,      ///< a JSON integer (its spec's range, or [lo, hi])
  Number,       ///< a JSON number (its spec's range, or [lo, hi])
  Text,         ///< a string (its syntax: `syntax`)
  Choice,       ///< one of `choices`
  Pair,         ///< [a, b], each in [lo, hi]
  NumberList,   ///< [a, b, ...]: `max_items` numbers if set, else any length >= 1 (a configuration: the scene's robot decides)
  IntegerList,  ///< [n, ...], 1 to `max_items` integers of `spec`
};

/// What a Text parameter must read as (checked by the core's own parsers).
enum class LessonParamSyntax { None, NeighborRule, EdgeChecker, RobotDescription, Planner, Sampler };

struct LessonParam {
  std::string_view name;             ///< the key of params() and of a link
  LessonParamKind kind;
  const ParamSpec* spec = nullptr;   ///< the lab's spec (its range, for Integer, Number, IntegerList)
  std::initializer_list<std::string_view> choices = {};
  double lo = -kInf, hi = kInf;      ///< without a spec: the inclusive range of a number, or of each item
  LessonParamSyntax syntax = LessonParamSyntax::None;
  int max_items = 0;                 ///< IntegerList: at most this many; NumberList: exactly this many (0: any)
};

struct CataloguedLesson {
  std::string_view id;    ///< as in links and the API ("step-prm")
  std::string_view name;  ///< as in the lesson menu ("Step PRM")
  std::initializer_list<LessonParam> params;
  /// The robot types whose scenes it takes: "point", "arm2" (the 2-link arm), "arm" (any
  /// number of links), "polygon". Empty: the lesson has no scene.
  std::initializer_list<std::string_view> robots;
};

/// Every lesson, in the order of the app's menu (by category, then name).
const std::vector<CataloguedLesson>& lesson_catalogue();
/// A lesson by id, or nullptr.
const CataloguedLesson* find_catalogued_lesson(const std::string& id);
/// "torus, notation, analysis, ..." (for messages).
std::string lesson_ids_text();
/// "grid_n, p, q" (for messages).
std::string lesson_param_names_text(const CataloguedLesson& lesson);

/// Why `value` cannot be parameter `param`'s value, as one line ("grid_n: an integer in [2,
/// 100000]"), or "".
std::string lesson_param_problem(const LessonParam& param, const nlohmann::json& value);
/// Why `params` (a JSON object) cannot be set on `lesson` by a link: an unknown key (naming
/// the lesson's), or a value lesson_param_problem() refuses; "" if each is one the lesson takes
/// (the lab checks the rest: budgets that depend on the scene).
std::string lesson_params_problem(const CataloguedLesson& lesson, const nlohmann::json& params);
/// Why `lesson` cannot show `scene` (a robot it does not take, or no scene at all), or "".
std::string lesson_scene_problem(const CataloguedLesson& lesson, const Scene& scene);

}  // namespace csl
